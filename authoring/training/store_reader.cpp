// StoreReader: the training store read-only. It opens with SQLITE_OPEN_READONLY, which reads a WAL store while a
// SessionWriter commits to it (the reader sees the last commit before each query), and it never locks the store
// against a writer. Every listing is one query, so 10,000 sessions list in one pass over the sessions table.

#include "store_file_check.h"
#include "store_schema.h"

#include <system_error>

namespace kumite::training {

struct StoreReader::State {
    std::filesystem::path store;
    sqlite3* db = nullptr;

    ~State() {
        // A reader never checkpoints: the store stays as the writer left it.
        if (db) sqlite3_db_config(db, SQLITE_DBCONFIG_NO_CKPT_ON_CLOSE, 1, nullptr);
        sqlite3_close(db);
    }

    // Runs `sql` with `trainee` bound to ?1 when given, calling `read` per row.
    template <class Read>
    Result<void> each(const std::string& sql, const std::optional<std::string>& trainee, Read&& read) const {
        Result<Statement> statement = Statement::prepare(db, sql, store);
        if (!statement) return statement.error();
        if (trainee) statement->bind_text(1, *trainee);
        int status = SQLITE_ROW;
        while ((status = statement->step()) == SQLITE_ROW) read(*statement);
        if (status != SQLITE_DONE) return make_error(ErrorCode::io, sqlite_failure(db, store, "reading"));
        return {};
    }

