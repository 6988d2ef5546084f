// The progress page (authoring/training/progress_html.h) over a store written by SessionWriter: the medians and
// shares it shows equal the ones of the rows written, the trend has a point a session, the first-versus-last
// comparison of a drill run twice, an incomplete session marked, an unknown trainee refused with the known ones.

#include "progress_html.h"
#include "support/html_counts.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <map>
#include <regex>
#include <thread>

using kumite::Result;
using namespace kumite::training;
using kumite::test::occurrences;

namespace {

struct Blow {
    const char* command;
    const char* kind;
    const char* height;
    double response_time_s; // NaN: no answer
    const char* result;
};

struct Session {
    std::string trainee, drill, started_utc;
    std::vector<Blow> blows;
    std::vector<const char*> user_outcomes; // the person's strikes
    bool finish = true;
};

void write_session(const std::filesystem::path& store, const Session& session) {
    SessionStart start;
    start.trainee = session.trainee;
    start.drill = session.drill;
    start.drill_file = "data/drills/" + session.drill + ".toml";
    start.started_utc = session.started_utc;
    start.tracker = "simulate:cover:0.3";
    Result<std::unique_ptr<SessionWriter>> writer = SessionWriter::open(store, start, 0.01);
    REQUIRE(writer);
    int seq = 0;
    for (const Blow& blow : session.blows) {
        AttackRow row;
        row.seq = seq;
        row.t_s = 2.0 * seq++;
        row.command = blow.command;
        row.kind = blow.kind;
        row.height = blow.height;
        row.result = blow.result;
        row.response_time_s = blow.response_time_s;
        row.response = std::isnan(blow.response_time_s) ? "none" : "slip";
        // In time when answered and not hit: the bout's rule (response_watch.cpp).
        row.quality = std::isnan(blow.response_time_s) ? "none" : std::string(blow.result) == "hit" ? "late" : "in_time";
        (*writer)->add(row);
    }
    seq = 0;
    for (const char* outcome : session.user_outcomes) {
        UserStrikeRow row;
        row.seq = seq;
        row.t_s = 1.0 + seq++;
        row.hand = "left";
        row.outcome = outcome;
        row.defended = std::string(outcome) == "blocked" || std::string(outcome) == "slipped";
        (*writer)->add(row);
    }
    if (session.finish) {
        REQUIRE((*writer)->finish(2.0 * double(seq + 1), "{}"));
    } else {
        // Killed mid-session: what the committing thread stored before stays.
        (*writer)->set_duration(12.5);
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
    }
}

constexpr double no_answer = k_no_value;

// Three sessions of ana (a reaction test, combinations, the reaction test again) and an unfinished one of ben.
std::filesystem::path sample_store() {
    const std::filesystem::path store = kumite::test::make_temp_dir("progress") / "training.sqlite";
    write_session(store, {"ana", "reaction test", "2026-11-02T10:00:00Z",
                          {{"punch", "straight", "high", 0.30, "miss"}, {"kick", "front", "middle", 0.40, "blocked"}, {"punch", "straight", "high", 0.50, "miss"},
                           {"punch", "straight", "high", 0.60, "hit"}, {"punch", "hook", "high", no_answer, "hit"}},
                          {"hit_by_user", "blocked", "missed", "slipped"}});
    write_session(store, {"ana", "combinations", "2026-11-09T10:00:00Z",
                          {{"punch", "straight", "high", 0.20, "miss"}, {"punch", "straight", "high", 0.25, "miss"}, {"kick", "front", "middle", 0.30, "hit"}},
                          {"hit_by_user"}});
    write_session(store, {"ana", "reaction test", "2026-11-30T10:00:00Z",
                          {{"punch", "straight", "high", 0.25, "miss"}, {"kick", "front", "middle", 0.30, "blocked"}, {"punch", "straight", "high", 0.35, "miss"},
                           {"punch", "straight", "high", 0.40, "miss"}, {"punch", "hook", "high", 0.45, "miss"}},
                          {"hit_by_user", "hit_by_user", "blocked", "missed"}});
    write_session(store, {"ben", "reaction test", "2026-12-01T09:00:00Z", {{"punch", "straight", "high", 0.5, "miss"}, {"punch", "straight", "high", 0.7, "miss"}}, {}, false});
    return store;
}

// Every value of `attribute` in the text, in order.
std::vector<double> attribute_values(const std::string& text, const std::string& attribute) {
    std::vector<double> values;
    const std::regex pattern(attribute + "=\"([-0-9.naninf]+)\"");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), pattern); it != std::sregex_iterator(); ++it) values.push_back(std::stod((*it)[1]));
    return values;
}

// The element with `id` up to its closing tag `end`.
std::string part_with_id(const std::string& html, const std::string& id, const std::string& end) {
    const std::size_t from = html.find("id=\"" + id + "\"");
    REQUIRE(from != std::string::npos);
    return html.substr(from, html.find(end, from) - from);
}

} // namespace

TEST_CASE("progress: quartiles interpolate between order statistics as numpy does", "[training]") {
    const TimeSpread spread = time_spread({0.4, 0.1, 0.3, 0.2, no_answer});
    CHECK(spread.n == 4);
    CHECK(spread.median_s == Approx(0.25));
    CHECK(spread.p25_s == Approx(0.175));
    CHECK(spread.p75_s == Approx(0.325));
    const TimeSpread none = time_spread({});
    CHECK(none.n == 0);
    CHECK(std::isnan(none.median_s));
}

