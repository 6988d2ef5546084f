// The training store's schema as an ordered list of migrations: PRAGMA user_version is the number applied. A new
// kumite appends a migration and never edits one that shipped, so every store reaches the current schema by the
// same steps.

#include "store_schema.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

namespace kumite::training {

namespace {

// The columns of attacks and user_strikes follow k_attack_columns and k_user_strike_columns.
const char* const k_migrations[] = {
    // 1: the tables. A session is one run of a drill by one trainee; its attacks and user_strikes are the bout's
    // user_response and user_strike_end events. NULL in a REAL column is "no value" (NaN in the rows).
    "CREATE TABLE trainees ("
    "  id INTEGER PRIMARY KEY,"
    "  name TEXT NOT NULL UNIQUE,"
    "  created_utc TEXT NOT NULL);"
    "CREATE TABLE sessions ("
    "  id INTEGER PRIMARY KEY,"
    "  trainee_id INTEGER NOT NULL REFERENCES trainees(id),"
    "  drill TEXT NOT NULL, drill_file TEXT NOT NULL, drill_text TEXT NOT NULL, settings_json TEXT NOT NULL,"
    "  character TEXT NOT NULL, tracker TEXT NOT NULL, started_utc TEXT NOT NULL,"
    "  duration_s REAL NOT NULL DEFAULT 0, complete INTEGER NOT NULL DEFAULT 0, summary_json TEXT NOT NULL DEFAULT '');"
    "CREATE TABLE attacks ("
    "  session_id INTEGER NOT NULL REFERENCES sessions(id),"
    "  seq INTEGER NOT NULL, t_s REAL, part INTEGER, part_name TEXT, difficulty TEXT, command TEXT, kind TEXT,"
    "  height TEXT, side TEXT, target_part TEXT, combination TEXT, blow INTEGER, own INTEGER, result TEXT,"
    "  blocked_by TEXT, response TEXT, response_time_s REAL, quality TEXT, countered INTEGER, counter_landed INTEGER);"
    "CREATE TABLE user_strikes ("
    "  session_id INTEGER NOT NULL REFERENCES sessions(id),"
    "  seq INTEGER NOT NULL, t_s REAL, part INTEGER, hand TEXT, aimed_at TEXT, move TEXT, outcome TEXT,"
    "  defended INTEGER, peak_speed_mps REAL);",
    // 2: what the readers look rows up by: a session's rows in order, a trainee's sessions by date, and every session
    // by date (the listing's order: without it, 10,000 sessions of a few KiB each go through a sort).
    "CREATE INDEX attacks_by_session ON attacks(session_id, seq);"
    "CREATE INDEX user_strikes_by_session ON user_strikes(session_id, seq);"
    "CREATE INDEX sessions_by_trainee ON sessions(trainee_id, started_utc);"
    "CREATE INDEX sessions_by_start ON sessions(started_utc);",
};

constexpr int k_migration_count = static_cast<int>(sizeof k_migrations / sizeof k_migrations[0]);

Result<std::int64_t> pragma_integer(sqlite3* db, const char* pragma, const std::filesystem::path& store) {
    Result<std::string> text = sqlite_first_text(db, pragma, store);
    if (!text) return text.error();
    return std::int64_t(std::strtoll(text->c_str(), nullptr, 10));
}

} // namespace

int store_schema_version() { return k_migration_count; }

Result<int> store_check_identity(sqlite3* db, const std::filesystem::path& store) {
    Result<std::int64_t> application_id = pragma_integer(db, "PRAGMA application_id", store);
    if (!application_id) return application_id.error();
    Result<std::int64_t> version = pragma_integer(db, "PRAGMA user_version", store);
    if (!version) return version.error();
    if (*application_id != k_store_application_id) {
        char id[16];
        std::snprintf(id, sizeof id, "0x%08llx", static_cast<unsigned long long>(std::uint32_t(*application_id)));
        return make_error(ErrorCode::invalid, store.string() + ": not a kumite training store (a SQLite database with application_id " + id + ")");
    }
    if (*version > store_schema_version()) {
        return make_error(ErrorCode::unsupported, store.string() + ": made by a newer kumite (schema " + std::to_string(*version) + ", this one reads up to " +
                                                      std::to_string(store_schema_version()) + ")");
    }
    if (*version < 1) return make_error(ErrorCode::invalid, store.string() + ": damaged: a kumite training store without a schema (user_version 0)");
    return static_cast<int>(*version);
}

Result<void> store_migrate(sqlite3* db, const std::filesystem::path& store, int from_version) {
    if (from_version >= store_schema_version()) return {};
    if (Result<void> begun = sqlite_exec(db, "BEGIN IMMEDIATE", store); !begun) return begun;
    std::string sql;
    for (int version = from_version + 1; version <= store_schema_version(); ++version) sql += k_migrations[version - 1];
    sql += "PRAGMA application_id = " + std::to_string(k_store_application_id) + ";";
    sql += "PRAGMA user_version = " + std::to_string(store_schema_version()) + ";";
    sql += "COMMIT;";
    if (Result<void> migrated = sqlite_exec(db, sql.c_str(), store); !migrated) {
        (void)sqlite_exec(db, "ROLLBACK", store);
        return make_error(ErrorCode::io, "migrating from schema " + std::to_string(from_version) + ": " + migrated.error().message);
    }
    return {};
}

Result<void> store_create_at_version(const std::filesystem::path& store, int version) {
    if (version < 1 || version > store_schema_version()) return make_error(ErrorCode::invalid, "no schema version " + std::to_string(version));
    const std::filesystem::path building = store.string() + ".creating-" + std::to_string(::getpid());
    std::error_code ignored;
    std::filesystem::remove(building, ignored);
    sqlite3* db = nullptr;
    int status = sqlite3_open_v2(building.c_str(), &db, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr);
    Result<void> made = status == SQLITE_OK ? sqlite_exec(db, "PRAGMA journal_mode=WAL", building)
                                            : Result<void>(make_error(ErrorCode::io, sqlite_failure(db, building, "creating")));
    if (made) {
        std::string sql = "BEGIN IMMEDIATE;";
        for (int v = 1; v <= version; ++v) sql += k_migrations[v - 1];
        sql += "PRAGMA application_id = " + std::to_string(k_store_application_id) + ";";
        sql += "PRAGMA user_version = " + std::to_string(version) + "; COMMIT;";
        made = sqlite_exec(db, sql.c_str(), building);
    }
    sqlite3_close(db); // the last connection: the WAL is checkpointed into the file and removed
    // link() refuses an existing name, where rename() would replace a store another process has just created.
    if (made && ::link(building.c_str(), store.c_str()) != 0) {
        made = make_error(ErrorCode::io, store.string() + ": cannot create the store: " + std::strerror(errno));
    }
    std::filesystem::remove(building, ignored);
    return made;
}

namespace {

std::string insert_sql(const char* table, const char* columns, int column_count) {
    std::string sql = std::string("INSERT INTO ") + table + "(session_id, " + columns + ") VALUES(?";
    for (int i = 0; i < column_count; ++i) sql += ", ?";
    return sql + ")";
}

} // namespace

std::string attack_insert_sql() { return insert_sql("attacks", k_attack_columns, k_attack_column_count); }
std::string user_strike_insert_sql() { return insert_sql("user_strikes", k_user_strike_columns, k_user_strike_column_count); }

void attack_bind(Statement& statement, int first_parameter, const AttackRow& row) {
    int p = first_parameter;
    statement.bind_integer(p++, row.seq);
    statement.bind_real(p++, row.t_s);
    statement.bind_integer(p++, row.part);
    statement.bind_text(p++, row.part_name);
    statement.bind_text(p++, row.difficulty);
    statement.bind_text(p++, row.command);
    statement.bind_text(p++, row.kind);
    statement.bind_text(p++, row.height);
    statement.bind_text(p++, row.side);
    statement.bind_text(p++, row.target_part);
    statement.bind_text(p++, row.combination);
    statement.bind_integer(p++, row.blow);
    statement.bind_integer(p++, row.own);
    statement.bind_text(p++, row.result);
    statement.bind_text(p++, row.blocked_by);
    statement.bind_text(p++, row.response);
    statement.bind_real(p++, row.response_time_s);
    statement.bind_text(p++, row.quality);
    statement.bind_integer(p++, row.countered);
    statement.bind_integer(p++, row.counter_landed);
}

AttackRow attack_read(const Statement& statement, int first_column) {
    int c = first_column;
    AttackRow row;
    row.seq = static_cast<int>(statement.integer(c++));
    row.t_s = statement.real(c++);
    row.part = static_cast<int>(statement.integer(c++));
    row.part_name = statement.text(c++);
    row.difficulty = statement.text(c++);
    row.command = statement.text(c++);
    row.kind = statement.text(c++);
    row.height = statement.text(c++);
    row.side = statement.text(c++);
    row.target_part = statement.text(c++);
    row.combination = statement.text(c++);
    row.blow = static_cast<int>(statement.integer(c++));
    row.own = statement.integer(c++) != 0;
    row.result = statement.text(c++);
    row.blocked_by = statement.text(c++);
    row.response = statement.text(c++);
    row.response_time_s = statement.real(c++);
    row.quality = statement.text(c++);
    row.countered = statement.integer(c++) != 0;
    row.counter_landed = static_cast<int>(statement.integer(c++));
    return row;
}

void user_strike_bind(Statement& statement, int first_parameter, const UserStrikeRow& row) {
    int p = first_parameter;
    statement.bind_integer(p++, row.seq);
    statement.bind_real(p++, row.t_s);
    statement.bind_integer(p++, row.part);
    statement.bind_text(p++, row.hand);
    statement.bind_text(p++, row.aimed_at);
    statement.bind_text(p++, row.move);
    statement.bind_text(p++, row.outcome);
    statement.bind_integer(p++, row.defended);
    statement.bind_real(p++, row.peak_speed_mps);
}

UserStrikeRow user_strike_read(const Statement& statement, int first_column) {
    int c = first_column;
    UserStrikeRow row;
    row.seq = static_cast<int>(statement.integer(c++));
    row.t_s = statement.real(c++);
    row.part = static_cast<int>(statement.integer(c++));
    row.hand = statement.text(c++);
    row.aimed_at = statement.text(c++);
    row.move = statement.text(c++);
    row.outcome = statement.text(c++);
    row.defended = statement.integer(c++) != 0;
    row.peak_speed_mps = statement.real(c++);
    return row;
}

} // namespace kumite::training
