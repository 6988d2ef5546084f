// The session report (authoring/report) from event lines: its counts equal the events', one timeline mark and one
// top-view mark per strike, nothing referenced outside the page, and bad lines end the reading with a say-where
// line instead of an exception.

#include "session_html.h"
#include "support/html_counts.h"
#include "session_log.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <random>
#include <regex>
#include <sstream>

using kumite::report::SessionLog;
using kumite::test::occurrences;
using kumite::test::summary_count;

namespace {

// A bout of one fighter as play writes it: orders every 2 s alternating hit and miss, a user strike of each
// outcome, a tracker loss, a character switch, the head sampled at 10 Hz.
std::vector<nlohmann::json> bout_lines(int strikes) {
    std::vector<nlohmann::json> lines;
    lines.push_back({{"t", 0.0}, {"type", "bout_start"}, {"fighters", 1}, {"character", "brawler"}, {"aim", "predicted"}, {"defence", true}});
    const char* outcomes[] = {"blocked", "slipped", "hit_by_user", "missed"};
    for (int i = 0; i < strikes; ++i) {
        const double t = 1.0 + 2.0 * i;
        for (double s = t - 1.0; s < t + 0.95; s += 0.1) lines.push_back({{"t", s}, {"type", "track"}, {"head", {0.1 * std::sin(s), 1.6, 1.2 + 0.1 * std::cos(s)}}});
        lines.push_back({{"t", t}, {"type", "order"}, {"fighter", 0}, {"command", "punch"}});
        lines.push_back({{"t", t + 0.05}, {"type", "order_performed"}, {"fighter", 0}, {"waited_s", 0.05}});
        lines.push_back({{"t", t + 0.4},
                         {"type", "strike"},
                         {"fighter", 0},
                         {"command", i % 3 ? "punch" : "kick"},
                         {"kind", "straight"},
                         {"height", "high"},
                         {"result", i % 2 ? "miss" : "hit"},
                         {"target", {0.0, 1.6, 1.2}},
                         {"aimed_point_at_contact", {0.05, 1.6, 1.25}},
                         {"prediction_error_m", 0.07},
                         {"effector_speed_at_contact_mps", 4.0 + i}});
        lines.push_back({{"t", t + 0.6}, {"type", "strike_end"}, {"fighter", 0}, {"overshoot_m", 0.01}, {"joint_limit_violations", 0}});
        lines.push_back({{"t", t + 0.7}, {"type", "user_strike"}, {"fighter", 0}, {"hand", "left"}, {"move", i % 2 ? "slip" : "block"}});
        nlohmann::json end = {{"t", t + 0.9}, {"type", "user_strike_end"}, {"fighter", 0}, {"hand", "left"}, {"outcome", outcomes[i % 4]}};
        // Every other slip and block was of a blow that would have landed (on course), the rest of ones passing wide.
        if (i % 4 == 1) end["unslipped_clearance_m"] = i % 8 == 1 ? -0.02 : 0.05;
        end["approach_s"] = i % 3 == 0 ? 0.25 : 0.1;
        lines.push_back(end);
        if (i % 4 == 0) lines.push_back({{"t", t + 1.1}, {"type", "user_strike_course"}, {"fighter", 0}, {"hand", "left"}, {"on_course", i % 8 == 0}});
    }
    lines.push_back({{"t", 2.0}, {"type", "ignored_order"}, {"fighter", 0}, {"why", "already striking"}});
    std::stable_sort(lines.begin(), lines.end(), [](const nlohmann::json& a, const nlohmann::json& b) { return a["t"].get<double>() < b["t"].get<double>(); });
    const double end = 2.0 * strikes + 1.0;
    lines.push_back({{"t", end - 0.5}, {"type", "character"}, {"fighter", 0}, {"character", "giant"}});
    lines.push_back({{"t", end - 0.4}, {"type", "tracker_lost"}, {"fighter", 0}});
    lines.push_back({{"t", end - 0.2}, {"type", "tracker_back"}, {"fighter", 0}});
    lines.push_back({{"t", end}, {"type", "bout_end"}, {"frames", int(end * 60)}, {"duration_s", end}});
    return lines;
}

std::string text_of(const std::vector<nlohmann::json>& lines) {
    std::string text;
    for (const nlohmann::json& line : lines) text += line.dump() + "\n";
    return text;
}

SessionLog log_of_text(const std::string& text) {
    SessionLog log;
    std::istringstream in(text);
    long long number = 0;
    for (std::string line; std::getline(in, line);) {
        if (!log.add_text(line, ++number)) break;
    }
    return log;
}

} // namespace

