// The training store (authoring/training): rows written by a SessionWriter read back field for field (NaN as NaN);
// a file that is not a store, is cut short, belongs to another application or to a newer kumite is refused by
// writer and reader and left byte for byte; one writer at a time, in this process or another; readers read while a
// writer commits, which it does without finish(); an unfinished session stays incomplete with its rows; an old
// store migrates with its rows.

#include "store_schema.h"
#include "support/test_paths.h"
#include "training_store.h"

#include <catch2/catch.hpp>

#include <sys/file.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <thread>

using namespace kumite::training;
using kumite::Result;
namespace fs = std::filesystem;

namespace {

SessionStart start_of(const std::string& trainee, const std::string& started_utc = "") {
    SessionStart start;
    start.trainee = trainee;
    start.drill = "basics";
    start.drill_file = "data/drills/basics.toml";
    start.drill_text = "[drill]\nname = \"basics\"\n";
    start.settings_json = R"({"character":"brawler"})";
    start.character = "brawler";
    start.tracker = "simulate:orbit";
    start.started_utc = started_utc;
    return start;
}

AttackRow attack(int seq) {
    AttackRow row;
    row.seq = seq;
    row.t_s = 1.5 + 2.25 * seq;
    row.part = seq % 3;
    row.part_name = "part " + std::to_string(seq % 3);
    row.difficulty = "medium";
    row.command = seq % 2 ? "kick" : "punch";
    row.kind = "hook";
    row.height = "high";
    row.side = seq % 2 ? "left" : "right";
    row.target_part = "chin";
    row.combination = seq % 4 == 0 ? "" : "one-two";
    row.blow = seq % 4;
    row.own = seq % 5 == 0;
    row.result = "blocked";
    row.blocked_by = "left_glove";
    row.response = seq % 3 == 0 ? "none" : "parry";
    row.response_time_s = seq % 3 == 0 ? k_no_value : 0.125 * seq;
    row.quality = seq % 3 == 0 ? "none" : "in_time";
    row.countered = seq % 2 == 0;
    row.counter_landed = seq % 2 == 0 ? seq % 4 == 0 : -1;
    return row;
}

UserStrikeRow user_strike(int seq) {
    UserStrikeRow row;
    row.seq = seq;
    row.t_s = 3.0 + seq;
    row.part = 1;
    row.hand = seq % 2 ? "left" : "right";
    row.aimed_at = "head";
    row.move = "slip";
    row.outcome = "slipped";
    row.defended = true;
    row.peak_speed_mps = seq == 0 ? k_no_value : 4.5 + seq;
    return row;
}

// A double equal to the expected one, NaN included.
bool same_value(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

void require_same(const AttackRow& a, const AttackRow& b) {
    CHECK(a.seq == b.seq);
    CHECK(a.t_s == b.t_s);
    CHECK(a.part == b.part);
    CHECK(a.part_name == b.part_name);
    CHECK(a.difficulty == b.difficulty);
    CHECK(a.command == b.command);
    CHECK(a.kind == b.kind);
    CHECK(a.height == b.height);
    CHECK(a.side == b.side);
    CHECK(a.target_part == b.target_part);
    CHECK(a.combination == b.combination);
    CHECK(a.blow == b.blow);
    CHECK(a.own == b.own);
    CHECK(a.result == b.result);
    CHECK(a.blocked_by == b.blocked_by);
    CHECK(a.response == b.response);
    CHECK(same_value(a.response_time_s, b.response_time_s));
    CHECK(a.quality == b.quality);
    CHECK(a.countered == b.countered);
    CHECK(a.counter_landed == b.counter_landed);
}

// A store holding one finished session of `attacks` attacks and 3 user strikes; returns the session's id.
std::int64_t write_session(const fs::path& store, const std::string& trainee, int attacks, const std::string& started_utc = "") {
    auto writer = SessionWriter::open(store, start_of(trainee, started_utc));
    REQUIRE(writer);
    for (int i = 0; i < attacks; ++i) (*writer)->add(attack(i));
    for (int i = 0; i < 3; ++i) (*writer)->add(user_strike(i));
    REQUIRE((*writer)->finish(60.0 + attacks, R"({"attacks":)" + std::to_string(attacks) + "}"));
    return (*writer)->session_id();
}

// Runs SQL on a store through SQLite directly, as another program would.
void run_sql(const fs::path& file, const std::string& sql) {
    sqlite3* db = nullptr;
    REQUIRE(sqlite3_open(file.c_str(), &db) == SQLITE_OK);
    char* message = nullptr;
    const int status = sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &message);
    INFO((message ? message : ""));
    sqlite3_free(message);
    sqlite3_close(db);
    REQUIRE(status == SQLITE_OK);
}

// The file's bytes hashed (FNV-1a), and the existence of its WAL companions.
std::uint64_t file_hash(const fs::path& file) {
    std::uint64_t hash = 1469598103934665603ull;
    for (const char c : kumite::test::read_text(file)) hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    return hash;
}

// Writer and reader both refuse `store` with a message naming it and containing `reason`; the file is unchanged.
void require_refused(const fs::path& store, const std::string& reason) {
    const std::uint64_t before = file_hash(store);
    const std::uintmax_t size_before = fs::file_size(store);
    auto writer = SessionWriter::open(store, start_of("ann"));
    REQUIRE_FALSE(writer);
    CHECK_THAT(writer.error().message, Catch::Contains(reason) && Catch::Contains(store.string()));
    auto reader = StoreReader::open(store);
    REQUIRE_FALSE(reader);
    CHECK_THAT(reader.error().message, Catch::Contains(reason) && Catch::Contains(store.string()));
    CHECK(fs::file_size(store) == size_before);
    CHECK(file_hash(store) == before);
}

template <class Condition>
bool wait_for(Condition&& condition, double seconds) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < deadline) {
        if (condition()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return condition();
}

} // namespace