TEST_CASE("progress: the page's medians, shares and trend points are the sessions' own", "[training]") {
    const std::filesystem::path store_path = sample_store();
    Result<StoreReader> store = StoreReader::open(store_path);
    REQUIRE(store);
    Result<std::string> page = progress_html(*store, "ana");
    REQUIRE(page);
    const std::string& html = *page;
    CHECK(html.find("<span id=\"trainee\">ana</span>") != std::string::npos);
    CHECK(html.find("<span id=\"sessions-count\">3</span>") != std::string::npos);
    CHECK(html.find("<span id=\"first-day\">2026-11-02</span>") != std::string::npos);
    CHECK(html.find("<span id=\"last-day\">2026-11-30</span>") != std::string::npos);

    // The sessions' table: the medians of the answers (the unanswered blow left out), oldest first.
    const std::string table = part_with_id(html, "sessions", "</table>");
    CHECK(occurrences(table, "<tr class=\"session") == 3);
    const std::vector<double> medians = attribute_values(table, "data-median-s");
    REQUIRE(medians.size() == 3);
    CHECK(medians[0] == Approx(0.45));
    CHECK(medians[1] == Approx(0.25));
    CHECK(medians[2] == Approx(0.35));
    CHECK(table.find("<td class=\"n spread\">375–525</td>") != std::string::npos);
    CHECK(table.find("<td class=\"n in-time\">60%</td>") != std::string::npos); // 3 of 5 answered and not hit
    CHECK(table.find("<td class=\"n user-landed\">25%</td>") != std::string::npos);
    CHECK(table.find("<td class=\"n user-defended\">50%</td>") != std::string::npos);
    CHECK(table.find("incomplete") == std::string::npos);

    // The trend: one point a session carrying the same medians, and quartiles around them.
    const std::string trend = part_with_id(html, "trend-response-time", "</svg>");
    CHECK(occurrences(trend, "class=\"median-point\"") == 3);
    CHECK(attribute_values(trend, "data-median-s") == medians);
    const std::vector<double> p25 = attribute_values(trend, "data-p25-s"), p75 = attribute_values(trend, "data-p75-s");
    for (std::size_t i = 0; i < 3; ++i) CHECK((p25[i] <= medians[i] && medians[i] <= p75[i]));
    CHECK(html.find("aria-label=\"Response time, all attacks\"") != std::string::npos);

    // By attack: the punch straight high has its own chart; its median in the first session is that of 0.3, 0.5, 0.6.
    const std::string punch = part_with_id(html.substr(html.find("id=\"trend-by-attack\"")), "trend-by-attack", "</svg>");
    CHECK(punch.find("data-attack=\"punch straight high\"") != std::string::npos);
    CHECK(attribute_values(punch, "data-median-s").front() == Approx(0.5));

    // Quality shares stack to 1 a session.
    const std::string quality = part_with_id(html, "trend-quality", "</svg>");
    std::map<std::string, double> stacked;
    const std::regex layer("data-session-id=\"([0-9]+)\" data-share=\"([0-9.]+)\"");
    for (auto it = std::sregex_iterator(quality.begin(), quality.end(), layer); it != std::sregex_iterator(); ++it) stacked[(*it)[1]] += std::stod((*it)[2]);
    REQUIRE(stacked.size() == 3);
    for (const auto& [session, total] : stacked) CHECK(total == Approx(1.0));

    // The reaction test ran twice: first against last, 100 ms faster; combinations ran once and are not compared.
    const std::string comparisons = part_with_id(html, "comparisons", "</table>");
    CHECK(occurrences(comparisons, "<tr class=\"comparison") == 1);
    CHECK(comparisons.find("data-drill=\"reaction test\"") != std::string::npos);
    CHECK(comparisons.find("reaction-test") != std::string::npos);
    CHECK(attribute_values(comparisons, "data-change").front() == Approx(-0.1));
    CHECK(comparisons.find("<td class=\"n in-time-last\">100%</td>") != std::string::npos); // was 60%

    // Self-contained: nothing fetched, no script.
    CHECK(html.find("<script") == std::string::npos);
    CHECK(html.find("http://") == std::string::npos);
    CHECK(html.find("https://") == std::string::npos);
    CHECK(html.find(" src=") == std::string::npos);
}

TEST_CASE("progress: a session that did not end is marked incomplete with the rows stored before", "[training]") {
    Result<StoreReader> store = StoreReader::open(sample_store());
    REQUIRE(store);
    Result<std::vector<SessionProgress>> sessions = session_progress(*store, "ben");
    REQUIRE(sessions);
    REQUIRE(sessions->size() == 1);
    CHECK_FALSE(sessions->front().session.complete);
    CHECK(sessions->front().response_time.median_s == Approx(0.6));
    Result<std::string> page = progress_html(*store, "ben");
    REQUIRE(page);
    CHECK(page->find("<tr class=\"session incomplete\"") != std::string::npos);
    CHECK(page->find("<span class=\"tag\">incomplete</span>") != std::string::npos);
    CHECK(page->find("1 did not end") != std::string::npos);
    CHECK(part_with_id(*page, "trend-response-time", "</svg>").find("fill=\"#ffffff\"") != std::string::npos); // hollow point
    CHECK(page->find("No drill has been run twice yet") != std::string::npos);
}

TEST_CASE("progress: an unknown trainee is refused with the trainees the store has", "[training]") {
    Result<StoreReader> store = StoreReader::open(sample_store());
    REQUIRE(store);
    Result<std::string> page = progress_html(*store, "zed");
    REQUIRE_FALSE(page);
    CHECK(page.error().message.find("\"zed\"") != std::string::npos);
    CHECK(page.error().message.find("ana, ben") != std::string::npos);
}
