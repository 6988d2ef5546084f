// What kumite play prints at the end of a bout without --json: a summary of a few lines that agrees with the report
// and names the files written.

#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>

using kumite::test::run_command;

TEST_CASE("cli: play ends on a short summary that agrees with its report and says where the files are", "[cli]") {
    const std::filesystem::path folder = kumite::test::make_temp_dir("cli_play_summary");
    const std::string golden = (kumite::test::source_dir() / "data/golden/golden-v2.kdb").string();
    const std::string report_path = (folder / "bout.json").string(), events_path = (folder / "bout.jsonl").string();
    const auto played = run_command((kumite::test::bin_dir() / "kumite").string() + " play " + golden +
                                    " --headless --duration 12 --tracker simulate:punch --commands script:" +
                                    (kumite::test::source_dir() / "data/bouts/demo.txt").string() + " --report " + report_path +
                                    " --events " + events_path);
    REQUIRE(played.status == 0);
    CHECK(std::count(played.out.begin(), played.out.end(), '\n') <= 30);
    std::ifstream in(report_path);
    const nlohmann::json report = nlohmann::json::parse(in);
    REQUIRE(report.at("strikes").get<long long>() > 0);
    CHECK_THAT(played.out, Catch::Contains("strikes      " + std::to_string(report.at("strikes").get<long long>()) + ": " +
                                           std::to_string(report.at("hits").get<long long>()) + " hits"));
    CHECK_THAT(played.out, Catch::Contains("blocked"));
    CHECK_THAT(played.out, Catch::Contains("  report       " + report_path + "\n"));
    CHECK_THAT(played.out, Catch::Contains("  events       " + events_path + "\n"));
    // The settings the bout ran with are in its report.
    CHECK(report.at("settings").at("strike_follow_s").get<double>() == 0.15);
    CHECK(report.at("settings").at("defence.enabled").get<bool>());
}
