// SessionWriter: one session into the training store. The frame loop only queues rows; a thread commits them. The
// store is taken with a BSD lock (flock) on its file for the writer's life: SQLite's own locks last a transaction,
// and a second session must be refused for the whole of the first one, not only while it commits.

#include "store_file_check.h"
#include "store_schema.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <ctime>
#include <fstream>
#include <mutex>
#include <set>
#include <thread>

namespace kumite::training {

namespace {

using Clock = std::chrono::steady_clock;
using FileId = std::pair<dev_t, ino_t>;

// The stores this process writes. A second writer of the same process is refused from this list before it opens a
// descriptor of the file: refused after, it would close that descriptor, and closing any descriptor of a file drops
// every POSIX lock the process holds on it, the first writer's SQLite locks included.
std::mutex g_written_mutex;
std::set<FileId> g_written;

// The process holding a BSD lock on the inode, from /proc/locks ("1: FLOCK  ADVISORY  WRITE 1234 fd:01:5678 0 EOF");
// 0 when none is found. Matched on the inode alone: on overlay file systems the device there is not stat()'s.
long lock_holder_pid(ino_t inode) {
    std::ifstream locks("/proc/locks");
    std::string line;
    while (std::getline(locks, line)) {
        char type[16] = {};
        long pid = 0;
        unsigned major = 0, minor = 0;
        unsigned long long locked_inode = 0;
        if (std::sscanf(line.c_str(), "%*d: %15s %*s %*s %ld %x:%x:%llu", type, &pid, &major, &minor, &locked_inode) == 5 &&
            std::strcmp(type, "FLOCK") == 0 && locked_inode == inode) {
            return pid;
        }
    }
    return 0;
}

std::string utc_now() {
    const std::time_t now = std::time(nullptr);
    std::tm utc{};
    gmtime_r(&now, &utc);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
    return text;
}

} // namespace

struct SessionWriter::State {
    std::filesystem::path store;
    sqlite3* db = nullptr;
    int lock_fd = -1;
    FileId file_id{};
    bool registered = false;
    bool refused = false; // closing leaves the WAL as it was, so that a refused store stays byte for byte
    std::int64_t session_id = 0;
    Clock::duration commit_every{};
    Statement insert_attack, insert_user_strike, update_duration, complete_session;

    // What the frame loop hands to the thread, guarded by `mutex`.
    std::mutex mutex;
    std::condition_variable wake;
    std::vector<AttackRow> queued_attacks;
    std::vector<UserStrikeRow> queued_user_strikes;
    std::optional<double> queued_duration_s;
    std::optional<std::pair<double, std::string>> finish_with; // duration, summary
    bool stopping = false;
    std::optional<std::string> error;
    std::thread thread;

    ~State() {
        if (thread.joinable()) {
            {
                std::lock_guard lock(mutex);
                stopping = true;
            }
            wake.notify_one();
            thread.join();
        }
        for (Statement* statement : {&insert_attack, &insert_user_strike, &update_duration, &complete_session}) *statement = Statement();
        if (refused && db) sqlite3_db_config(db, SQLITE_DBCONFIG_NO_CKPT_ON_CLOSE, 1, nullptr);
        sqlite3_close(db);
        // Only now: closing the lock's descriptor drops this process's POSIX locks on the file, SQLite's included.
        if (lock_fd >= 0) {
            ::flock(lock_fd, LOCK_UN);
            ::close(lock_fd);
        }
        if (registered) {
            std::lock_guard lock(g_written_mutex);
            g_written.erase(file_id);
        }
    }

    // One transaction of the rows taken from the queue; the error's message when it failed (rolled back).
    std::optional<std::string> commit(const std::vector<AttackRow>& attacks, const std::vector<UserStrikeRow>& user_strikes,
                                      std::optional<double> duration_s, const std::optional<std::pair<double, std::string>>& finish) {
        if (attacks.empty() && user_strikes.empty() && !duration_s && !finish) return std::nullopt;
        if (Result<void> begun = sqlite_exec(db, "BEGIN IMMEDIATE", store); !begun) return begun.error().message;
        std::optional<std::string> failure;
        const auto run = [&](Statement& statement, const char* doing) {
            if (!failure && statement.step() != SQLITE_DONE) failure = sqlite_failure(db, store, doing);
            statement.reset();
        };
        for (const AttackRow& row : attacks) {
            insert_attack.bind_integer(1, session_id);
            attack_bind(insert_attack, 2, row);
            run(insert_attack, "storing an attack");
        }
        for (const UserStrikeRow& row : user_strikes) {
            insert_user_strike.bind_integer(1, session_id);
            user_strike_bind(insert_user_strike, 2, row);
            run(insert_user_strike, "storing a strike");
        }
        if (finish) {
            complete_session.bind_real(1, finish->first);
            complete_session.bind_text(2, finish->second);
            complete_session.bind_integer(3, session_id);
            run(complete_session, "completing the session");
        } else if (duration_s) {
            update_duration.bind_real(1, *duration_s);
            update_duration.bind_integer(2, session_id);
            run(update_duration, "storing the duration");
        }
        if (!failure) {
            if (Result<void> committed = sqlite_exec(db, "COMMIT", store); !committed) failure = committed.error().message;
        }
        if (failure) (void)sqlite_exec(db, "ROLLBACK", store);
        return failure;
    }