TEST_CASE("report: the summary's counts are the events', one mark per strike in the timeline and the top view", "[report]") {
    const int strikes = 12;
    const SessionLog log = log_of_text(text_of(bout_lines(strikes)));
    REQUIRE_FALSE(log.stopped);
    REQUIRE(log.fighters.size() == 1);
    const nlohmann::json play_report = {{"frame_time_us", {{"mean", 50.0}, {"p99", 90.0}, {"max", 400.0}}}, {"missed_frames", 0}};
    const std::string html = kumite::report::session_html(log, &play_report);
    CHECK(summary_count(html, "n-strikes") == strikes);
    CHECK(summary_count(html, "n-hits") == strikes / 2);
    CHECK(summary_count(html, "n-orders") == strikes);
    CHECK(summary_count(html, "n-performed") == strikes);
    CHECK(summary_count(html, "n-refused") == 1);
    CHECK(summary_count(html, "n-user-strikes") == strikes);
    CHECK(summary_count(html, "n-blocked") == strikes / 4);
    CHECK(summary_count(html, "n-landed") == strikes / 4);
    CHECK(summary_count(html, "n-kept-off") == 4); // blocks at 0 and 8, slips at 1 and 9 of blows on course
    CHECK(summary_count(html, "n-warned") == 3);   // of those and the landed 2, 6 and 10: 0, 6 and 9 came on for 0.25 s
    CHECK(summary_count(html, "n-losses") == 1);
    CHECK(occurrences(html, "class=\"tl-strike hit\"") == strikes / 2);
    CHECK(occurrences(html, "class=\"tl-strike miss\"") == strikes / 2);
    CHECK(occurrences(html, "class=\"tv-target ") == strikes);
    CHECK(occurrences(html, "class=\"tv-error\"") == strikes);
    CHECK(occurrences(html, "class=\"tl-order\"") == strikes);
    CHECK(occurrences(html, "class=\"tl-refused\"") == 1);
    CHECK(occurrences(html, "class=\"tl-user-strike\"") == strikes);
    CHECK(occurrences(html, "class=\"tl-defence\"") == strikes);
    CHECK(occurrences(html, "class=\"tl-lost\"") == 1);
    CHECK(occurrences(html, "class=\"tl-character\"") == 1);
    CHECK(occurrences(html, "<section class=\"fighter\"") == 1);
    CHECK(html.find("brawler → giant") != std::string::npos);
    CHECK(html.find("p99 90 µs") != std::string::npos);
    // The medians the histograms write: latency 50 ms, speed of 12 strikes 4..15 m/s -> the 7th smallest, 10.
    CHECK(html.find("<tspan class=\"median\">50</tspan> ms") != std::string::npos);
    CHECK(html.find("<tspan class=\"median\">10</tspan> m/s") != std::string::npos);
    CHECK(html.find("Reading stopped") == std::string::npos);
    CHECK(kumite::report::session_html(log).find("not in the events") != std::string::npos); // without the report
}

TEST_CASE("report: the page references nothing outside itself", "[report]") {
    const std::string html = kumite::report::session_html(log_of_text(text_of(bout_lines(5))), nullptr, "<script>alert(1)</script>.jsonl");
    CHECK(html.find("<script") == std::string::npos); // the source name is escaped, no script of its own
    CHECK(html.find("&lt;script&gt;") != std::string::npos);
    for (const char* outside : {"http:", "https:", "//", "src=", "url(", "@import", "<link", "<img", "<iframe"}) {
        INFO(outside);
        // "//" may only appear inside the doctype-free text: none at all is simplest to check.
        CHECK(html.find(outside) == std::string::npos);
    }
    // Every href points into the page.
    const std::regex href("href=\"([^\"]*)\"");
    for (auto it = std::sregex_iterator(html.begin(), html.end(), href); it != std::sregex_iterator(); ++it) CHECK((*it)[1].str().front() == '#');
    CHECK(html.find("id=\"head-path\"") != std::string::npos);
}

