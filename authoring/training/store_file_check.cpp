// Where the training store is by default, and the check of its file before SQLite opens it: SQLite itself opens an
// empty or foreign file as a new database and would write its header into it on the first write, and reads a
// truncated one until it meets the missing pages.

#include "store_file_check.h"
#include "training_store.h"

#include <sqlite3.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <system_error>

namespace kumite::training {

std::filesystem::path default_store_path() {
    if (const char* store = std::getenv("KUMITE_STORE"); store && *store) return store;
    if (const char* data = std::getenv("XDG_DATA_HOME"); data && *data) return std::filesystem::path(data) / "kumite" / "training.sqlite";
    const char* home = std::getenv("HOME");
    return std::filesystem::path(home && *home ? home : ".") / ".local" / "share" / "kumite" / "training.sqlite";
}

namespace {

constexpr std::size_t k_header_bytes = 100; // SQLite's database header

std::uint32_t big_endian_u32(const unsigned char* bytes) {
    return (std::uint32_t(bytes[0]) << 24) | (std::uint32_t(bytes[1]) << 16) | (std::uint32_t(bytes[2]) << 8) | bytes[3];
}

// The file's first bytes, read through SQLite's own file layer rather than open()/close(): closing any descriptor of
// a file drops every POSIX lock this process holds on it, SQLite's included (a SessionWriter's in the same process),
// whereas SQLite's layer keeps the descriptor open until this process's connections release their locks.
Result<void> read_file_start(const std::filesystem::path& store, unsigned char* bytes, int count) {
    sqlite3_vfs* vfs = sqlite3_vfs_find(nullptr);
    // A main-database name must be built by SQLite (it looks for URI parameters after it); only a main database
    // shares SQLite's per-file lock bookkeeping.
    const std::unique_ptr<const char, void (*)(const char*)> name(sqlite3_create_filename(store.c_str(), "", "", 0, nullptr),
                                                                   [](const char* p) { sqlite3_free_filename(p); });
    const std::unique_ptr<unsigned char[]> storage(new unsigned char[static_cast<std::size_t>(vfs->szOsFile)]());
    auto* file = reinterpret_cast<sqlite3_file*>(storage.get());
    int opened_flags = 0;
    if (!name || vfs->xOpen(vfs, name.get(), file, SQLITE_OPEN_READONLY | SQLITE_OPEN_MAIN_DB, &opened_flags) != SQLITE_OK) {
        return make_error(ErrorCode::io, store.string() + ": cannot open: " + std::strerror(errno));
    }
    const int status = file->pMethods->xRead(file, bytes, count, 0);
    file->pMethods->xClose(file);
    if (status != SQLITE_OK) return make_error(ErrorCode::io, store.string() + ": cannot read its first " + std::to_string(count) + " bytes");
    return {};
}

} // namespace

Result<void> store_file_check(const std::filesystem::path& store) {
    std::error_code error;
    const std::uintmax_t file_bytes = std::filesystem::file_size(store, error);
    if (error) return make_error(ErrorCode::io, store.string() + ": " + error.message());
    if (file_bytes == 0) {
        return make_error(ErrorCode::invalid, store.string() + ": the file is empty (0 bytes), not a kumite training store: remove it or give another --store");
    }
    if (file_bytes < k_header_bytes) {
        return make_error(ErrorCode::invalid, store.string() + ": not a SQLite database (" + std::to_string(file_bytes) + " bytes, shorter than its header)");
    }
    unsigned char header[k_header_bytes];
    if (Result<void> read = read_file_start(store, header, static_cast<int>(k_header_bytes)); !read) return read;
    if (std::memcmp(header, "SQLite format 3", 16) != 0) {
        return make_error(ErrorCode::invalid, store.string() + ": not a SQLite database (no \"SQLite format 3\" at its start)");
    }
    // The header's page count is valid only when the "version valid for" number equals the change counter (older
    // writers did not keep it). A WAL file with frames beside the store means a checkpoint may be under way, which
    // writes page 1 (the new count) before the pages that grow the file: SQLite reads those from the WAL meanwhile.
    const std::uint32_t page_count = big_endian_u32(header + 28);
    const bool count_valid = page_count != 0 && big_endian_u32(header + 92) == big_endian_u32(header + 24);
    const std::uintmax_t wal_bytes = std::filesystem::file_size(store.string() + "-wal", error);
    const bool checkpoint_possible = !error && wal_bytes > 0;
    const std::uint32_t page_field = (std::uint32_t(header[16]) << 8) | header[17];
    const std::uint64_t page_bytes = page_field == 1 ? 65536 : page_field;
    const std::uint64_t header_bytes = std::uint64_t(page_count) * page_bytes;
    if (count_valid && !checkpoint_possible && header_bytes > file_bytes) {
        return make_error(ErrorCode::invalid, store.string() + ": truncated: the header says " + std::to_string(header_bytes) + " bytes, the file has " +
                                                  std::to_string(file_bytes));
    }
    return {};
}

bool store_being_written(const std::filesystem::path& store) {
    const int fd = ::open(store.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    // The writer holds flock(LOCK_EX) for its life: a shared lock not granted at once means it is there.
    const bool held = ::flock(fd, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK;
    ::close(fd); // releases the shared lock if it was granted
    return held;
}

} // namespace kumite::training