    template <class Row, class Read>
    Result<std::vector<Row>> collect(const std::string& sql, const std::optional<std::string>& trainee, Read&& read) const {
        std::vector<Row> rows;
        Result<void> done = each(sql, trainee, [&](const Statement& statement) { rows.push_back(read(statement)); });
        if (!done) return done.error();
        return rows;
    }
};

namespace {

// "SELECT columns FROM sessions s JOIN trainees t ... [WHERE t.name = ?1] ORDER BY start", the one order every
// listing and export shares. `rows_table` joins that table's rows (aliased r) and orders them by seq in a session.
std::string session_query(const std::string& columns, bool of_trainee, const char* rows_table = nullptr) {
    std::string sql = "SELECT " + columns + " FROM sessions s JOIN trainees t ON t.id = s.trainee_id";
    if (rows_table) sql += std::string(" JOIN ") + rows_table + " r ON r.session_id = s.id";
    if (of_trainee) sql += " WHERE t.name = ?1";
    sql += " ORDER BY s.started_utc, s.id";
    if (rows_table) sql += ", r.seq";
    return sql;
}

// A session's counts through the (session_id, seq) indexes: one index range per session, no table read.
constexpr const char* k_session_counts = "(SELECT count(*) FROM attacks a WHERE a.session_id = s.id) AS attacks, "
                                         "(SELECT count(*) FROM user_strikes u WHERE u.session_id = s.id) AS user_strikes";

} // namespace

Result<StoreReader> StoreReader::open(const std::filesystem::path& store) {
    std::error_code error;
    if (!std::filesystem::exists(store, error)) return make_error(ErrorCode::io, "no training store at " + store.string());
    if (Result<void> checked = store_file_check(store); !checked) return checked.error();
    auto state = std::make_unique<State>();
    state->store = store;
    if (sqlite3_open_v2(store.c_str(), &state->db, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK) {
        return make_error(ErrorCode::io, sqlite_failure(state->db, store, "opening"));
    }
    sqlite3_busy_timeout(state->db, 5000); // a WAL reader waits only while a writer's checkpoint resets the log
    Result<int> version = store_check_identity(state->db, store);
    if (!version) return version.error();
    if (*version < k_store_oldest_readable_version) {
        return make_error(ErrorCode::unsupported, store.string() + ": older schema " + std::to_string(*version) + ": a `kumite train` on it migrates it");
    }
    return StoreReader(std::move(state));
}

StoreReader::StoreReader(std::unique_ptr<State> state) : m_state(std::move(state)) {}
StoreReader::StoreReader(StoreReader&&) noexcept = default;
StoreReader& StoreReader::operator=(StoreReader&&) noexcept = default;
StoreReader::~StoreReader() = default;

Result<std::vector<TraineeRow>> StoreReader::trainees() const {
    return m_state->collect<TraineeRow>("SELECT t.id, t.name, count(s.id), coalesce(max(s.started_utc), '') FROM trainees t "
                                        "LEFT JOIN sessions s ON s.trainee_id = t.id GROUP BY t.id ORDER BY t.name",
                                        std::nullopt, [](const Statement& row) {
                                            return TraineeRow{row.integer(0), row.text(1), static_cast<int>(row.integer(2)), row.text(3)};
                                        });
}

Result<void> StoreReader::check_trainee(const std::string& trainee) const {
    Result<std::vector<TraineeRow>> known = trainees();
    if (!known) return known.error();
    std::string names;
    for (const TraineeRow& row : *known) {
        if (row.name == trainee) return {};
        names += (names.empty() ? "" : ", ") + row.name;
    }
    return make_error(ErrorCode::invalid, m_state->store.string() + ": no trainee \"" + trainee + "\" (" +
                                              (names.empty() ? std::string("the store has no trainee yet") : "its trainees: " + names) + ")");
}

Result<std::vector<SessionRow>> StoreReader::sessions(const std::optional<std::string>& trainee, bool with_json) const {
    const std::string columns = "s.id, t.name, s.drill, s.drill_file, s.character, s.tracker, s.started_utc, s.duration_s, s.complete, " +
                                std::string(with_json ? "s.settings_json, s.summary_json, " : "'', '', ") + k_session_counts;
    return m_state->collect<SessionRow>(session_query(columns, trainee.has_value()), trainee, [](const Statement& row) {
        SessionRow session;
        session.id = row.integer(0);
        session.trainee = row.text(1);
        session.drill = row.text(2);
        session.drill_file = row.text(3);
        session.character = row.text(4);
        session.tracker = row.text(5);
        session.started_utc = row.text(6);
        session.duration_s = row.real(7);
        session.complete = row.integer(8) != 0;
        session.settings_json = row.text(9);
        session.summary_json = row.text(10);
        session.attacks = static_cast<int>(row.integer(11));
        session.user_strikes = static_cast<int>(row.integer(12));
        return session;
    });
}

Result<std::vector<AttackRow>> StoreReader::attacks(std::int64_t session_id) const {
    const std::string sql = "SELECT " + std::string(k_attack_columns) + " FROM attacks WHERE session_id = " + std::to_string(session_id) + " ORDER BY seq";
    return m_state->collect<AttackRow>(sql, std::nullopt, [](const Statement& row) { return attack_read(row, 0); });
}

Result<std::vector<UserStrikeRow>> StoreReader::user_strikes(std::int64_t session_id) const {
    const std::string sql =
        "SELECT " + std::string(k_user_strike_columns) + " FROM user_strikes WHERE session_id = " + std::to_string(session_id) + " ORDER BY seq";
    return m_state->collect<UserStrikeRow>(sql, std::nullopt, [](const Statement& row) { return user_strike_read(row, 0); });
}

Result<std::vector<std::pair<std::int64_t, AttackRow>>> StoreReader::trainee_attacks(const std::string& trainee) const {
    return m_state->collect<std::pair<std::int64_t, AttackRow>>(
        session_query("s.id, " + std::string(k_attack_columns), true, "attacks"), trainee,
        [](const Statement& row) { return std::make_pair(row.integer(0), attack_read(row, 1)); });
}

Result<std::vector<std::pair<std::int64_t, UserStrikeRow>>> StoreReader::trainee_user_strikes(const std::string& trainee) const {
    return m_state->collect<std::pair<std::int64_t, UserStrikeRow>>(
        session_query("s.id, " + std::string(k_user_strike_columns), true, "user_strikes"), trainee,
        [](const Statement& row) { return std::make_pair(row.integer(0), user_strike_read(row, 1)); });
}

Result<void> StoreReader::read_table(StoreTable table, const std::optional<std::string>& trainee,
                                     const std::function<void(const std::vector<std::string>& names)>& on_columns,
                                     const std::function<void(const std::vector<StoreValue>& values)>& on_row) const {
    std::string sql;
    switch (table) {
    case StoreTable::sessions:
        sql = session_query("s.id AS session_id, t.name AS trainee, s.drill, s.drill_file, s.character, s.tracker, s.started_utc, s.duration_s, "
                            "s.complete, " + std::string(k_session_counts) + ", s.settings_json, s.summary_json, s.drill_text",
                            trainee.has_value());
        break;
    case StoreTable::attacks:
        sql = session_query("s.id AS session_id, t.name AS trainee, " + std::string(k_attack_columns), trainee.has_value(), "attacks");
        break;
    case StoreTable::user_strikes:
        sql = session_query("s.id AS session_id, t.name AS trainee, " + std::string(k_user_strike_columns), trainee.has_value(), "user_strikes");
        break;
    }
    Result<Statement> statement = Statement::prepare(m_state->db, sql, m_state->store);
    if (!statement) return statement.error();
    const int column_count = sqlite3_column_count(statement->get());
    std::vector<std::string> names;
    for (int c = 0; c < column_count; ++c) names.emplace_back(sqlite3_column_name(statement->get(), c));
    on_columns(names);
    if (trainee) statement->bind_text(1, *trainee);
    std::vector<StoreValue> values(static_cast<std::size_t>(column_count));
    int status = SQLITE_ROW;
    while ((status = statement->step()) == SQLITE_ROW) {
        for (int c = 0; c < column_count; ++c) {
            sqlite3_stmt* row = statement->get();
            switch (sqlite3_column_type(row, c)) {
            case SQLITE_INTEGER: values[c] = std::int64_t(sqlite3_column_int64(row, c)); break;
            case SQLITE_FLOAT: values[c] = sqlite3_column_double(row, c); break;
            case SQLITE_NULL: values[c] = std::monostate(); break;
            default: values[c] = std::string_view(reinterpret_cast<const char*>(sqlite3_column_text(row, c)), sqlite3_column_bytes(row, c)); break;
            }
        }
        on_row(values);
    }
    if (status != SQLITE_DONE) return make_error(ErrorCode::io, sqlite_failure(m_state->db, m_state->store, "reading"));
    return {};
}

} // namespace kumite::training