TEST_CASE("report: a cut-off or malformed events file gives what came before and where reading stopped", "[report]") {
    const std::string text = text_of(bout_lines(10));
    SECTION("cut in the middle of a line") {
        const std::size_t cut = text.find("\"type\":\"strike\"", text.size() / 2);
        REQUIRE(cut != std::string::npos);
        const SessionLog log = log_of_text(text.substr(0, cut));
        REQUIRE(log.stopped);
        CHECK_THAT(*log.stopped, Catch::Contains("line ") && Catch::Contains("cut off"));
        const std::string html = kumite::report::session_html(log);
        CHECK(html.find("Reading stopped at line") != std::string::npos);
        const long long before = static_cast<long long>(log.fighters.at(0).strikes.size());
        CHECK(before > 0);
        CHECK(summary_count(html, "n-strikes") == before);
    }
    SECTION("lines that are not events") {
        for (const std::string bad : {"[1,2,3]", "{\"t\":\"soon\",\"type\":\"strike\"}", "{\"t\":1e400,\"type\":\"x\"}", "{\"type\":\"strike\"}",
                                      "{\"t\":5,\"type\":\"strike\",\"fighter\":1000000000}", "{\"t\":5,\"type\":\"strike\",\"fighter\":-1}",
                                      "{\"t\":-0.5,\"type\":\"order\"}", "{\"t\":5,\"type\":7}", "not json at all"}) {
            INFO(bad);
            const std::size_t middle = text.find('\n', text.size() / 2) + 1;
            const SessionLog log = log_of_text(text.substr(0, middle) + bad + "\n" + text.substr(middle));
            REQUIRE(log.stopped);
            const long long line = std::count(text.begin(), text.begin() + std::ptrdiff_t(middle), '\n') + 1;
            CHECK_THAT(*log.stopped, Catch::StartsWith("line " + std::to_string(line) + ":"));
            CHECK_FALSE(kumite::report::session_html(log).empty());
        }
    }
    SECTION("fields of the wrong type or far outside the room are left out, not trusted") {
        const std::string odd = "{\"t\":30,\"type\":\"strike\",\"fighter\":0,\"result\":7,\"target\":[1e300,\"x\",2],\"prediction_error_m\":\"far\","
                                "\"effector_speed_at_contact_mps\":null}\n{\"t\":31,\"type\":\"track\",\"head\":[1,2]}\n"
                                "{\"t\":32,\"type\":\"fighter_position\",\"fighter\":0,\"position\":[1e9,0,0]}\n{\"t\":33,\"type\":\"from_the_future\"}\n";
        const SessionLog log = log_of_text(odd);
        CHECK_FALSE(log.stopped);
        REQUIRE(log.fighters.at(0).strikes.size() == 1);
        CHECK_FALSE(log.fighters.at(0).strikes[0].target);
        CHECK(log.fighters.at(0).positions.empty());
        CHECK(log.head_path.empty());
        CHECK(log.unknown_lines == 1);
        const std::string html = kumite::report::session_html(log);
        CHECK(occurrences(html, "class=\"tl-strike miss\"") == 1);
        CHECK(html.find("without the bout's last line") != std::string::npos);
    }
}

TEST_CASE("report: corrupted bytes anywhere never throw and always give a page", "[report]") {
    const std::string text = text_of(bout_lines(6));
    std::mt19937 random(7);
    for (int round = 0; round < 300; ++round) {
        std::string corrupt = text;
        const int edits = 1 + int(random() % 8);
        for (int e = 0; e < edits; ++e) corrupt[random() % corrupt.size()] = static_cast<char>(random() % 256);
        if (round % 3 == 0) corrupt.resize(random() % corrupt.size());
        SessionLog log;
        std::string html;
        REQUIRE_NOTHROW(log = log_of_text(corrupt));
        REQUIRE_NOTHROW(html = kumite::report::session_html(log));
        CHECK(html.ends_with("</html>\n"));
    }
}