TEST_CASE("store: sessions, attacks and user strikes read back as written", "[training]") {
    const fs::path store = kumite::test::make_temp_dir("store") / "new folder" / "training.sqlite";
    const std::int64_t first = write_session(store, "ann", 12, "2026-12-06T04:00:00Z");
    const std::int64_t second = write_session(store, "bob", 4, "2026-12-05T04:00:00Z");
    write_session(store, "ann", 2, "2026-12-07T04:00:00Z");

    auto reader = StoreReader::open(store);
    REQUIRE(reader);
    auto sessions = reader->sessions();
    REQUIRE(sessions);
    REQUIRE(sessions->size() == 3);
    CHECK((*sessions)[0].id == second); // oldest first
    const SessionRow& row = (*sessions)[1];
    CHECK(row.id == first);
    CHECK(row.trainee == "ann");
    CHECK(row.drill == "basics");
    CHECK(row.drill_file == "data/drills/basics.toml");
    CHECK(row.character == "brawler");
    CHECK(row.tracker == "simulate:orbit");
    CHECK(row.started_utc == "2026-12-06T04:00:00Z");
    CHECK(row.duration_s == 72.0);
    CHECK(row.complete);
    CHECK(row.settings_json == R"({"character":"brawler"})");
    CHECK(row.summary_json == R"({"attacks":12})");
    CHECK(row.attacks == 12);
    CHECK(row.user_strikes == 3);

    auto attacks = reader->attacks(first);
    REQUIRE(attacks);
    REQUIRE(attacks->size() == 12);
    for (int i = 0; i < 12; ++i) require_same((*attacks)[i], attack(i));
    CHECK(std::isnan((*attacks)[0].response_time_s)); // NaN: no response
    auto strikes = reader->user_strikes(first);
    REQUIRE(strikes);
    REQUIRE(strikes->size() == 3);
    CHECK(std::isnan((*strikes)[0].peak_speed_mps));
    CHECK((*strikes)[2].peak_speed_mps == 6.5);
    CHECK((*strikes)[1].hand == "left");
    CHECK((*strikes)[1].outcome == "slipped");
    CHECK((*strikes)[1].defended);

    auto trainees = reader->trainees();
    REQUIRE(trainees);
    REQUIRE(trainees->size() == 2);
    CHECK((*trainees)[0].name == "ann");
    CHECK((*trainees)[0].sessions == 2);
    CHECK((*trainees)[0].last_utc == "2026-12-07T04:00:00Z");
    auto of_ann = reader->sessions(std::string("ann"));
    REQUIRE(of_ann);
    CHECK(of_ann->size() == 2);
    auto of_nobody = reader->sessions(std::string("nobody"));
    REQUIRE(of_nobody);
    CHECK(of_nobody->empty());
    auto ann_attacks = reader->trainee_attacks("ann");
    REQUIRE(ann_attacks);
    REQUIRE(ann_attacks->size() == 14);
    CHECK((*ann_attacks)[0].first == first);
    CHECK((*ann_attacks)[11].second.seq == 11);
    CHECK((*ann_attacks)[12].second.seq == 0);
    auto ann_strikes = reader->trainee_user_strikes("ann");
    REQUIRE(ann_strikes);
    CHECK(ann_strikes->size() == 6);
}