    // The thread: every `commit_every` of wall time (and once more when stopping) commits what was queued. After an
    // error the rows are dropped: the first error is what the session reports.
    void commit_loop() {
        std::vector<AttackRow> attacks;
        std::vector<UserStrikeRow> user_strikes;
        std::unique_lock lock(mutex);
        for (;;) {
            wake.wait_until(lock, Clock::now() + commit_every, [&] { return stopping; });
            attacks.swap(queued_attacks); // the emptied vectors keep their capacity for the frame loop
            user_strikes.swap(queued_user_strikes);
            const std::optional<double> duration_s = std::exchange(queued_duration_s, std::nullopt);
            const std::optional<std::pair<double, std::string>> finish = std::exchange(finish_with, std::nullopt);
            const bool last = stopping, failed_before = error.has_value();
            lock.unlock();
            const std::optional<std::string> failure = failed_before ? std::nullopt : commit(attacks, user_strikes, duration_s, finish);
            attacks.clear();
            user_strikes.clear();
            lock.lock();
            if (failure && !error) error = failure;
            if (last) return;
        }
    }

    Result<void> refuse(std::string message) {
        refused = true;
        return make_error(ErrorCode::invalid, std::move(message));
    }

    // Takes the store for this writer: this process's list, then the BSD lock.
    Result<void> take();
    // Checks, migrates and inserts the session (incomplete).
    Result<void> begin(const SessionStart& start);
};

Result<void> SessionWriter::State::take() {
    struct stat file_stat {};
    if (::stat(store.c_str(), &file_stat) != 0) return make_error(ErrorCode::io, store.string() + ": " + std::strerror(errno));
    file_id = {file_stat.st_dev, file_stat.st_ino};
    {
        std::lock_guard lock(g_written_mutex);
        if (!g_written.insert(file_id).second) {
            return refuse(store.string() + ": in use by another session (pid " + std::to_string(::getpid()) + ", this process)");
        }
        registered = true;
    }
    // READWRITE without CREATE: the file exists (created above when missing); SQLite must not make a new one.
    if (sqlite3_open_v2(store.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr) != SQLITE_OK) {
        return make_error(ErrorCode::io, sqlite_failure(db, store, "opening"));
    }
    lock_fd = ::open(store.c_str(), O_RDONLY | O_CLOEXEC);
    if (lock_fd < 0) return make_error(ErrorCode::io, store.string() + ": " + std::strerror(errno));
    if (::flock(lock_fd, LOCK_EX | LOCK_NB) != 0) {
        const long holder = lock_holder_pid(file_stat.st_ino);
        return refuse(store.string() + ": in use by another session" + (holder > 0 ? " (pid " + std::to_string(holder) + ")" : "") +
                      ": one session writes to a store at a time");
    }
    return {};
}

Result<void> SessionWriter::State::begin(const SessionStart& start) {
    sqlite3_busy_timeout(db, 5000); // readers never block a WAL writer; this covers a checkpointing reader
    // Read-only checks first: journal_mode=WAL would rewrite the header of a file that is then refused.
    Result<int> version = store_check_identity(db, store);
    if (!version) return refuse(version.error().message);
    Result<std::string> check = sqlite_first_text(db, "PRAGMA quick_check", store);
    if (!check) return refuse(store.string() + ": damaged: " + sqlite3_errmsg(db));
    if (*check != "ok") {
        // The first finding, without the "*** in database main ***" line that heads it.
        std::string finding = *check;
        if (finding.rfind("***", 0) == 0 && finding.find('\n') != std::string::npos) finding.erase(0, finding.find('\n') + 1);
        return refuse(store.string() + ": damaged: " + finding.substr(0, finding.find('\n')) + " (PRAGMA quick_check)");
    }
    Result<std::string> journal = sqlite_first_text(db, "PRAGMA journal_mode=WAL", store);
    if (!journal) return journal.error();
    if (*journal != "wal") return make_error(ErrorCode::io, store.string() + ": cannot use a write-ahead log (journal mode " + *journal + ")");
    if (Result<void> set = sqlite_exec(db, "PRAGMA synchronous=NORMAL", store); !set) return set;
    if (Result<void> migrated = store_migrate(db, store, *version); !migrated) return migrated;

    if (Result<void> begun = sqlite_exec(db, "BEGIN IMMEDIATE", store); !begun) return begun;
    const std::string started_utc = start.started_utc.empty() ? utc_now() : start.started_utc;
    Result<Statement> trainee = Statement::prepare(db, "INSERT OR IGNORE INTO trainees(name, created_utc) VALUES(?, ?)", store);
    Result<Statement> session = Statement::prepare(
        db,
        "INSERT INTO sessions(trainee_id, drill, drill_file, drill_text, settings_json, character, tracker, started_utc) "
        "VALUES((SELECT id FROM trainees WHERE name = ?), ?, ?, ?, ?, ?, ?, ?)",
        store);
    if (!trainee || !session) {
        (void)sqlite_exec(db, "ROLLBACK", store);
        return !trainee ? trainee.error() : session.error();
    }
    trainee->bind_text(1, start.trainee);
    trainee->bind_text(2, started_utc);
    int p = 1;
    for (const std::string* text : {&start.trainee, &start.drill, &start.drill_file, &start.drill_text, &start.settings_json, &start.character,
                                    &start.tracker, &started_utc}) {
        session->bind_text(p++, *text);
    }
    if (trainee->step() != SQLITE_DONE || session->step() != SQLITE_DONE) {
        const std::string message = sqlite_failure(db, store, "inserting the session");
        (void)sqlite_exec(db, "ROLLBACK", store);
        return make_error(ErrorCode::io, message);
    }
    session_id = sqlite3_last_insert_rowid(db);
    return sqlite_exec(db, "COMMIT", store);
}

Result<std::unique_ptr<SessionWriter>> SessionWriter::open(const std::filesystem::path& store, const SessionStart& start, double commit_every_s) {
    if (start.trainee.empty()) return make_error(ErrorCode::invalid, store.string() + ": a session needs the trainee's name");
    std::error_code error;
    if (!std::filesystem::exists(store, error)) {
        if (store.has_parent_path()) std::filesystem::create_directories(store.parent_path(), error);
        if (error) return make_error(ErrorCode::io, store.parent_path().string() + ": cannot create the store's folder: " + error.message());
        // Another session may have created it meanwhile: then it is opened as any existing store.
        if (Result<void> created = store_create_at_version(store, store_schema_version()); !created && !std::filesystem::exists(store, error)) {
            return created.error();
        }
    }
    if (Result<void> checked = store_file_check(store); !checked) return checked.error();

    auto state = std::make_unique<State>();
    state->store = store;
    state->commit_every = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(std::max(0.01, commit_every_s)));
    if (Result<void> taken = state->take(); !taken) return taken.error();
    if (Result<void> begun = state->begin(start); !begun) return begun.error();
    Result<Statement> insert_attack = Statement::prepare(state->db, attack_insert_sql(), store);
    Result<Statement> insert_user_strike = Statement::prepare(state->db, user_strike_insert_sql(), store);
    Result<Statement> update_duration = Statement::prepare(state->db, "UPDATE sessions SET duration_s = ? WHERE id = ?", store);
    Result<Statement> complete_session = Statement::prepare(state->db, "UPDATE sessions SET complete = 1, duration_s = ?, summary_json = ? WHERE id = ?", store);
    for (Result<Statement>* statement : {&insert_attack, &insert_user_strike, &update_duration, &complete_session}) {
        if (!*statement) return statement->error();
    }
    state->insert_attack = std::move(*insert_attack);
    state->insert_user_strike = std::move(*insert_user_strike);
    state->update_duration = std::move(*update_duration);
    state->complete_session = std::move(*complete_session);
    state->queued_attacks.reserve(256); // a session's first seconds of rows without a reallocation in add()
    state->queued_user_strikes.reserve(256);
    State& running = *state;
    state->thread = std::thread([&running] { running.commit_loop(); });
    return std::unique_ptr<SessionWriter>(new SessionWriter(std::move(state)));
}

