#pragma once
// Writing a file so that readers only ever see the old content or the whole new one.

#include "kumite/core/result.h"

#include <filesystem>
#include <string_view>

namespace kumite {

// Writes `content` to a temporary file in path's folder, flushes it, then renames it over `path`.
// On any failure the temporary is removed and `path` is untouched.
Result<void> write_file_atomically(const std::filesystem::path& path, std::string_view content);

} // namespace kumite
