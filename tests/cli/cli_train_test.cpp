// kumite train: a drill's parts run in turn at their difficulties (drill_part lines, the report's drill), its attacks
// at their moments, and the session stored: listed by `kumite sessions` (running while it is written), its attacks in
// the part they started in; a malformed drill refused with its line before anything (no store made); --no-store stores
// nothing.

#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

using kumite::test::run_command;

namespace {

const std::string k_drill = R"(name = "two parts"
[[part]]
name = "jabs"
attacks = ["punch", "kick"]
order = "in turn"
cadence_s = 2.5
count = 4
difficulty = "beginner"

[[part]]
name = "sparring"
free_sparring = true
duration_s = 8
difficulty = "expert"
)";

std::filesystem::path write_drill(const std::filesystem::path& folder, const std::string& name, const std::string& text) {
    const std::filesystem::path path = folder / name;
    std::ofstream(path) << text;
    return path;
}

std::string kumite_exe() { return (kumite::test::bin_dir() / "kumite").string(); }
std::string golden() { return (kumite::test::source_dir() / "data/golden/golden-v2.kdb").string(); }

std::vector<nlohmann::json> event_lines(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::vector<nlohmann::json> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(nlohmann::json::parse(line));
    return lines;
}

} // namespace

TEST_CASE("cli: train runs a drill's parts at their levels and stores the session", "[cli][train]") {
    const std::filesystem::path folder = kumite::test::make_temp_dir("cli_train");
    const std::filesystem::path drill = write_drill(folder, "drill.toml", k_drill), store = folder / "store.sqlite";
    const auto trained = run_command(kumite_exe() + " train " + golden() + " --headless --trainee 'Ada L' --drill " + drill.string() + " --store " + store.string() +
                                     " --tracker simulate:cover:0.25 --events " + (folder / "e.jsonl").string() + " --report " + (folder / "r.json").string());
    INFO(trained.err);
    REQUIRE(trained.status == 0);
    // The parts in turn: 4 attacks 2.5 s apart ending 3 s after the last (13 s), then 8 s of free sparring.
    std::ifstream report_in(folder / "r.json");
    const nlohmann::json report = nlohmann::json::parse(report_in);
    REQUIRE(report.at("drill").at("parts").size() == 2);
    CHECK(report.at("drill").at("parts")[0].at("end_s").get<double>() == Approx(13.0));
    CHECK(report.at("drill").at("duration_s").get<double>() == Approx(21.0));
    CHECK(report.at("frames").get<long long>() >= 21 * 60);
    CHECK(report.at("frames").get<long long>() <= 22 * 60 + 1);
    std::vector<nlohmann::json> parts, orders;
    for (const nlohmann::json& line : event_lines(folder / "e.jsonl")) {
        if (line.at("type") == "drill_part") parts.push_back(line);
        if (line.at("type") == "order" && !line.value("own", false)) orders.push_back(line);
    }
    REQUIRE(parts.size() == 2);
    CHECK(parts[0].at("difficulty") == "beginner");
    CHECK(parts[1].at("difficulty") == "expert");
    CHECK(parts[1].at("t").get<double>() == Approx(13.0).margin(0.02));
    REQUIRE(orders.size() == 4); // punch, kick in turn, at 2.5, 5, 7.5 and 10 s
    for (int k = 0; k < 4; ++k) {
        CHECK(orders[std::size_t(k)].at("t").get<double>() == Approx(2.5 * (k + 1)).margin(0.02));
        CHECK(orders[std::size_t(k)].at("command") == (k % 2 == 0 ? "punch" : "kick"));
    }

    // Stored: one complete session of Ada L, listed with its attacks.
    const auto listed = run_command(kumite_exe() + " sessions --store " + store.string() + " --json");
    INFO(listed.err);
    REQUIRE(listed.status == 0);
    const nlohmann::json sessions = nlohmann::json::parse(listed.out);
    REQUIRE(sessions.at("sessions").size() == 1);
    const nlohmann::json& session = sessions.at("sessions")[0];
    CHECK(session.at("trainee") == "Ada L");
    CHECK(session.at("drill") == "two parts");
    CHECK(session.at("complete").get<bool>());
    CHECK(session.at("attacks").get<int>() >= 4);

    // A second session goes beside the first.
    REQUIRE(run_command(kumite_exe() + " train " + golden() + " --headless --trainee 'Ada L' --drill " + drill.string() + " --store " + store.string() +
                        " --tracker simulate:slip:0.3").status == 0);
    const auto again = run_command(kumite_exe() + " sessions --store " + store.string());
    CHECK(again.status == 0);
    CHECK(std::count(again.out.begin(), again.out.end(), '\n') >= 2);
}

