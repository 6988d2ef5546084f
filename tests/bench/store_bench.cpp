// The training store at scale: a generated store of 10,000 sessions x 30 attacks (and 3 user strikes each) over 50
// trainees, written in one transaction through the schema's own row binding, then timed as the commands use it:
//   - list: StoreReader::open + sessions() of every session (kumite sessions), against the baseline of counting each
//     session's attacks by reading them (one query a session, as a listing without the GROUP BY would);
//   - trainee: open + sessions(one trainee) + trainee_attacks(that trainee) (kumite progress's data).
// Each run opens the store anew, on a warm page cache. Also: the generation time, the file's size, and the cost of
// SessionWriter::add (what the frame loop pays per row).
//
// usage: store_bench [--sessions N] [--attacks K] [--trainees T] [--repeats R] [--keep STORE.sqlite]
// Prints one JSON document.

#include "store_schema.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <iostream>
#include <random>
#include <string>
#include <unistd.h>
#include <vector>

using namespace kumite;
using namespace kumite::training;

namespace {

using Clock = std::chrono::steady_clock;

[[noreturn]] void fail(const std::string& message) {
    std::cerr << "store_bench: " << message << "\n";
    std::exit(1);
}

template <class T>
T checked(Result<T> result) {
    if (!result) fail(result.error().message);
    return std::move(result.value());
}

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

template <class Work>
nlohmann::json time_runs(int repeats, Work&& work) {
    work(); // warm: the file's pages into the page cache
    std::vector<double> times;
    for (int i = 0; i < repeats; ++i) {
        const auto start = Clock::now();
        work();
        times.push_back(seconds_since(start));
    }
    std::sort(times.begin(), times.end());
    const std::size_t p99 = std::min(times.size() - 1, static_cast<std::size_t>(0.99 * times.size()));
    return {{"n", repeats}, {"median_s", times[times.size() / 2]}, {"p99_s", times[p99]}, {"max_s", times.back()}};
}

AttackRow random_attack(int seq, std::mt19937& random) {
    static const char* commands[] = {"punch", "kick", "knee", "elbow"};
    static const char* responses[] = {"block", "parry", "slip", "duck", "none"};
    AttackRow row;
    row.seq = seq;
    row.t_s = 2.0 + 3.1 * seq;
    row.part = seq / 10;
    row.part_name = "part " + std::to_string(seq / 10);
    row.difficulty = "medium";
    row.command = commands[random() % 4];
    row.kind = "straight";
    row.height = random() % 2 ? "high" : "middle";
    row.side = random() % 2 ? "left" : "right";
    row.target_part = "head";
    row.combination = seq % 3 ? "one-two" : "";
    row.blow = seq % 3;
    row.result = random() % 3 ? "blocked" : "hit";
    row.blocked_by = "left_glove";
    row.response = responses[random() % 5];
    row.response_time_s = row.response == "none" ? k_no_value : 0.15 + 0.001 * (random() % 400);
    row.quality = row.response == "none" ? "none" : "in_time";
    row.countered = random() % 4 == 0;
    row.counter_landed = row.countered ? static_cast<int>(random() % 2) : -1;
    return row;
}

// The store, in one transaction: what years of sessions would leave, without a writer's per-session commits.
void generate(const std::filesystem::path& store, int sessions, int attacks, int trainees) {
    if (Result<void> created = store_create_at_version(store, store_schema_version()); !created) fail(created.error().message);
    sqlite3* db = nullptr;
    if (sqlite3_open_v2(store.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr) != SQLITE_OK) fail(sqlite_failure(db, store, "opening"));
    const auto exec = [&](const char* sql) {
        if (Result<void> done = sqlite_exec(db, sql, store); !done) fail(done.error().message);
    };
    const auto run = [&](Statement& statement) {
        if (statement.step() != SQLITE_DONE) fail(sqlite_failure(db, store, "inserting"));
        statement.reset();
    };
    exec("BEGIN");
    {
        Statement trainee = checked(Statement::prepare(db, "INSERT INTO trainees(id, name, created_utc) VALUES(?, ?, '2025-01-01T00:00:00Z')", store));
        for (int t = 1; t <= trainees; ++t) {
            trainee.bind_integer(1, t);
            trainee.bind_text(2, "trainee " + std::to_string(t));
            run(trainee);
        }
        Statement session = checked(Statement::prepare(
            db,
            "INSERT INTO sessions(id, trainee_id, drill, drill_file, drill_text, settings_json, character, tracker, started_utc, duration_s, "
            "complete, summary_json) VALUES(?, ?, 'basics', 'data/drills/basics.toml', ?, ?, 'brawler', 'dtrack:5000', ?, 180, 1, ?)",
            store));
        Statement attack = checked(Statement::prepare(db, attack_insert_sql(), store));
        Statement strike = checked(Statement::prepare(db, user_strike_insert_sql(), store));
        // Sizes of real ones: a drill file of a few parts, play's settings, a bout summary.
        const std::string drill_text = "[drill]\nname = \"basics\"\n" + std::string(600, '#') + "\n";
        const std::string settings_json = "{\"settings\": \"" + std::string(1500, 's') + "\"}";
        const std::string summary_json = "{\"summary\": \"" + std::string(400, 'x') + "\"}";
        std::mt19937 random(63);
        for (int s = 1; s <= sessions; ++s) {
            // One session every 3 hours from 2023 on, stored as they happened.
            const std::time_t when = 1672531200 + std::time_t(s) * 3 * 3600;
            std::tm utc{};
            gmtime_r(&when, &utc);
            char started[32];
            std::strftime(started, sizeof started, "%Y-%m-%dT%H:%M:%SZ", &utc);
            session.bind_integer(1, s);
            session.bind_integer(2, 1 + s % trainees);
            session.bind_text(3, drill_text);
            session.bind_text(4, settings_json);
            session.bind_text(5, started);
            session.bind_text(6, summary_json);
            run(session);
            for (int a = 0; a < attacks; ++a) {
                attack.bind_integer(1, s);
                attack_bind(attack, 2, random_attack(a, random));
                run(attack);
            }
            for (int u = 0; u < 3; ++u) {
                UserStrikeRow row;
                row.seq = u;
                row.hand = u % 2 ? "left" : "right";
                row.outcome = "blocked";
                row.peak_speed_mps = 5.0 + u;
                strike.bind_integer(1, s);
                user_strike_bind(strike, 2, row);
                run(strike);
            }
        }
    }
    exec("COMMIT");
    sqlite3_close(db);
}

// What SessionWriter::add costs the frame loop, per row, while its thread commits every 0.25 s.
nlohmann::json time_add(const std::filesystem::path& store, int rows) {
    SessionStart start;
    start.trainee = "trainee 1";
    start.drill = "bench";
    std::unique_ptr<SessionWriter> writer = checked(SessionWriter::open(store, start));
    std::mt19937 random(7);
    std::vector<AttackRow> prepared;
    for (int i = 0; i < rows; ++i) prepared.push_back(random_attack(i, random));
    std::vector<double> times;
    for (AttackRow& row : prepared) {
        const auto begin = Clock::now();
        writer->add(std::move(row));
        times.push_back(std::chrono::duration<double, std::micro>(Clock::now() - begin).count());
        if (times.size() % 100 == 0) usleep(16667); // a frame now and then, so commits interleave
    }
    const auto finish_start = Clock::now();
    if (Result<void> finished = writer->finish(60.0, "{}"); !finished) fail(finished.error().message);
    const double finish_s = seconds_since(finish_start);
    std::sort(times.begin(), times.end());
    return {{"n", rows}, {"median_us", times[times.size() / 2]}, {"p99_us", times[times.size() * 99 / 100]}, {"max_us", times.back()}, {"finish_s", finish_s}};
}

} // namespace

