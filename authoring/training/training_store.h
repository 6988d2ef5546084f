#pragma once
// The training store: trainees, their sessions, every attack of the fighter with the person's response, the person's
// own strikes, and each session's summary, in one SQLite file (docs/training.md). A session writes it through a
// SessionWriter (one at a time: a second is refused while the store is in use); any number of StoreReaders read it
// meanwhile (WAL). The schema has a version (PRAGMA user_version) and migrates forward on opening; a store that is
// not one, is damaged, or comes from a newer kumite is refused with the reason and left as it was, byte for byte.

#include "kumite/core/result.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace kumite::training {

// The schema's version this kumite writes (the number of migrations, store_schema.cpp).
int store_schema_version();

// Where the store is when --store is not given: $KUMITE_STORE, else $XDG_DATA_HOME/kumite/training.sqlite, else
// ~/.local/share/kumite/training.sqlite.
std::filesystem::path default_store_path();

// Whether a session is writing to `store` now (its SessionWriter holds the store). Call it before opening a reader
// in this process: it opens and closes a descriptor of the file, and closing one drops the process's SQLite locks.
bool store_being_written(const std::filesystem::path& store);

inline constexpr double k_no_value = std::numeric_limits<double>::quiet_NaN();

// A session as it starts (what the sessions table holds before its end).
struct SessionStart {
    std::string trainee;         // the name given to --trainee; created in the store the first time
    std::string drill;           // the drill's name
    std::string drill_file;      // the path it was read from
    std::string drill_text;      // the drill file's text, as it was run
    std::string settings_json;   // the fighter's settings (play --print-settings as JSON)
    std::string character;       // the fighter's character
    std::string tracker;         // the tracker's source (dtrack:…, xr, simulate:…, capture:…)
    std::string started_utc;     // ISO 8601, e.g. 2026-12-06T04:00:00Z (empty: now)
};

// One blow of the fighter and the person's answer (a user_response event of the bout).
struct AttackRow {
    int seq = 0;                 // 0-based, in the session
    double t_s = 0.0;            // the blow's start, seconds into the session
    int part = 0;                // the drill part, 0-based
    std::string part_name;
    std::string difficulty;      // the part's level
    std::string command;         // punch, kick, knee, elbow, slash
    std::string kind;            // straight, hook, uppercut, front, roundhouse, side, other
    std::string height;          // low, middle, high
    std::string side;            // the clip's side: left, right
    std::string target_part;     // head, chin, chest, solar_plexus
    std::string combination;     // its combination's name, or empty
    int blow = 0;                // 1-based in the combination, 0 for a single
    bool own = false;            // the fighter's own attack (free sparring), not an ordered one
    std::string result;          // hit, blocked, miss
    std::string blocked_by;      // the glove or forearm, when blocked
    std::string response;        // block, parry, slip, duck, step_back, none
    double response_time_s = k_no_value; // from the blow's first visible motion; NaN: no response
    std::string quality;         // in_time, late, none
    bool countered = false;
    int counter_landed = -1;     // -1: no counter; 0 or 1
};

// One strike of the person (a user_strike_end event).
struct UserStrikeRow {
    int seq = 0;
    double t_s = 0.0;
    int part = 0;
    std::string hand;            // left, right
    std::string aimed_at;        // head, chest
    std::string move;            // the fighter's defence: block_clip, synthesized, slip, none
    std::string outcome;         // landed, blocked, slipped, missed, ...
    bool defended = false;
    double peak_speed_mps = k_no_value;
};

// A session as stored (sessions joined with trainees, with its counts).
struct SessionRow {
    std::int64_t id = 0;
    std::string trainee;
    std::string drill;
    std::string drill_file;
    std::string character;
    std::string tracker;
    std::string started_utc;
    double duration_s = 0.0;     // as of the last commit for an incomplete session
    bool complete = false;       // false: it did not end (killed, crashed, or still running)
    std::string settings_json;
    std::string summary_json;    // empty for an incomplete session
    int attacks = 0;
    int user_strikes = 0;
};