TEST_CASE("store: a file that is not a current store is refused and left byte for byte", "[training]") {
    const fs::path dir = kumite::test::make_temp_dir("store-refusals");
    SECTION("garbage") {
        const fs::path store = dir / "garbage.sqlite";
        std::ofstream(store) << std::string(4096, 'x');
        require_refused(store, "not a SQLite database");
    }
    SECTION("shorter than a header") {
        const fs::path store = dir / "short.sqlite";
        std::ofstream(store) << "SQLite format 3";
        require_refused(store, "not a SQLite database");
    }
    SECTION("empty") {
        const fs::path store = dir / "empty.sqlite";
        std::ofstream{store};
        require_refused(store, "empty (0 bytes)");
    }
    SECTION("truncated to half") {
        const fs::path store = dir / "training.sqlite";
        write_session(store, "ann", 400);
        const std::uintmax_t whole = fs::file_size(store);
        fs::resize_file(store, whole / 2);
        require_refused(store, "truncated: the header says " + std::to_string(whole) + " bytes, the file has " + std::to_string(whole / 2));
    }
    SECTION("another application's SQLite database") {
        const fs::path store = dir / "other.sqlite";
        run_sql(store, "PRAGMA application_id = 1234; CREATE TABLE notes(text); INSERT INTO notes VALUES('hello');");
        require_refused(store, "not a kumite training store");
    }
    SECTION("a store of a newer kumite") {
        const fs::path store = dir / "training.sqlite";
        write_session(store, "ann", 3);
        run_sql(store, "PRAGMA user_version = " + std::to_string(store_schema_version() + 1));
        require_refused(store, "made by a newer kumite (schema " + std::to_string(store_schema_version() + 1) + ", this one reads up to " +
                                   std::to_string(store_schema_version()) + ")");
    }
    SECTION("a damaged store") {
        const fs::path store = dir / "training.sqlite";
        write_session(store, "ann", 300);
        // The attacks table's pages overwritten in the middle of the file: the size and header stay right.
        std::fstream file(store, std::ios::in | std::ios::out | std::ios::binary);
        file.seekp(static_cast<std::streamoff>(fs::file_size(store) / 2));
        file << std::string(8192, '\xff');
        file.close();
        const std::uint64_t before = file_hash(store);
        auto writer = SessionWriter::open(store, start_of("ann"));
        REQUIRE_FALSE(writer);
        CHECK_THAT(writer.error().message, Catch::Contains("damaged: ") && Catch::Contains(store.string()));
        CHECK(file_hash(store) == before);
    }
}

TEST_CASE("store: a missing store is not created by a reader", "[training]") {
    const fs::path store = kumite::test::make_temp_dir("store-missing") / "training.sqlite";
    auto reader = StoreReader::open(store);
    REQUIRE_FALSE(reader);
    CHECK_THAT(reader.error().message, Catch::Contains("no training store at " + store.string()));
    CHECK_FALSE(fs::exists(store));
}

TEST_CASE("store: one writer at a time, in this process or another", "[training]") {
    const fs::path store = kumite::test::make_temp_dir("store-lock") / "training.sqlite";
    SECTION("this process") {
        {
            auto first = SessionWriter::open(store, start_of("ann"));
            REQUIRE(first);
            const std::uint64_t before = file_hash(store);
            auto second = SessionWriter::open(store, start_of("bob"));
            REQUIRE_FALSE(second);
            CHECK_THAT(second.error().message, Catch::Contains("in use by another session"));
            CHECK(file_hash(store) == before);
        }
        auto after = SessionWriter::open(store, start_of("bob"));
        REQUIRE(after);
    }
    SECTION("another process") {
        write_session(store, "ann", 1);
        int locked[2], release[2];
        REQUIRE(pipe(locked) == 0);
        REQUIRE(pipe(release) == 0);
        const pid_t child = fork();
        if (child == 0) { // only system calls here: the child of a threaded process
            const int fd = ::open(store.c_str(), O_RDONLY);
            const char ok = fd >= 0 && ::flock(fd, LOCK_EX) == 0 ? 'y' : 'n';
            (void)!::write(locked[1], &ok, 1);
            char ignored;
            (void)!::read(release[0], &ignored, 1);
            _exit(0);
        }
        REQUIRE(child > 0);
        char ok = 0;
        REQUIRE(::read(locked[0], &ok, 1) == 1);
        REQUIRE(ok == 'y');
        auto refused = SessionWriter::open(store, start_of("bob"));
        (void)!::write(release[1], &ok, 1);
        int status = 0;
        waitpid(child, &status, 0);
        for (const int fd : {locked[0], locked[1], release[0], release[1]}) ::close(fd);
        REQUIRE_FALSE(refused);
        CHECK_THAT(refused.error().message, Catch::Contains("in use by another session (pid " + std::to_string(child) + ")"));
        auto after = SessionWriter::open(store, start_of("bob"));
        CHECK(after);
    }
}

