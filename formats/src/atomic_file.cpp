#include "kumite/formats/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <string>
#include <unistd.h>

namespace kumite {

Result<void> write_file_atomically(const std::filesystem::path& path, std::string_view content) {
    const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    std::string temporary = (folder / ("." + path.filename().string() + ".XXXXXX")).string();
    const int fd = ::mkstemp(temporary.data());
    if (fd < 0) {
        return make_error(ErrorCode::io, path.string() + ": cannot create a temporary file in " + folder.string() +
                                             ": " + std::strerror(errno));
    }
    auto fail = [&](const char* what) {
        const std::string reason = std::strerror(errno);
        ::close(fd);
        ::unlink(temporary.c_str());
        return make_error(ErrorCode::io, path.string() + ": " + what + ": " + reason);
    };
    std::size_t written = 0;
    while (written < content.size()) {
        const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
        if (n < 0) {
            if (errno == EINTR) continue;
            return fail("write failed");
        }
        written += static_cast<std::size_t>(n);
    }
    if (::fchmod(fd, 0644) != 0) return fail("cannot set permissions");
    if (::fsync(fd) != 0) return fail("flush failed");
    if (::close(fd) != 0) {
        ::unlink(temporary.c_str());
        return make_error(ErrorCode::io, path.string() + ": close failed: " + std::strerror(errno));
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        const std::string reason = std::strerror(errno);
        ::unlink(temporary.c_str());
        return make_error(ErrorCode::io, path.string() + ": cannot replace the file: " + reason);
    }
    return {};
}

} // namespace kumite
