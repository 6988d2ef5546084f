#pragma once
// The training store's schema (private to authoring/training): its migrations, the identity a store carries
// (application_id, user_version) and the one place where an AttackRow or UserStrikeRow meets its table's columns.

#include "store_sqlite.h"
#include "training_store.h"

#include <cstdint>
#include <filesystem>

namespace kumite::training {

// PRAGMA application_id of every kumite training store: "KUMI" in ASCII, so another application's SQLite file is
// told apart from a store.
inline constexpr std::int32_t k_store_application_id = 0x4B554D49;

// The oldest schema a StoreReader reads as it is. Every migration so far only adds (indexes), so version 1 reads;
// raise this when a migration changes a column the reader's queries use.
inline constexpr int k_store_oldest_readable_version = 1;

// The store's schema version (PRAGMA user_version), after refusing another application's SQLite file ("not a
// kumite training store") and a newer kumite's store ("made by a newer kumite (schema N, this one reads up to M)").
// Reads only.
Result<int> store_check_identity(sqlite3* db, const std::filesystem::path& store);

// Applies the migrations after `from_version` up to the current one in one transaction, with the application_id.
Result<void> store_migrate(sqlite3* db, const std::filesystem::path& store, int from_version);

// Creates a store at `store`, at schema `version` (1..store_schema_version(); tests make older stores with it), in
// WAL mode. It is built under a temporary name and linked into place, so a store is never seen half-made; refused
// when `store` exists.
Result<void> store_create_at_version(const std::filesystem::path& store, int version);

// The attacks and user_strikes tables' columns after session_id, in the rows' field order: what the writer inserts,
// the reader selects and the export writes.
inline constexpr const char* k_attack_columns =
    "seq, t_s, part, part_name, difficulty, command, kind, height, side, target_part, combination, blow, own, result, "
    "blocked_by, response, response_time_s, quality, countered, counter_landed";
inline constexpr int k_attack_column_count = 20;
inline constexpr const char* k_user_strike_columns = "seq, t_s, part, hand, aimed_at, move, outcome, defended, peak_speed_mps";
inline constexpr int k_user_strike_column_count = 9;

// "INSERT INTO attacks(session_id, …) VALUES(?, …)": the session's id, then the row's fields from parameter 2.
std::string attack_insert_sql();
std::string user_strike_insert_sql();

// Binds a row's fields to parameters first_parameter.. (k_…_column_count of them), and reads one from columns
// first_column.. of a row selected with k_…_columns.
void attack_bind(Statement& statement, int first_parameter, const AttackRow& row);
AttackRow attack_read(const Statement& statement, int first_column);
void user_strike_bind(Statement& statement, int first_parameter, const UserStrikeRow& row);
UserStrikeRow user_strike_read(const Statement& statement, int first_column);

} // namespace kumite::training
