// The fighter's own attacks (kumite play --spar): they come at the difficulty's tempo without any order, the same
// for the same seed, none without --spar; the difficulty's tempo and share of combinations are in the report.

#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <fstream>

using kumite::test::run_command;

namespace {

struct Played {
    nlohmann::json report;
    std::string events;
};

Played play(const std::string& flags, const std::string& name) {
    const std::filesystem::path folder = kumite::test::make_temp_dir("cli_play_attacks_" + name);
    const std::string golden = (kumite::test::source_dir() / "data/golden/golden-v2.kdb").string();
    const std::string report = (folder / "bout.json").string(), events = (folder / "bout.jsonl").string();
    const auto played = run_command((kumite::test::bin_dir() / "kumite").string() + " play " + golden + " --headless --duration 40 " + flags +
                                    " --report " + report + " --events " + events);
    REQUIRE(played.status == 0);
    std::ifstream report_in(report), events_in(events);
    Played out;
    out.report = nlohmann::json::parse(report_in);
    out.events.assign(std::istreambuf_iterator<char>(events_in), {});
    return out;
}

} // namespace

TEST_CASE("cli: play --spar attacks on its own at the difficulty's tempo, the same for the same seed", "[cli]") {
    const Played sparring = play("--tracker simulate:still --spar --seed 3", "seed3");
    const Played again = play("--tracker simulate:still --spar --seed 3", "seed3_again");
    const Played other_seed = play("--tracker simulate:still --spar --seed 4", "seed4");
    const Played ordered_only = play("--tracker simulate:still --seed 3", "no_spar");
    // Every 2 s on average (0.6-1.4 of it) over 40 s, less the time the fighter is busy striking: 8 to 33 attacks.
    const long long own = sparring.report.at("own_attacks").get<long long>();
    INFO(own << " own attacks");
    CHECK(own >= 8);
    CHECK(own <= 33);
    CHECK(sparring.report.at("strikes").get<long long>() >= own - 2);
    CHECK(sparring.events.find("\"own\":true") != std::string::npos);
    CHECK(again.events == sparring.events);
    CHECK(other_seed.events != sparring.events);
    CHECK(ordered_only.report.at("own_attacks").get<long long>() == 0);
    CHECK(ordered_only.report.at("strikes").get<long long>() == 0);
    CHECK(sparring.report.at("settings").at("attacks.on_its_own").get<bool>());
    CHECK(sparring.report.at("settings").at("attacks.tempo_s").get<double>() == 2.0);
}

TEST_CASE("cli: play --difficulty sets the fighter's tempo and combinations, and a beginner attacks less often", "[cli]") {
    const Played beginner = play("--tracker simulate:still --spar --difficulty beginner", "beginner");
    const Played expert = play("--tracker simulate:still --spar --difficulty expert", "expert");
    CHECK(beginner.report.at("difficulty") == "beginner");
    CHECK(beginner.report.at("settings").at("attacks.tempo_s").get<double>() == 4.0);
    CHECK(beginner.report.at("settings").at("attacks.combination_share").get<double>() == 0.0);
    CHECK(expert.report.at("settings").at("attacks.tempo_s").get<double>() == 2.0);
    CHECK(beginner.report.at("own_attacks").get<long long>() < expert.report.at("own_attacks").get<long long>());
    // A setting changed after the level: the report says the difficulty is custom.
    const Played custom = play("--tracker simulate:still --difficulty beginner --set attacks.tempo_s=3", "custom");
    CHECK(custom.report.at("difficulty") == "custom");
}
