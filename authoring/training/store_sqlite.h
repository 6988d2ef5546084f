#pragma once
// The few SQLite C API wrappers the training store uses (private to authoring/training): a prepared statement that
// finalizes itself and binds NaN as NULL, and statements run for their first value. Every error message starts with
// the store's path.

#include "kumite/core/result.h"

#include <sqlite3.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>

namespace kumite::training {

// "PATH: what was being done: SQLite's message".
inline std::string sqlite_failure(sqlite3* db, const std::filesystem::path& store, std::string_view doing) {
    return store.string() + ": " + std::string(doing) + ": " + (db ? sqlite3_errmsg(db) : "out of memory");
}

class Statement {
public:
    Statement() = default;
    Statement(Statement&& other) noexcept : m_statement(std::exchange(other.m_statement, nullptr)) {}
    Statement& operator=(Statement&& other) noexcept {
        std::swap(m_statement, other.m_statement);
        return *this;
    }
    Statement(const Statement&) = delete;
    Statement& operator=(const Statement&) = delete;
    ~Statement() { sqlite3_finalize(m_statement); }

    static Result<Statement> prepare(sqlite3* db, std::string_view sql, const std::filesystem::path& store) {
        Statement statement;
        if (sqlite3_prepare_v2(db, sql.data(), static_cast<int>(sql.size()), &statement.m_statement, nullptr) != SQLITE_OK) {
            return make_error(ErrorCode::io, sqlite_failure(db, store, "preparing `" + std::string(sql.substr(0, 60)) + "`"));
        }
        return statement;
    }

    sqlite3_stmt* get() const { return m_statement; }
    int step() { return sqlite3_step(m_statement); }
    // Ready for new values: the last run's bindings cleared.
    void reset() {
        sqlite3_reset(m_statement);
        sqlite3_clear_bindings(m_statement);
    }

    // Parameters are 1-based, as in SQLite.
    void bind_integer(int parameter, std::int64_t value) { sqlite3_bind_int64(m_statement, parameter, value); }
    // NaN (k_no_value) is stored as NULL, which reads back as NaN.
    void bind_real(int parameter, double value) {
        if (std::isnan(value)) sqlite3_bind_null(m_statement, parameter);
        else sqlite3_bind_double(m_statement, parameter, value);
    }
    void bind_text(int parameter, std::string_view value) {
        sqlite3_bind_text(m_statement, parameter, value.data(), static_cast<int>(value.size()), SQLITE_TRANSIENT);
    }

    // Columns are 0-based, as in SQLite.
    std::int64_t integer(int column) const { return sqlite3_column_int64(m_statement, column); }
    double real(int column) const {
        return sqlite3_column_type(m_statement, column) == SQLITE_NULL ? std::nan("") : sqlite3_column_double(m_statement, column);
    }
    std::string text(int column) const {
        const unsigned char* bytes = sqlite3_column_text(m_statement, column);
        return bytes ? std::string(reinterpret_cast<const char*>(bytes), static_cast<std::size_t>(sqlite3_column_bytes(m_statement, column))) : std::string();
    }

private:
    sqlite3_stmt* m_statement = nullptr;
};

// Runs statements that return no rows (several, separated by semicolons).
inline Result<void> sqlite_exec(sqlite3* db, const char* sql, const std::filesystem::path& store) {
    char* message = nullptr;
    if (sqlite3_exec(db, sql, nullptr, nullptr, &message) != SQLITE_OK) {
        const std::string text = message ? message : sqlite3_errmsg(db);
        sqlite3_free(message);
        return make_error(ErrorCode::io, store.string() + ": `" + std::string(sql).substr(0, 60) + "`: " + text);
    }
    return {};
}

// The first column of the first row of `sql` as text ("" when there is no row): what a PRAGMA answers.
inline Result<std::string> sqlite_first_text(sqlite3* db, const char* sql, const std::filesystem::path& store) {
    Result<Statement> statement = Statement::prepare(db, sql, store);
    if (!statement) return statement.error();
    const int status = statement->step();
    if (status == SQLITE_ROW) return statement->text(0);
    if (status == SQLITE_DONE) return std::string();
    return make_error(ErrorCode::io, sqlite_failure(db, store, std::string("running `") + sql + "`"));
}

} // namespace kumite::training