SessionWriter::SessionWriter(std::unique_ptr<State> state) : m_state(std::move(state)) {}
SessionWriter::~SessionWriter() = default;

std::int64_t SessionWriter::session_id() const { return m_state->session_id; }

void SessionWriter::add(AttackRow row) {
    std::lock_guard lock(m_state->mutex);
    if (!m_state->stopping) m_state->queued_attacks.push_back(std::move(row));
}

void SessionWriter::add(UserStrikeRow row) {
    std::lock_guard lock(m_state->mutex);
    if (!m_state->stopping) m_state->queued_user_strikes.push_back(std::move(row));
}

void SessionWriter::set_duration(double duration_s) {
    std::lock_guard lock(m_state->mutex);
    m_state->queued_duration_s = duration_s;
}

Result<void> SessionWriter::finish(double duration_s, const std::string& summary_json) {
    State& state = *m_state;
    if (!state.thread.joinable()) return make_error(ErrorCode::invalid, state.store.string() + ": the session was finished already");
    {
        std::lock_guard lock(state.mutex);
        state.finish_with = std::make_pair(duration_s, summary_json);
        state.stopping = true;
    }
    state.wake.notify_one();
    state.thread.join();
    std::lock_guard lock(state.mutex);
    if (state.error) return make_error(ErrorCode::io, *state.error);
    return {};
}

std::optional<std::string> SessionWriter::error() const {
    std::lock_guard lock(m_state->mutex);
    return m_state->error;
}

} // namespace kumite::training