TEST_CASE("report: one section per fighter, the many beyond the first ones in a table", "[report]") {
    std::vector<nlohmann::json> lines = {{{"t", 0.0}, {"type", "bout_start"}, {"fighters", 30}}};
    for (int f = 0; f < 30; ++f) {
        lines.push_back({{"t", 1.0}, {"type", "order"}, {"fighter", f}, {"command", "kick"}});
        lines.push_back({{"t", 1.0}, {"type", "fighter_position"}, {"fighter", f}, {"position", {f * 0.8, 1.0, 0.0}}});
    }
    for (int f = 0; f < 30; ++f) lines.push_back({{"t", 1.5}, {"type", "strike"}, {"fighter", f}, {"result", "hit"}, {"target", {f * 0.8, 1.6, 1.0}}});
    const SessionLog log = log_of_text(text_of(lines));
    REQUIRE(log.fighters.size() == 30);
    const std::string html = kumite::report::session_html(log);
    CHECK(occurrences(html, "<section class=\"fighter\"") == std::size_t(kumite::report::k_detailed_fighters));
    CHECK(occurrences(html, "<tr class=\"fighter-row\">") == 30 - std::size_t(kumite::report::k_detailed_fighters));
    CHECK(summary_count(html, "n-strikes") == 30); // the bout's summary counts every fighter
    CHECK(occurrences(html, "class=\"tv-fighter\"") == std::size_t(kumite::report::k_detailed_fighters));
}

TEST_CASE("report: strikes the user's guard blocked are counted and named", "[report]") {
    std::vector<nlohmann::json> lines = bout_lines(4);
    lines.push_back({{"t", 6.0}, {"type", "strike"}, {"fighter", 0}, {"command", "punch"}, {"kind", "straight"}, {"height", "high"}, {"clip_side", "left"},
                     {"result", "blocked"}, {"blocked_by", "glove_right"}, {"target", {0.0, 1.6, 1.2}}});
    const std::string html = kumite::report::session_html(log_of_text(text_of(lines)), nullptr);
    CHECK(summary_count(html, "n-strikes") == 5);
    CHECK(summary_count(html, "n-hits") == 2);
    CHECK(summary_count(html, "n-blocked-by-user") == 1);
    CHECK(html.find("punch straight high left: blocked by the user") != std::string::npos); // the title escaped
    CHECK(html.find("glove_right") != std::string::npos);
    // Without such strikes the row is not there.
    CHECK(kumite::report::session_html(log_of_text(text_of(bout_lines(4))), nullptr).find("n-blocked-by-user") == std::string::npos);
}

TEST_CASE("report: the user's answers are tabled by attack, with a histogram of response times for each", "[report]") {
    std::vector<nlohmann::json> lines = bout_lines(4);
    auto response = [](double t, const char* command, const char* result, const char* kind, const char* quality, double time_s, bool countered) {
        nlohmann::json line = {{"t", t}, {"type", "user_response"}, {"fighter", 0}, {"command", command}, {"kind", "straight"}, {"result", result},
                               {"response", kind}, {"quality", quality}, {"moved", time_s > -1.0}, {"contact_s", t - 1.6}, {"countered", countered}};
        line["response_time_s"] = time_s > -1.0 ? nlohmann::json(time_s) : nlohmann::json(nullptr);
        if (countered) line["counter_landed"] = true;
        return line;
    };
    lines.push_back(response(3.0, "punch", "miss", "slip", "in_time", 0.20, true));
    lines.push_back(response(5.0, "punch", "hit", "block", "late", 0.30, false));
    lines.push_back(response(7.0, "punch", "blocked", "block", "in_time", -2.0, false)); // a guard held: no move
    lines.push_back(response(9.0, "kick", "miss", "step_back", "in_time", -0.05, false)); // moved before it showed
    const std::string html = kumite::report::session_html(log_of_text(text_of(lines)), nullptr);
    CHECK(occurrences(html, "<tr class=\"attack\">") == 2);
    CHECK(html.find("<th>punch straight</th><td class=\"n blows\">3</td>") != std::string::npos);
    CHECK(html.find("<td class=\"n answered\">2 <span class=\"share\">(67%)</span>") != std::string::npos);
    CHECK(html.find("<td class=\"n median\">0.30 s</td>") != std::string::npos); // of 0.20 and 0.30: the upper middle, as the other figures
    CHECK(html.find("<td class=\"n kind-block\">2 <span") != std::string::npos);
    CHECK(html.find("<td class=\"n countered\">1 (1)</td>") != std::string::npos);
    CHECK(occurrences(html, "class=\"histogram response-time\"") == 2);
    CHECK(html.find("<th>kick straight</th><td class=\"n blows\">1</td><td class=\"n landed\">0</td><td class=\"n answered\">1 <span class=\"share\">(100%)</span></td><td class=\"n anticipated\">1</td>") != std::string::npos);
    // Events from before the answers were measured: no section.
    CHECK(kumite::report::session_html(log_of_text(text_of(bout_lines(4))), nullptr).find("class=\"responses\"") == std::string::npos);
}
