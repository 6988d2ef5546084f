#include "partial_file.h"

#include <filesystem>

namespace kumite::cli {

Result<void> PartialFile::open(const std::string& path, const std::string& what) {
    m_path = path;
    m_what = what;
    m_out.open(path + ".partial");
    if (!m_out) return make_error(ErrorCode::io, path + ": cannot write " + what);
    return {};
}

Result<void> PartialFile::finish() {
    if (!m_out.is_open()) return {};
    m_out.close();
    const std::string temporary = m_path + ".partial";
    if (!m_out) {
        std::filesystem::remove(temporary);
        return make_error(ErrorCode::io, m_path + ": cannot finish " + m_what + " (a write failed)");
    }
    std::error_code error;
    std::filesystem::rename(temporary, m_path, error);
    if (error) return make_error(ErrorCode::io, m_path + ": cannot finish " + m_what + ": " + error.message());
    return {};
}

} // namespace kumite::cli
