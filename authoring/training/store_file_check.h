#pragma once
// Checks a store's file before SQLite opens it (private to authoring/training), so that a file that is not a SQLite
// database, or is cut short, is refused with the reason instead of being opened, "repaired" or overwritten.

#include "kumite/core/result.h"

#include <filesystem>

namespace kumite::training {

// Refuses an existing `store` that is empty, is not a SQLite database (shorter than its 100-byte header or without
// "SQLite format 3"), or is shorter than its header says. Reads 100 bytes and never writes; every message names the
// file. A missing file is an error too (the caller decides whether to create one).
Result<void> store_file_check(const std::filesystem::path& store);

} // namespace kumite::training