TEST_CASE("store: rows are committed while the session runs, and readers read them meanwhile", "[training]") {
    const fs::path store = kumite::test::make_temp_dir("store-live") / "training.sqlite";
    auto writer = SessionWriter::open(store, start_of("ann"), 0.1);
    REQUIRE(writer);
    auto reader = StoreReader::open(store);
    REQUIRE(reader);
    for (int i = 0; i < 20; ++i) (*writer)->add(attack(i));
    (*writer)->set_duration(12.5);
    const auto committed = [&] {
        auto sessions = reader->sessions();
        return sessions && sessions->size() == 1 && (*sessions)[0].attacks == 20 && (*sessions)[0].duration_s == 12.5;
    };
    CHECK(wait_for(committed, 2.0)); // every 0.1 s; well within the bound on a loaded machine
    auto sessions = reader->sessions();
    REQUIRE(sessions);
    CHECK_FALSE((*sessions)[0].complete);
    for (int i = 20; i < 30; ++i) (*writer)->add(attack(i));
    CHECK(wait_for([&] { auto rows = reader->attacks((*writer)->session_id()); return rows && rows->size() == 30; }, 2.0));
    CHECK_FALSE((*writer)->error());
}

TEST_CASE("store: a session not finished stays incomplete with its rows", "[training]") {
    const fs::path store = kumite::test::make_temp_dir("store-unfinished") / "training.sqlite";
    std::int64_t id = 0;
    {
        auto writer = SessionWriter::open(store, start_of("ann"), 60.0); // no periodic commit before the end
        REQUIRE(writer);
        id = (*writer)->session_id();
        for (int i = 0; i < 7; ++i) (*writer)->add(attack(i));
        (*writer)->add(user_strike(0));
        (*writer)->set_duration(31.0);
    }
    auto reader = StoreReader::open(store);
    REQUIRE(reader);
    auto sessions = reader->sessions();
    REQUIRE(sessions);
    REQUIRE(sessions->size() == 1);
    CHECK((*sessions)[0].id == id);
    CHECK_FALSE((*sessions)[0].complete);
    CHECK((*sessions)[0].duration_s == 31.0);
    CHECK((*sessions)[0].summary_json.empty());
    CHECK((*sessions)[0].attacks == 7);
    CHECK((*sessions)[0].user_strikes == 1);
}

TEST_CASE("store: a store of schema 1 migrates forward with its rows", "[training]") {
    REQUIRE(store_schema_version() >= 2);
    const fs::path store = kumite::test::make_temp_dir("store-migrate") / "training.sqlite";
    REQUIRE(store_create_at_version(store, 1));
    run_sql(store,
            "INSERT INTO trainees(id, name, created_utc) VALUES(1, 'ann', '2025-01-01T00:00:00Z');"
            "INSERT INTO sessions(id, trainee_id, drill, drill_file, drill_text, settings_json, character, tracker, started_utc, duration_s, "
            "complete, summary_json) VALUES(1, 1, 'old', 'old.toml', '', '{}', 'brawler', 'xr', '2025-01-01T00:00:00Z', 90, 1, '{}');"
            "INSERT INTO attacks(session_id, seq, t_s, response_time_s, result, counter_landed) VALUES(1, 0, 2.5, NULL, 'hit', -1);"
            "INSERT INTO attacks(session_id, seq, t_s, response_time_s, result, counter_landed) VALUES(1, 1, 4.5, 0.25, 'blocked', 1);");
    {
        auto old_reader = StoreReader::open(store); // schema 1 reads as it is (only indexes came after)
        REQUIRE(old_reader);
        CHECK(old_reader->sessions()->size() == 1);
    }
    write_session(store, "ann", 5);

    sqlite3* db = nullptr;
    REQUIRE(sqlite3_open_v2(store.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK);
    auto version = store_check_identity(db, store);
    Result<std::string> indexes = sqlite_first_text(db, "SELECT group_concat(name) FROM sqlite_master WHERE type = 'index' AND name LIKE '%_by_%'", store);
    sqlite3_close(db);
    REQUIRE(version);
    CHECK(*version == store_schema_version());
    REQUIRE(indexes);
    CHECK_THAT(*indexes, Catch::Contains("attacks_by_session") && Catch::Contains("sessions_by_trainee"));

    auto reader = StoreReader::open(store);
    REQUIRE(reader);
    auto sessions = reader->sessions(std::string("ann"));
    REQUIRE(sessions);
    REQUIRE(sessions->size() == 2);
    CHECK((*sessions)[0].drill == "old");
    CHECK((*sessions)[0].attacks == 2);
    CHECK((*sessions)[1].attacks == 5);
    auto attacks = reader->attacks(1);
    REQUIRE(attacks);
    REQUIRE(attacks->size() == 2);
    CHECK(std::isnan((*attacks)[0].response_time_s));
    CHECK((*attacks)[1].response_time_s == 0.25);
    CHECK((*attacks)[1].result == "blocked");
}