struct TraineeRow {
    std::int64_t id = 0;
    std::string name;
    int sessions = 0;
    std::string last_utc;        // the latest session's start, or empty
};

// Writes one session. Opening takes the store for itself (refused while another session writes to it), creates the
// store (and its folder) when there is none, migrates an older one, and inserts the session, marked incomplete.
// add() queues rows without touching the file; a thread commits them at least every `commit_every_s` of wall time
// (one transaction each), so the frame loop never waits on the disk. finish() commits the rest and marks the
// session complete with its duration and summary. Destroyed without finish() (or killed), the session stays
// incomplete with every row committed so far.
class SessionWriter {
public:
    static Result<std::unique_ptr<SessionWriter>> open(const std::filesystem::path& store, const SessionStart& start, double commit_every_s = 0.25);
    ~SessionWriter();
    SessionWriter(const SessionWriter&) = delete;
    SessionWriter& operator=(const SessionWriter&) = delete;

    std::int64_t session_id() const;
    void add(AttackRow row);
    void add(UserStrikeRow row);
    void set_duration(double duration_s); // the session's length so far (committed with the next rows)
    Result<void> finish(double duration_s, const std::string& summary_json);
    // The first error of the committing thread (the disk full, the file gone), if any; rows after it are lost.
    std::optional<std::string> error() const;

    struct State;
private:
    explicit SessionWriter(std::unique_ptr<State> state);
    std::unique_ptr<State> m_state;
};

// A table of the store as the export writes it (store_export.h): sessions with their trainee's name and counts,
// attacks and user_strikes with their session's id and trainee's name.
enum class StoreTable { sessions, attacks, user_strikes };

// One stored value as SQLite gives it: NULL (a NaN or a missing value), an integer, a real or text.
using StoreValue = std::variant<std::monostate, std::int64_t, double, std::string_view>;

// Reads a store (read-only; never creates, migrates or locks it).
class StoreReader {
public:
    static Result<StoreReader> open(const std::filesystem::path& store);
    StoreReader(StoreReader&&) noexcept;
    StoreReader& operator=(StoreReader&&) noexcept;
    ~StoreReader();

    Result<std::vector<TraineeRow>> trainees() const;
    // Refuses a name the store has no trainee of, naming the ones it has (what a --trainee flag answers).
    Result<void> check_trainee(const std::string& trainee) const;
    // Every session, oldest first; of one trainee when `trainee` is given (an unknown name: none). Without
    // `with_json`, settings_json and summary_json are left empty (a listing: most of a session's bytes are those).
    Result<std::vector<SessionRow>> sessions(const std::optional<std::string>& trainee = std::nullopt, bool with_json = true) const;
    Result<std::vector<AttackRow>> attacks(std::int64_t session_id) const;
    Result<std::vector<UserStrikeRow>> user_strikes(std::int64_t session_id) const;
    // Every attack of a trainee's sessions, paired with its session's id, in session then seq order.
    Result<std::vector<std::pair<std::int64_t, AttackRow>>> trainee_attacks(const std::string& trainee) const;
    Result<std::vector<std::pair<std::int64_t, UserStrikeRow>>> trainee_user_strikes(const std::string& trainee) const;
    // Every row of `table` (of one trainee's sessions when given), in session then seq order: `on_columns` once with
    // the column names, then `on_row` per row with its values (the text valid during the call only).
    Result<void> read_table(StoreTable table, const std::optional<std::string>& trainee,
                            const std::function<void(const std::vector<std::string>& names)>& on_columns,
                            const std::function<void(const std::vector<StoreValue>& values)>& on_row) const;

    struct State;
private:
    explicit StoreReader(std::unique_ptr<State> state);
    std::unique_ptr<State> m_state;
};

} // namespace kumite::training