int main(int argc, char** argv) {
    int sessions = 10000, attacks = 30, trainees = 50, repeats = 20;
    std::string keep;
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        if (i + 1 >= argc) fail("usage: store_bench [--sessions N] [--attacks K] [--trainees T] [--repeats R] [--keep STORE.sqlite]");
        const std::string value = argv[++i];
        if (flag == "--sessions") sessions = std::max(1, std::atoi(value.c_str()));
        else if (flag == "--attacks") attacks = std::max(0, std::atoi(value.c_str()));
        else if (flag == "--trainees") trainees = std::max(1, std::atoi(value.c_str()));
        else if (flag == "--repeats") repeats = std::max(1, std::atoi(value.c_str()));
        else if (flag == "--keep") keep = value;
        else fail("unknown flag " + flag);
    }
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("kumite-store-bench-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    const std::filesystem::path store = keep.empty() ? dir / "training.sqlite" : std::filesystem::path(keep);
    std::error_code ignored;
    std::filesystem::remove(store, ignored);

    const auto generation_start = Clock::now();
    generate(store, sessions, attacks, trainees);
    const double generation_s = seconds_since(generation_start);
    const std::uintmax_t bytes = std::filesystem::file_size(store);

    const std::string one_trainee = "trainee 7";
    std::size_t listed = 0, trainee_sessions = 0, trainee_attacks = 0;
    const nlohmann::json list = time_runs(repeats, [&] {
        StoreReader reader = checked(StoreReader::open(store));
        listed = checked(reader.sessions()).size();
    });
    const nlohmann::json baseline = time_runs(std::max(3, repeats / 5), [&] {
        StoreReader reader = checked(StoreReader::open(store));
        std::size_t counted = 0;
        for (const SessionRow& row : checked(reader.sessions())) counted += checked(reader.attacks(row.id)).size();
        if (counted != std::size_t(sessions) * std::size_t(attacks)) fail("the baseline counted " + std::to_string(counted) + " attacks");
    });
    const nlohmann::json trainee = time_runs(repeats, [&] {
        StoreReader reader = checked(StoreReader::open(store));
        trainee_sessions = checked(reader.sessions(one_trainee)).size();
        trainee_attacks = checked(reader.trainee_attacks(one_trainee)).size();
    });
    const nlohmann::json add = time_add(store, 3000);

    nlohmann::json document = {
        {"bench", "store"},
        {"store", {{"sessions", sessions}, {"attacks_per_session", attacks}, {"trainees", trainees}, {"bytes", bytes}, {"generation_s", generation_s}}},
        {"list", {{"name", "StoreReader::open + sessions() of every session"}, {"sessions", listed}, {"time", list}, {"bar_s", 0.2}}},
        {"baseline", {{"name", "open + sessions() + attacks(id) per session (one query a session)"}, {"time", baseline}}},
        {"speedup_vs_baseline", baseline["median_s"].get<double>() / list["median_s"].get<double>()},
        {"trainee", {{"name", "open + sessions(one trainee) + trainee_attacks(that trainee)"}, {"sessions", trainee_sessions}, {"attacks", trainee_attacks},
                     {"time", trainee}, {"bar_s", 1.0}}},
        {"session_writer_add", add}};
    std::cout << document.dump(2) << "\n";
    if (keep.empty()) std::filesystem::remove_all(dir, ignored);
    return 0;
}
