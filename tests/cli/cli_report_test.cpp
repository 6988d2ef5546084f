// `kumite report EVENTS.jsonl -o OUT.html` and `kumite play --html`: the page's counts equal the events a real
// bout wrote (against a recorded boxer), a cut-off events file still gives a page and a warning saying where.

#include "support/test_paths.h"
#include "support/html_counts.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

using kumite::test::read_text;
using kumite::test::occurrences;
using kumite::test::run_command;
using kumite::test::summary_count;

TEST_CASE("cli: report and play --html draw the bout's events, counts equal to the events", "[cli][corpus]") {
    const std::filesystem::path boxer = kumite::test::mocap_root() / "cmu14-boxing" / "box-1.bvh";
    if (!std::filesystem::exists(boxer)) return;
    const std::string kumite = (kumite::test::bin_dir() / "kumite").string();
    const std::string db = (kumite::test::source_dir() / "data/golden/golden-v2.kdb").string();
    const std::filesystem::path folder = kumite::test::make_temp_dir("cli-report");
    {
        std::ofstream script(folder / "orders.txt");
        for (int i = 0; i < 14; ++i) script << 1.0 + 1.5 * i << (i % 2 ? " kick\n" : " punch\n");
        script << "9.5 character giant\n";
    }
    const auto played = run_command(kumite + " play " + db + " --headless --duration 24 --aim predicted --tracker capture:" + boxer.string() +
                                    " --commands script:" + (folder / "orders.txt").string() + " --events " + (folder / "bout.jsonl").string() +
                                    " --report " + (folder / "bout.json").string() + " --html " + (folder / "play.html").string());
    INFO(played.err);
    REQUIRE(played.status == 0);
    const auto drawn = run_command(kumite + " report " + (folder / "bout.jsonl").string() + " --report " + (folder / "bout.json").string() + " -o " +
                                   (folder / "report.html").string() + " --json");
    INFO(drawn.err);
    REQUIRE(drawn.status == 0);
    CHECK(nlohmann::json::parse(drawn.out)["complete"] == true);

    // What the events say.
    std::map<std::string, long long> types, outcomes, arm_speeds;
    std::map<std::string, std::map<std::string, long long>> outcomes_by_state; // the fighter's state as its events say
    std::string state = "rest";
    std::map<std::string, double> fastest_arm;
    double fastest_block_wrist = 0.0, fastest_block_elbow = 0.0;
    long long hits = 0, targets = 0;
    std::istringstream lines(read_text(folder / "bout.jsonl"));
    for (std::string line; std::getline(lines, line);) {
        const nlohmann::json event = nlohmann::json::parse(line);
        ++types[event["type"].get<std::string>()];
        if (event["type"] == "state") state = event["state"].get<std::string>();
        if (event["type"] == "user_strike_end") ++outcomes_by_state[state][event["outcome"].get<std::string>()];
        if (event["type"] == "strike") hits += event["result"] == "hit", targets += event.contains("target");
        if (event["type"] == "user_strike_end") ++outcomes[event["outcome"].get<std::string>()];
        if (event["type"] == "user_strike_end" && event.contains("arm_from_shoulder_mps")) {
            ++arm_speeds[event["move"].get<std::string>()];
            fastest_arm[event["move"].get<std::string>()] = std::max(fastest_arm[event["move"].get<std::string>()], event["arm_from_shoulder_mps"].get<double>());
        }
        if (event["type"] == "user_strike_end" && event.contains("wrist_mps")) {
            fastest_block_wrist = std::max(fastest_block_wrist, event["wrist_mps"].get<double>());
            fastest_block_elbow = std::max(fastest_block_elbow, event["elbow_mps"].get<double>());
        }
    }
    const nlohmann::json report = nlohmann::json::parse(read_text(folder / "bout.json"));
    REQUIRE(types["strike"] >= 5);
    CHECK(types["bout_start"] == 1);
    CHECK(types["bout_end"] == 1);
    CHECK(types["track"] >= 200); // 10 a second
    CHECK(types["strike"] == report["strikes"].get<long long>());
    // The blocks' arm speeds relative to the shoulder, per block as the events give them.
    const nlohmann::json& speeds = report["user_strikes"]["arm_from_shoulder_mps"];
    CHECK(arm_speeds["synthesized"] > 0);
    CHECK(speeds["synthesized"]["count"].get<long long>() == arm_speeds["synthesized"]);
    CHECK(speeds["synthesized"]["max"].get<double>() == Approx(fastest_arm["synthesized"]));
    CHECK(speeds["block_clip"]["count"].get<long long>() == arm_speeds["block_clip"]);
    CHECK(report["user_strikes"]["block_clip_speed_ratio"]["count"].get<long long>() == arm_speeds["block_clip"]);
    // The instruments agree: a block's wrist and elbow (world) are what the motion meter measures on the frames of a
    // block, so no block event is faster than the meter's fastest block frame, and the fastest block is that frame.
    const nlohmann::json& block_motion = report["motion"]["by_move"]["block"];
    CHECK(fastest_block_wrist > 0.0);
    CHECK(fastest_block_wrist <= block_motion["wrist_mps"].get<double>() + 1e-9);
    CHECK(fastest_block_elbow <= block_motion["elbow_mps"].get<double>() + 1e-9);
    CHECK(report["user_strikes"]["blocking_wrist_mps"]["max"].get<double>() == Approx(fastest_block_wrist));
    CHECK(report["user_strikes"]["blocking_elbow_mps"]["max"].get<double>() == Approx(fastest_block_elbow));

    // The user's strikes by what the fighter was doing when each ended: as the events say, summing to the outcomes;
    // this bout (a boxer shadow boxing, orders every 1.5 s) has blows ending while it strikes and while it does not.
    {
        const nlohmann::json& by_state = report["user_strikes"]["by_fighter_state"];
        std::map<std::string, long long> summed;
        long long while_striking = 0, otherwise = 0;
        for (const auto& [name, entry] : by_state.items()) {
            for (const auto& [outcome, count] : entry.items()) {
                INFO(name << " " << outcome);
                CHECK(count.get<long long>() == outcomes_by_state[name][outcome]);
                summed[outcome] += count.get<long long>();
                (name == "strike" ? while_striking : otherwise) += count.get<long long>();
            }
        }
        for (const char* outcome : {"blocked", "slipped", "hit_by_user", "missed"}) CHECK(summed[outcome] == outcomes[outcome]);
        CHECK(while_striking > 0);
        CHECK(otherwise > 0);
    }

    // The motion: frames by move kind summing to the bout's, the strikes' speeds at contact by kind
    // equal to the events', the same object in the report and the bout_end line, drawn on both pages.
    const nlohmann::json& motion = report["motion"];
    long long motion_frames = 0;
    for (const auto& [move, entry] : motion["by_move"].items()) motion_frames += entry["frames"].get<long long>();
    CHECK(motion_frames == report["frames"].get<long long>());
    CHECK(motion["by_move"]["punch"]["library"]["wrist_mps"].get<double>() > 3.0);
    long long contact_count = 0;
    for (const auto& [kind, entry] : motion["speed_at_contact_by_kind_mps"].items()) contact_count += entry["count"].get<long long>();
    CHECK(contact_count == types["strike"]);
    CHECK(motion["distance_between_strikes"]["frames"].get<long long>() > 0);
    {
        std::istringstream all(read_text(folder / "bout.jsonl"));
        std::string line, last;
        while (std::getline(all, line)) last = line;
        CHECK(nlohmann::json::parse(last)["motion"] == motion);
    }

    for (const char* page : {"play.html", "report.html"}) {
        INFO(page);
        const std::string html = read_text(folder / page);
        CHECK(html.find("<table class=\"motion\">") != std::string::npos);
        CHECK(html.find("<tr class=\"move-punch\">") != std::string::npos);
        CHECK(summary_count(html, "n-strikes") == types["strike"]);
        // The bout's blocks as its bout_start says: synthesized here (defence.captured_blocks false).
        CHECK(html.find("<th>blocks</th><td class=\"n blocks\">synthesized</td>") != std::string::npos);
        CHECK(summary_count(html, "n-hits") == hits);
        CHECK(summary_count(html, "n-orders") == report["orders"].get<long long>());
        CHECK(summary_count(html, "n-performed") == types["order_performed"]);
        CHECK(summary_count(html, "n-refused") == types["ignored_order"]);
        CHECK(summary_count(html, "n-expired") == types["order_expired"]);
        CHECK(summary_count(html, "n-user-strikes") == report["user_strikes"]["seen"].get<long long>() + (types["user_strike_end"] - types["user_strike"]));
        CHECK(summary_count(html, "n-blocked") == outcomes["blocked"]);
        CHECK(summary_count(html, "n-slipped") == outcomes["slipped"]);
        CHECK(summary_count(html, "n-landed") == outcomes["hit_by_user"]);
        // Blocks and slips of blows that would have landed, as the report counts them.
        CHECK(summary_count(html, "n-kept-off") ==
              report["user_strikes"]["blocked_on_course"].get<long long>() + report["user_strikes"]["slipped_on_course"].get<long long>());
        // Every strike that landed is answered by a hit reaction (the last may land as the bout ends).
        CHECK(summary_count(html, "n-hit-reactions") == types["hit_reaction"]);
        CHECK(summary_count(html, "n-reaction-blows") == report["hit_reactions"]["blows_answered"].get<long long>());
        CHECK(summary_count(html, "n-reaction-blows") >= outcomes["hit_by_user"] - 1);
        CHECK(occurrences(html, "class=\"tl-strike ") == std::size_t(types["strike"]));
        CHECK(occurrences(html, "class=\"tv-target ") == std::size_t(targets));
        CHECK(occurrences(html, "class=\"tl-character\"") == std::size_t(types["character"]));
        CHECK(html.find("box-1.bvh") != std::string::npos);
        CHECK(html.find("<script") == std::string::npos);
        CHECK(html.find("http") == std::string::npos);
    }

    // Cut off in the middle of a line: the page of what came before, a warning that says where.
    const std::string text = read_text(folder / "bout.jsonl");
    const std::size_t cut = text.find("\"type\":\"strike\"", text.size() / 2);
    REQUIRE(cut != std::string::npos);
    {
        std::ofstream out(folder / "cut.jsonl", std::ios::binary);
        out << text.substr(0, cut);
    }
    const long long cut_line = std::count(text.begin(), text.begin() + std::ptrdiff_t(cut), '\n') + 1;
    const auto partial = run_command(kumite + " report " + (folder / "cut.jsonl").string() + " -o " + (folder / "cut.html").string());
    CHECK(partial.status == 0);
    CHECK_THAT(partial.err, Catch::Contains((folder / "cut.jsonl").string() + ":" + std::to_string(cut_line) + ":"));
    const std::string cut_html = read_text(folder / "cut.html");
    CHECK(cut_html.find("Reading stopped at") != std::string::npos);
    CHECK(summary_count(cut_html, "n-strikes") < types["strike"]);

    // Several fighters: a section each, every strike of each drawn (their events interleave, and an order's end is
    // stamped with the order's time: not in time order, and read to the end).
    const auto crowd = run_command(kumite + " play " + db + " --headless --duration 12 --fighters 3 --tracker simulate:punch --commands script:" +
                                   (folder / "orders.txt").string() + " --report " + (folder / "crowd.json").string() + " --html " +
                                   (folder / "crowd.html").string());
    REQUIRE(crowd.status == 0);
    const std::string crowd_html = read_text(folder / "crowd.html");
    const nlohmann::json crowd_report = nlohmann::json::parse(read_text(folder / "crowd.json"));
    CHECK(crowd_html.find("Reading stopped") == std::string::npos);
    CHECK(occurrences(crowd_html, "<section class=\"fighter\"") == 3);
    CHECK(summary_count(crowd_html, "n-strikes") == crowd_report["strikes"].get<long long>());
    CHECK(occurrences(crowd_html, "class=\"tl-strike ") == crowd_report["strikes"].get<std::size_t>());

    // Usage and input errors; nothing written.
    CHECK(run_command(kumite + " report " + (folder / "bout.jsonl").string()).status == 2);
    CHECK(run_command(kumite + " report " + (folder / "none.jsonl").string() + " -o " + (folder / "none.html").string()).status == 1);
    CHECK(run_command(kumite + " report " + (folder / "bout.jsonl").string() + " --report " + (folder / "bout.jsonl").string() + " -o " +
                      (folder / "bad.html").string()).status == 1);
    CHECK_FALSE(std::filesystem::exists(folder / "none.html"));
    CHECK_FALSE(std::filesystem::exists(folder / "bad.html"));
    CHECK(run_command(kumite + " play " + db + " --headless --duration 1 --html /no/such/folder/page.html").status == 1);
}