TEST_CASE("cli: train refuses a malformed drill with its line before anything starts, and --no-store stores nothing", "[cli][train]") {
    const std::filesystem::path folder = kumite::test::make_temp_dir("cli_train_bad");
    const std::filesystem::path store = folder / "store.sqlite";
    std::string bad = k_drill;
    bad.replace(bad.find("\"kick\""), 6, "\"kick sideways\"");
    const std::filesystem::path drill = write_drill(folder, "bad.toml", bad);
    const auto refused = run_command(kumite_exe() + " train " + golden() + " --headless --trainee x --drill " + drill.string() + " --store " + store.string());
    INFO(refused.err);
    CHECK(refused.status == 1);
    CHECK(refused.err.find(drill.string() + ":4: 'kick sideways'") != std::string::npos);
    CHECK(!std::filesystem::exists(store));

    const std::filesystem::path level = write_drill(folder, "level.toml", std::string(k_drill).replace(k_drill.find("\"expert\""), 8, "\"hardest\""));
    const auto unknown_level = run_command(kumite_exe() + " train " + golden() + " --headless --trainee x --drill " + level.string() + " --store " + store.string());
    INFO(unknown_level.err);
    CHECK(unknown_level.status == 1);
    CHECK(unknown_level.err.find(level.string() + ":14: difficulty takes") != std::string::npos);

    const std::filesystem::path good = write_drill(folder, "good.toml", k_drill);
    const auto unstored = run_command(kumite_exe() + " train " + golden() + " --headless --trainee x --no-store --drill " + good.string());
    CHECK(unstored.status == 0);
    CHECK(!std::filesystem::exists(store));
    CHECK(run_command(kumite_exe() + " train --trainee x").status == 2);
}

TEST_CASE("cli: sessions marks the session being written as running, and as complete once it ended", "[cli][train]") {
    const std::filesystem::path folder = kumite::test::make_temp_dir("cli_train_running");
    const std::filesystem::path drill = write_drill(folder, "drill.toml", k_drill), store = folder / "store.sqlite";
    // A drill on the wall clock, in the background, for 4 s.
    run_command("(" + kumite_exe() + " train " + golden() + " --headless --realtime --duration 4 --trainee r --drill " + drill.string() + " --store " +
                store.string() + " --tracker simulate:still >/dev/null 2>&1 &)");
    nlohmann::json seen;
    for (int attempt = 0; attempt < 60 && seen.is_null(); ++attempt) {
        const auto listed = run_command(kumite_exe() + " sessions --store " + store.string() + " --json");
        if (listed.status == 0) {
            const nlohmann::json document = nlohmann::json::parse(listed.out);
            if (!document.at("sessions").empty()) seen = document.at("sessions")[0];
        }
        if (seen.is_null()) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    REQUIRE(!seen.is_null());
    CHECK(seen.at("running").get<bool>());
    CHECK_FALSE(seen.at("complete").get<bool>());
    nlohmann::json ended;
    for (int attempt = 0; attempt < 200; ++attempt) { // up to 10 s
        ended = nlohmann::json::parse(run_command(kumite_exe() + " sessions --store " + store.string() + " --json").out).at("sessions")[0];
        if (ended.at("complete").get<bool>()) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    CHECK(ended.at("complete").get<bool>());
    CHECK_FALSE(ended.at("running").get<bool>());
}
