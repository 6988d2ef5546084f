#pragma once
// A file written as a bout goes (events, the user's recording): streamed into `PATH.partial`, renamed to PATH when
// finished, so that an interrupted or failed run never leaves a half-written file under the name asked for.

#include "kumite/core/result.h"

#include <fstream>
#include <string>

namespace kumite::cli {

class PartialFile {
public:
    // Opens PATH.partial for writing; `what` names the file in errors ("the events file").
    Result<void> open(const std::string& path, const std::string& what);
    bool is_open() const { return m_out.is_open(); }
    std::ofstream& stream() { return m_out; }
    // Closes it and renames it to PATH; an error when anything could not be written.
    Result<void> finish();

private:
    std::ofstream m_out;
    std::string m_path, m_what;
};

} // namespace kumite::cli
