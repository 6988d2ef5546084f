// `kumite play --tracker capture:FILE.bvh[:DISTANCE[:START_S]]`: a recorded person as the user. The report and the
// events say which capture and where it was placed; every event carries the capture's time; bad specs are usage
// errors, missing files input errors.

#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

using kumite::test::run_command;

TEST_CASE("cli: play against a recorded boxer says which capture, where, and when in it each event came", "[cli][corpus]") {
    const std::filesystem::path boxer = kumite::test::mocap_root() / "cmu14-boxing" / "box-2.bvh";
    if (!std::filesystem::exists(boxer)) return;
    const std::string kumite = (kumite::test::bin_dir() / "kumite").string();
    const std::string db = (kumite::test::source_dir() / "data/golden/golden-v2.kdb").string();
    const std::filesystem::path folder = kumite::test::make_temp_dir("cli-capture");
    const std::string events = (folder / "bout.jsonl").string();
    const auto played = run_command(kumite + " play " + db + " --headless --duration 6 --character brawler --tracker capture:" + boxer.string() +
                                    ":1.4:10 --events " + events + " --json");
    INFO(played.err);
    REQUIRE(played.status == 0);
    const nlohmann::json report = nlohmann::json::parse(played.out);
    REQUIRE(report.contains("tracker_source"));
    const nlohmann::json& source = report["tracker_source"];
    CHECK(source["source"] == "capture");
    CHECK(source["capture"] == boxer.string());
    CHECK(source["distance_m"] == 1.4);
    CHECK(source["start_s"] == 10.0);
    CHECK(source["at_end"] == "loops");
    CHECK(source["frame_rate_hz"].get<double>() == Approx(60.0).epsilon(0.001));
    CHECK(source["mean_head"][2].get<double>() == Approx(1.4));

    std::istringstream lines(kumite::test::read_text(events));
    std::string line;
    REQUIRE(std::getline(lines, line));
    CHECK(nlohmann::json::parse(line)["type"] == "bout_start");
    REQUIRE(std::getline(lines, line));
    const nlohmann::json first = nlohmann::json::parse(line);
    CHECK(first["type"] == "tracker_source");
    CHECK(first["capture"] == boxer.string());
    int later = 0;
    for (; std::getline(lines, line); ++later) {
        const nlohmann::json event = nlohmann::json::parse(line);
        REQUIRE(event.contains("capture_s"));
        CHECK(event["capture_s"].get<double>() == Approx(10.0 + event["t"].get<double>()).margin(1e-6));
    }
    CHECK(later > 0);

    // Orders every 0.5 s, faster than strikes end: they wait, and each ends performed, refused or expired, or is
    // still waiting when the bout ends.
    const std::filesystem::path orders = folder / "orders.txt";
    {
        std::ofstream out(orders);
        for (int k = 0; k < 16; ++k) out << 0.5 + 0.5 * k << (k % 2 ? " kick" : " punch") << "\n";
    }
    const auto busy = run_command(kumite + " play " + db + " --headless --duration 9 --character brawler --aim predicted --tracker capture:" +
                                  boxer.string() + " --commands script:" + orders.string() + " --json");
    REQUIRE(busy.status == 0);
    const nlohmann::json outcomes = nlohmann::json::parse(busy.out)["order_outcomes"];
    INFO(outcomes.dump());
    CHECK(outcomes["queued"].get<int>() > 0);
    CHECK(outcomes["performed"].get<int>() + outcomes["expired"].get<int>() + outcomes["refused"].get<int>() +
              outcomes["waiting_at_end"].get<int>() == 16);

    CHECK(run_command(kumite + " play " + db + " --headless --duration 1 --tracker capture:" + boxer.string() + ":0.01").status == 2);
    const auto missing = run_command(kumite + " play " + db + " --headless --duration 1 --tracker capture:/no/such/boxer.bvh");
    CHECK(missing.status == 1);
    CHECK_THAT(missing.err, Catch::Contains("/no/such/boxer.bvh"));
}
