// A trainee's progress (progress_html.h): each session's numbers from the store's rows, then the page: the sessions'
// table, the trends drawn session by session, and first-versus-last comparisons of the drills run again.

#include "progress_html.h"

#include "svg_plot.h"

#include <algorithm>
#include <cmath>

namespace kumite::training {

using report::escape_html;
using report::fixed;
using report::px;
namespace colour = report::colour;

TimeSpread time_spread(std::vector<double> times_s) {
    times_s.erase(std::remove_if(times_s.begin(), times_s.end(), [](double t) { return !std::isfinite(t); }), times_s.end());
    if (times_s.empty()) return {};
    std::sort(times_s.begin(), times_s.end());
    // Quartiles between order statistics, as numpy and pandas compute them (report::median takes the upper middle
    // value instead, which would disagree with a trainer's own analysis of the same rows).
    const auto at = [&](double q) {
        const double position = q * double(times_s.size() - 1);
        const std::size_t below = static_cast<std::size_t>(std::floor(position));
        if (below + 1 >= times_s.size()) return times_s.back();
        return times_s[below] + (position - double(below)) * (times_s[below + 1] - times_s[below]);
    };
    return {static_cast<int>(times_s.size()), at(0.5), at(0.25), at(0.75)};
}

std::string attack_name(const AttackRow& attack) {
    std::string name;
    for (const std::string* part : {&attack.command, &attack.kind, &attack.height}) {
        if (!part->empty() && *part != "none") name += (name.empty() ? "" : " ") + *part;
    }
    return name.empty() ? std::string("attack") : name;
}

double share(int part, int whole) { return whole > 0 ? double(part) / double(whole) : k_no_value; }

Result<std::vector<SessionProgress>> session_progress(const StoreReader& store, const std::string& trainee) {
    if (Result<void> known = store.check_trainee(trainee); !known) return known.error();
    Result<std::vector<SessionRow>> rows = store.sessions(trainee);
    if (!rows) return rows.error();
    std::vector<SessionProgress> sessions(rows->size());
    std::map<std::int64_t, std::size_t> index_of;
    for (std::size_t i = 0; i < rows->size(); ++i) {
        sessions[i].session = std::move((*rows)[i]);
        index_of[sessions[i].session.id] = i;
    }
    Result<std::vector<std::pair<std::int64_t, AttackRow>>> attacks = store.trainee_attacks(trainee);
    if (!attacks) return attacks.error();
    for (const auto& [session_id, attack] : *attacks) {
        const auto found = index_of.find(session_id);
        if (found == index_of.end()) continue;
        SessionProgress& s = sessions[found->second];
        const std::string name = attack_name(attack);
        ++s.attacks;
        ++s.attacks_by_name[name];
        if (std::isfinite(attack.response_time_s) && attack.response_time_s < 0.0) {
            ++s.anticipated;
        } else if (std::isfinite(attack.response_time_s)) {
            s.response_times_s.push_back(attack.response_time_s);
            s.response_times_by_attack_s[name].push_back(attack.response_time_s);
        }
        s.in_time += attack.quality == "in_time";
        s.late += attack.quality == "late";
        s.no_answer += attack.quality != "in_time" && attack.quality != "late";
        s.fighter_hit += attack.result == "hit";
        s.fighter_blocked += attack.result == "blocked";
        s.fighter_missed += attack.result == "miss";
    }
    Result<std::vector<std::pair<std::int64_t, UserStrikeRow>>> strikes = store.trainee_user_strikes(trainee);
    if (!strikes) return strikes.error();
    for (const auto& [session_id, strike] : *strikes) {
        const auto found = index_of.find(session_id);
        if (found == index_of.end()) continue;
        SessionProgress& s = sessions[found->second];
        ++s.user_strikes;
        // The bout's events call a strike that landed on the fighter hit_by_user; accept the plain word too.
        s.user_landed += strike.outcome == "hit_by_user" || strike.outcome == "landed";
        s.user_defended += strike.defended;
    }
    for (SessionProgress& s : sessions) s.response_time = time_spread(s.response_times_s);
    return sessions;
}

std::vector<DrillComparison> drill_comparisons(const std::vector<SessionProgress>& sessions) {
    std::map<std::string, DrillComparison> by_drill;
    for (std::size_t i = 0; i < sessions.size(); ++i) {
        const std::string& drill = sessions[i].session.drill;
        DrillComparison& c = by_drill[drill];
        if (c.runs++ == 0) c.first = i;
        c.last = i;
        c.drill = drill;
        std::string lower = drill;
        std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char ch) { return char(std::tolower(ch)); });
        c.reaction_test = lower.find("reaction") != std::string::npos;
    }
    std::vector<DrillComparison> compared;
    for (auto& [drill, c] : by_drill) {
        if (c.runs >= 2) compared.push_back(c);
    }
    std::stable_sort(compared.begin(), compared.end(), [](const DrillComparison& a, const DrillComparison& b) { return a.reaction_test > b.reaction_test; });
    return compared;
}

namespace {

constexpr const char* k_style = R"(
body { font-family: system-ui, "DejaVu Sans", sans-serif; color: #222; margin: 24px 32px; max-width: 1280px; line-height: 1.35; }
.overview { color: #444; font-size: 14px; }
table { border-collapse: collapse; font-size: 12.5px; margin: 4px 16px 8px 0; }
td, th { border-bottom: 1px solid #e3e3e3; padding: 3px 7px 3px 0; text-align: left; vertical-align: top; white-space: nowrap; }
th.group { border-bottom: 1px solid #999; text-align: center; white-space: normal; } td.n, th.n { text-align: right; } td.drill { white-space: normal; }
tr.incomplete td { background: #fff3cd; } .tag { font-size: 11px; border: 1px solid #E69F00; border-radius: 3px; padding: 0 4px; }
.better { color: #006b4f; } .worse { color: #a14400; } .dim { color: #777; }
.figures { display: flex; flex-wrap: wrap; align-items: flex-start; gap: 8px 20px; } .figures > div { width: min-content; }
svg .title { font-size: 13px; font-weight: 600; } svg .tick { font-size: 10px; fill: #444; } svg .label { font-size: 11px; fill: #333; }
svg .note { font-size: 12px; fill: #888; } svg .axis { stroke: #555; stroke-width: 1; } svg .grid { stroke: #e2e2e2; stroke-width: 1; }
.notes { font-size: 12px; color: #555; max-width: 1000px; }
)";

constexpr int k_attacks_shown = 4; // the most frequent attacks drawn one by one; the rest pooled

std::string ms(double seconds) { return std::isfinite(seconds) ? fixed(seconds * 1000.0, 0) : "–"; }
std::string ms_text(double seconds) { return std::isfinite(seconds) ? ms(seconds) + " ms" : "–"; }
std::string percent(double part) { return std::isfinite(part) ? fixed(100.0 * part, 0) + "%" : "–"; }
std::string seconds_attribute(double seconds) { return std::isfinite(seconds) ? fixed(seconds, 4) : "nan"; }

// "2026-12-06T04:00:00Z" → "2026-12-06 04:00"; the day alone for ranges.
std::string when(const std::string& utc) { return utc.size() >= 16 ? utc.substr(0, 10) + " " + utc.substr(11, 5) : utc; }
std::string day(const std::string& utc) { return utc.substr(0, 10); }

// "1:40 min", "48 s".
std::string duration_text(double seconds) {
    if (!std::isfinite(seconds)) return "–";
    const long long whole = std::llround(seconds);
    const std::string secs = std::to_string(whole % 60);
    return whole < 60 ? secs + " s" : std::to_string(whole / 60) + ":" + (secs.size() < 2 ? "0" : "") + secs + " min";
}

std::string session_label(const std::vector<SessionProgress>& sessions, std::size_t i) {
    return "#" + std::to_string(i + 1) + " " + when(sessions[i].session.started_utc) + ", " + sessions[i].session.drill +
           (sessions[i].session.complete ? "" : " (incomplete)");
}

// A chart with the sessions along x (one slot each, oldest left) and a value up y, in display units.
struct SessionChart {
    double width = 560.0, height = 230.0, left = 54.0, right = 14.0, top = 30.0, bottom = 40.0;
    std::size_t sessions = 1;
    double lo = 0.0, hi = 1.0;
    double plot_w() const { return width - left - right; }
    double plot_h() const { return height - top - bottom; }
    double x(std::size_t i) const { return left + plot_w() * (double(i) + 0.5) / double(std::max<std::size_t>(sessions, 1)); }
    double y(double value) const { return top + plot_h() * (1.0 - std::clamp((value - lo) / (hi - lo), 0.0, 1.0)); }
};

// The chart's frame: its title (also the SVG's accessible name), the value grid and axes, the session numbers.
std::string chart_open(const SessionChart& c, const std::string& id_and_class, const std::string& title, const std::string& y_label) {
    std::string svg = "<svg " + id_and_class + " width=\"" + px(c.width) + "\" height=\"" + px(c.height) + "\" viewBox=\"0 0 " + px(c.width) + " " +
                      px(c.height) + "\" role=\"img\" aria-label=\"" + escape_html(title) + "\"><title>" + escape_html(title) + "</title>";
    svg += "<text x=\"4\" y=\"16\" class=\"title\">" + escape_html(title) + "</text>";
    const report::Ticks ticks = report::nice_ticks(c.lo, c.hi, 5);
    for (int i = 0; i < ticks.count; ++i) {
        const double y = c.y(ticks.at(i));
        svg += "<line x1=\"" + px(c.left) + "\" y1=\"" + px(y) + "\" x2=\"" + px(c.left + c.plot_w()) + "\" y2=\"" + px(y) + "\" class=\"grid\"/>";
        svg += "<text x=\"" + px(c.left - 5) + "\" y=\"" + px(y + 3) + "\" class=\"tick\" text-anchor=\"end\">" + fixed(ticks.at(i), ticks.step >= 1.0 ? 0 : 1) + "</text>";
    }
    const double bottom_y = c.top + c.plot_h();
    svg += "<line x1=\"" + px(c.left) + "\" y1=\"" + px(bottom_y) + "\" x2=\"" + px(c.left + c.plot_w()) + "\" y2=\"" + px(bottom_y) + "\" class=\"axis\"/>";
    svg += "<line x1=\"" + px(c.left) + "\" y1=\"" + px(c.top) + "\" x2=\"" + px(c.left) + "\" y2=\"" + px(bottom_y) + "\" class=\"axis\"/>";
    const std::size_t every = std::max<std::size_t>(1, (c.sessions + 11) / 12); // at most a dozen numbers
    for (std::size_t i = 0; i < c.sessions; i += every) {
        svg += "<text x=\"" + px(c.x(i)) + "\" y=\"" + px(bottom_y + 14) + "\" class=\"tick\" text-anchor=\"middle\">" + std::to_string(i + 1) + "</text>";
    }
    svg += "<text x=\"" + px(c.left + c.plot_w() / 2) + "\" y=\"" + px(c.height - 6) + "\" class=\"label\" text-anchor=\"middle\">session (# of the table, oldest first)</text>";
    svg += "<text transform=\"rotate(-90)\" x=\"" + px(-(c.top + c.plot_h() / 2)) + "\" y=\"14\" class=\"label\" text-anchor=\"middle\">" + escape_html(y_label) + "</text>";
    return svg;
}

// A point of a session, hollow when the session did not end.
std::string marker(double x, double y, bool filled, const char* fill, bool square, const std::string& attributes, const std::string& tooltip) {
    const std::string paint = "fill=\"" + std::string(filled ? fill : "#ffffff") + "\" stroke=\"" + fill + "\" stroke-width=\"1.5\" " + attributes + ">";
    const std::string shape = square ? "<rect x=\"" + px(x - 4) + "\" y=\"" + px(y - 4) + "\" width=\"8\" height=\"8\" " + paint + "<title>" + tooltip + "</title></rect>"
                                     : "<circle cx=\"" + px(x) + "\" cy=\"" + px(y) + "\" r=\"4.5\" " + paint + "<title>" + tooltip + "</title></circle>";
    return shape;
}

// Response times session by session: the median as points on a line, the quartiles as a band (`band`) or whiskers.
std::string response_time_svg(const std::vector<SessionProgress>& sessions, const std::vector<TimeSpread>& spreads, SessionChart c, const std::string& id_and_class,
                              const std::string& title, const std::string& attack, bool band) {
    std::string svg = chart_open(c, id_and_class, title, "response time (ms)");
    std::string line, upper, lower, marks;
    for (std::size_t i = 0; i < spreads.size(); ++i) {
        const TimeSpread& s = spreads[i];
        if (s.n == 0) continue;
        const double x = c.x(i), y = c.y(1000.0 * s.median_s), y25 = c.y(1000.0 * s.p25_s), y75 = c.y(1000.0 * s.p75_s);
        line += (line.empty() ? "" : " ") + px(x) + "," + px(y);
        upper += (upper.empty() ? "" : " ") + px(x) + "," + px(y75);
        lower = px(x) + "," + px(y25) + (lower.empty() ? "" : " ") + lower;
        if (!band) {
            marks += "<path d=\"M" + px(x) + " " + px(y25) + "V" + px(y75) + "M" + px(x - 4) + " " + px(y25) + "h8M" + px(x - 4) + " " + px(y75) + "h8\" stroke=\"" +
                     colour::blue + "\" stroke-width=\"1.2\" class=\"whisker\"/>";
        }
        const std::string attributes = "class=\"median-point\" data-session-id=\"" + std::to_string(sessions[i].session.id) + "\" data-attack=\"" + escape_html(attack) +
                                       "\" data-median-s=\"" + seconds_attribute(s.median_s) + "\" data-p25-s=\"" + seconds_attribute(s.p25_s) + "\" data-p75-s=\"" +
                                       seconds_attribute(s.p75_s) + "\" data-n=\"" + std::to_string(s.n) + "\"";
        const std::string tooltip = escape_html(session_label(sessions, i)) + ": median " + ms(s.median_s) + " ms (p25–p75 " + ms(s.p25_s) + "–" + ms(s.p75_s) +
                                    " ms), " + std::to_string(s.n) + " answers";
        marks += marker(x, y, sessions[i].session.complete, colour::blue, false, attributes, tooltip);
    }
    if (line.empty()) return svg + "<text x=\"" + px(c.left + 12) + "\" y=\"" + px(c.top + c.plot_h() / 2) + "\" class=\"note\">no answers timed</text></svg>";
    if (band) svg += "<polygon points=\"" + upper + " " + lower + "\" fill=\"" + colour::sky + "\" fill-opacity=\"0.35\" class=\"spread-band\"><title>p25–p75</title></polygon>";
    svg += "<polyline points=\"" + line + "\" fill=\"none\" stroke=\"" + colour::blue + "\" stroke-width=\"1.5\"/>";
    return svg + marks + "</svg>";
}

struct Layer {
    const char* label;
    const char* css_class;
    const char* colour;
    std::vector<int> counts; // one a session
};

// Shares of each session's total stacked to 100%, the first layer at the bottom.
std::string stacked_shares_svg(const std::vector<SessionProgress>& sessions, const std::vector<Layer>& layers, SessionChart c, const std::string& id_and_class,
                               const std::string& title, const std::string& of_what) {
    c.lo = 0.0;
    c.hi = 100.0;
    std::string svg = chart_open(c, id_and_class, title, "share of " + of_what + " (%)");
    const double bar_w = std::min(30.0, 0.7 * c.plot_w() / double(std::max<std::size_t>(sessions.size(), 1)));
    for (std::size_t i = 0; i < sessions.size(); ++i) {
        int total = 0;
        for (const Layer& layer : layers) total += layer.counts[i];
        double below = 0.0;
        for (const Layer& layer : layers) {
            const double part = share(layer.counts[i], total);
            if (!(part > 0.0)) continue;
            const double y_top = c.y(100.0 * (below + part)), y_bottom = c.y(100.0 * below);
            svg += "<rect class=\"" + std::string(layer.css_class) + "\" data-session-id=\"" + std::to_string(sessions[i].session.id) + "\" data-share=\"" +
                   fixed(part, 4) + "\" x=\"" + px(c.x(i) - bar_w / 2) + "\" y=\"" + px(y_top) + "\" width=\"" + px(bar_w) + "\" height=\"" + px(y_bottom - y_top) +
                   "\" fill=\"" + layer.colour + "\" fill-opacity=\"" + (sessions[i].session.complete ? "1" : "0.45") + "\"><title>" +
                   escape_html(session_label(sessions, i)) + ": " + layer.label + " " + std::to_string(layer.counts[i]) + " of " + std::to_string(total) + " (" +
                   percent(part) + ")</title></rect>";
            below += part;
        }
    }
    return svg + "</svg>";
}

std::string legend(const std::vector<std::pair<const char*, const char*>>& colour_and_words, bool squares_for_second = false) {
    std::string html = "<p class=\"legend\">";
    bool first = true;
    for (const auto& [fill, words] : colour_and_words) {
        const bool square = squares_for_second && !first;
        html += "<span class=\"key\"><svg width=\"12\" height=\"12\" aria-hidden=\"true\">" +
                std::string(square || !squares_for_second ? "<rect x=\"1\" y=\"1\" width=\"10\" height=\"10\"" : "<circle cx=\"6\" cy=\"6\" r=\"5\"") + " fill=\"" + fill +
                "\"/></svg>" + words + "</span>";
        first = false;
    }
    return html + "</p>";
}

// The person's strikes session by session: the share that landed on the fighter and the share it defended.
std::string user_strikes_svg(const std::vector<SessionProgress>& sessions, SessionChart c) {
    c.lo = 0.0;
    c.hi = 100.0;
    std::string svg = chart_open(c, "id=\"trend-user-strikes\" class=\"trend\"", "Your strikes: landed, defended by the fighter", "share of your strikes (%)");
    for (const bool defended : {false, true}) {
        const char* fill = defended ? colour::orange : colour::blue;
        std::string line, marks;
        for (std::size_t i = 0; i < sessions.size(); ++i) {
            const SessionProgress& s = sessions[i];
            const double part = share(defended ? s.user_defended : s.user_landed, s.user_strikes);
            if (!std::isfinite(part)) continue;
            line += (line.empty() ? "" : " ") + px(c.x(i)) + "," + px(c.y(100.0 * part));
            marks += marker(c.x(i), c.y(100.0 * part), s.session.complete, fill, defended,
                            std::string("class=\"") + (defended ? "defended-point" : "landed-point") + "\" data-session-id=\"" + std::to_string(s.session.id) +
                                "\" data-share=\"" + fixed(part, 4) + "\"",
                            escape_html(session_label(sessions, i)) + ": " + (defended ? "defended " : "landed ") +
                                std::to_string(defended ? s.user_defended : s.user_landed) + " of " + std::to_string(s.user_strikes) + " (" + percent(part) + ")");
        }
        if (!line.empty()) svg += "<polyline points=\"" + line + "\" fill=\"none\" stroke=\"" + fill + "\" stroke-width=\"1.5\"" + (defended ? " stroke-dasharray=\"5 3\"" : "") + "/>";
        svg += marks;
    }
    if (std::all_of(sessions.begin(), sessions.end(), [](const SessionProgress& s) { return s.user_strikes == 0; })) {
        svg += "<text x=\"" + px(c.left + 12) + "\" y=\"" + px(c.top + c.plot_h() / 2) + "\" class=\"note\">no strikes of yours stored</text>";
    }
    return svg + "</svg>";
}

// The attacks drawn one by one (the most frequent over every session) and the name of the rest, pooled.
std::vector<std::string> frequent_attacks(const std::vector<SessionProgress>& sessions) {
    std::map<std::string, int> totals;
    for (const SessionProgress& s : sessions) {
        for (const auto& [name, count] : s.attacks_by_name) totals[name] += count;
    }
    std::vector<std::pair<std::string, int>> ranked(totals.begin(), totals.end());
    std::stable_sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
    std::vector<std::string> names;
    for (std::size_t i = 0; i < ranked.size() && i < std::size_t(k_attacks_shown); ++i) names.push_back(ranked[i].first);
    return names;
}

std::string trends_html(const std::vector<SessionProgress>& sessions) {
    SessionChart chart;
    chart.sessions = sessions.size();
    // One time scale for every response-time chart, so attacks compare at a glance.
    std::vector<TimeSpread> all;
    double slowest_ms = 100.0;
    for (const SessionProgress& s : sessions) {
        all.push_back(s.response_time);
        for (const auto& [name, times] : s.response_times_by_attack_s) slowest_ms = std::max(slowest_ms, 1000.0 * time_spread(times).p75_s);
    }
    const report::Ticks ticks = report::nice_ticks(0.0, slowest_ms * 1.05, 5);
    chart.hi = std::max(slowest_ms * 1.05, ticks.at(ticks.count - 1));
    SessionChart wide = chart;
    wide.width = 800.0;
    wide.height = 260.0;
    std::string html = "<h2>Trends</h2><div class=\"figures\"><div>" +
                       response_time_svg(sessions, all, wide, "id=\"trend-response-time\" class=\"trend\"", "Response time, all attacks", "all", true) +
                       "<p class=\"legend\">line and points: the median; band: the middle half of the answers (p25–p75); hollow: a session that did not end</p></div>";

    const std::vector<std::string> shown = frequent_attacks(sessions);
    SessionChart small = chart;
    small.width = 290.0;
    small.height = 200.0;
    std::string by_attack;
    bool others = false;
    for (std::size_t k = 0; k <= shown.size(); ++k) {
        std::vector<TimeSpread> spreads;
        for (const SessionProgress& s : sessions) {
            std::vector<double> times;
            for (const auto& [name, these] : s.response_times_by_attack_s) {
                const bool is_shown = std::find(shown.begin(), shown.end(), name) != shown.end();
                if (k < shown.size() ? name == shown[k] : !is_shown) times.insert(times.end(), these.begin(), these.end());
            }
            others |= k == shown.size() && !times.empty();
            spreads.push_back(time_spread(times));
        }
        if (k == shown.size() && !others) break;
        const std::string name = k < shown.size() ? shown[k] : "other attacks";
        by_attack += response_time_svg(sessions, spreads, small, "class=\"trend attack-trend\" data-attack=\"" + escape_html(name) + "\"", name, name, false);
    }
    html += "</div><h3>Response time by attack</h3><p class=\"legend\">the " + std::to_string(shown.size()) +
            " most frequent attacks, the rest pooled: the median, whiskers from p25 to p75</p><div class=\"figures\" id=\"trend-by-attack\">" + by_attack + "</div>";

    chart.width = 350.0;
    Layer in_time{"in time", "in-time", colour::green, {}}, late{"late", "late", colour::orange, {}}, none{"no answer", "no-answer", colour::vermillion, {}};
    Layer hit{"landed on you", "fighter-hit", colour::vermillion, {}}, blocked{"blocked", "fighter-blocked", colour::blue, {}}, missed{"missed", "fighter-missed", colour::sky, {}};
    for (const SessionProgress& s : sessions) {
        in_time.counts.push_back(s.in_time);
        late.counts.push_back(s.late);
        none.counts.push_back(s.no_answer);
        hit.counts.push_back(s.fighter_hit);
        blocked.counts.push_back(s.fighter_blocked);
        missed.counts.push_back(s.fighter_missed);
    }
    html += "<h3>Answers and blows</h3><div class=\"figures\"><div>" +
            stacked_shares_svg(sessions, {in_time, late, none}, chart, "id=\"trend-quality\" class=\"trend\"", "The answers: in time, late, none", "attacks") +
            legend({{colour::green, "in time"}, {colour::orange, "late"}, {colour::vermillion, "no answer"}}) + "</div><div>" +
            stacked_shares_svg(sessions, {hit, blocked, missed}, chart, "id=\"trend-fighter-blows\" class=\"trend\"", "The fighter's blows: landed, blocked, missed", "attacks") +
            legend({{colour::vermillion, "landed on you"}, {colour::blue, "blocked"}, {colour::sky, "missed"}}) + "</div><div>" + user_strikes_svg(sessions, chart) +
            legend({{colour::blue, "landed on the fighter (solid)"}, {colour::orange, "defended by the fighter (dashed)"}}, true) +
            "</div></div><p class=\"legend\">paler bars, hollow points: a session that did not end</p>";
    return html;
}

std::string sessions_table(const std::vector<SessionProgress>& sessions) {
    std::string html = "<h2>Sessions</h2><table id=\"sessions\"><thead><tr><th colspan=\"5\"></th><th colspan=\"3\" class=\"group\">response time (ms)</th>"
                       "<th colspan=\"3\" class=\"group\">answers (of the attacks)</th><th colspan=\"3\" class=\"group\">the fighter's blows</th>"
                       "<th colspan=\"3\" class=\"group\">your strikes</th></tr><tr><th class=\"n\">#</th><th>started (UTC)</th><th>drill</th>"
                       "<th class=\"n\">duration</th><th class=\"n\">attacks</th><th class=\"n\">median</th><th class=\"n\">p25–p75</th>"
                       "<th class=\"n\" title=\"answers timed (and ones begun before the blow showed)\">timed</th><th class=\"n\">in time</th><th class=\"n\">late</th>"
                       "<th class=\"n\">none</th><th class=\"n\" title=\"landed on you\">landed</th><th class=\"n\">blocked</th><th class=\"n\">missed</th>"
                       "<th class=\"n\">thrown</th><th class=\"n\" title=\"share that landed on the fighter\">landed</th>"
                       "<th class=\"n\" title=\"share blocked or slipped by the fighter\">defended</th></tr></thead><tbody>";
    const auto cell = [](const std::string& css_class, const std::string& text) { return "<td class=\"n " + css_class + "\">" + text + "</td>"; };
    for (std::size_t i = 0; i < sessions.size(); ++i) {
        const SessionProgress& s = sessions[i];
        const TimeSpread& rt = s.response_time;
        html += "<tr class=\"session" + std::string(s.session.complete ? "" : " incomplete") + "\" data-session-id=\"" + std::to_string(s.session.id) + "\">" +
                cell("number", std::to_string(i + 1)) + "<td class=\"started\">" + escape_html(when(s.session.started_utc)) + "</td><td class=\"drill\">" +
                escape_html(s.session.drill) + (s.session.complete ? "" : " <span class=\"tag\">incomplete</span>") + "</td>" +
                cell("duration", duration_text(s.session.duration_s)) + cell("attacks", std::to_string(s.attacks)) + "<td class=\"n median\" data-median-s=\"" +
                seconds_attribute(rt.median_s) + "\">" + ms(rt.median_s) + "</td>" +
                cell("spread", rt.n ? ms(rt.p25_s) + "–" + ms(rt.p75_s) : "–") +
                cell("timed", std::to_string(rt.n) + (s.anticipated ? " <span class=\"dim\">+" + std::to_string(s.anticipated) + " early</span>" : "")) +
                cell("in-time", percent(share(s.in_time, s.attacks))) + cell("late", percent(share(s.late, s.attacks))) +
                cell("no-answer", percent(share(s.no_answer, s.attacks))) + cell("fighter-hit", std::to_string(s.fighter_hit)) +
                cell("fighter-blocked", std::to_string(s.fighter_blocked)) + cell("fighter-missed", std::to_string(s.fighter_missed)) +
                cell("user-strikes", std::to_string(s.user_strikes)) + cell("user-landed", percent(share(s.user_landed, s.user_strikes))) +
                cell("user-defended", percent(share(s.user_defended, s.user_strikes))) + "</tr>";
    }
    return html + "</tbody></table>";
}

// "−42 ms (−9%)", coloured by whether it is better for the trainee (`lower_is_better` for times).
std::string change_cell(const std::string& css_class, double before, double after, bool lower_is_better, bool as_ms) {
    if (!std::isfinite(before) || !std::isfinite(after)) return "<td class=\"n " + css_class + "\">–</td>";
    const double delta = after - before;
    const bool better = lower_is_better ? delta < 0.0 : delta > 0.0;
    const std::string sign = delta > 0.0 ? "+" : delta < 0.0 ? "−" : "±";
    std::string text = as_ms ? sign + fixed(std::abs(delta) * 1000.0, 0) + " ms" : sign + fixed(std::abs(delta) * 100.0, 0) + " points";
    if (as_ms && before > 0.0) text += " (" + sign + fixed(std::abs(delta) / before * 100.0, 0) + "%)";
    const std::string verdict = delta == 0.0 ? "" : better ? " better" : " worse";
    return "<td class=\"n " + css_class + verdict + "\" data-change=\"" + fixed(delta, 4) + "\">" + text + "</td>";
}

std::string comparisons_html(const std::vector<SessionProgress>& sessions) {
    const std::vector<DrillComparison> comparisons = drill_comparisons(sessions);
    std::string html = "<h2>First and last run of each drill</h2>";
    if (comparisons.empty()) return html + "<p id=\"comparisons\" class=\"dim\">No drill has been run twice yet: a pre- and post-test needs two runs of the same drill.</p>";
    html += "<table id=\"comparisons\"><thead><tr><th colspan=\"3\"></th><th colspan=\"3\" class=\"group\">median response time</th><th colspan=\"2\" class=\"group\">"
            "p25–p75</th><th colspan=\"3\" class=\"group\">in time</th><th colspan=\"2\" class=\"group\">answers timed</th></tr><tr><th>drill</th><th class=\"n\">runs</th>"
            "<th>first → last</th><th class=\"n\">first</th><th class=\"n\">last</th><th class=\"n\">change</th><th class=\"n\">first</th><th class=\"n\">last</th>"
            "<th class=\"n\">first</th><th class=\"n\">last</th><th class=\"n\">change</th><th class=\"n\">first</th><th class=\"n\">last</th></tr></thead><tbody>";
    for (const DrillComparison& c : comparisons) {
        const SessionProgress& a = sessions[c.first];
        const SessionProgress& b = sessions[c.last];
        const auto n = [](const std::string& css_class, const std::string& text) { return "<td class=\"n " + css_class + "\">" + text + "</td>"; };
        const auto spread = [](const TimeSpread& s) { return s.n ? ms(s.p25_s) + "–" + ms(s.p75_s) + " ms" : std::string("–"); };
        html += "<tr class=\"comparison" + std::string(c.reaction_test ? " reaction-test" : "") + "\" data-drill=\"" + escape_html(c.drill) + "\" data-first-session-id=\"" +
                std::to_string(a.session.id) + "\" data-last-session-id=\"" + std::to_string(b.session.id) + "\"><td>" + escape_html(c.drill) +
                (c.reaction_test ? " <span class=\"tag\">reaction test</span>" : "") + "</td>" + n("runs", std::to_string(c.runs)) + "<td>#" +
                std::to_string(c.first + 1) + " " + escape_html(day(a.session.started_utc)) + " → #" + std::to_string(c.last + 1) + " " +
                escape_html(day(b.session.started_utc)) + "</td>" + n("median-first", ms_text(a.response_time.median_s)) +
                n("median-last", ms_text(b.response_time.median_s)) + change_cell("median-change", a.response_time.median_s, b.response_time.median_s, true, true) +
                n("spread-first", spread(a.response_time)) + n("spread-last", spread(b.response_time)) + n("in-time-first", percent(share(a.in_time, a.attacks))) +
                n("in-time-last", percent(share(b.in_time, b.attacks))) +
                change_cell("in-time-change", share(a.in_time, a.attacks), share(b.in_time, b.attacks), false, false) + n("n-first", std::to_string(a.response_time.n)) +
                n("n-last", std::to_string(b.response_time.n)) + "</tr>";
    }
    return html + "</tbody></table><p class=\"legend\">Green: better (faster, more in time); brown: worse. A change over few answers (n) is mostly chance.</p>";
}

} // namespace

Result<std::string> progress_html(const StoreReader& store, const std::string& trainee) {
    Result<std::vector<SessionProgress>> sessions = session_progress(store, trainee);
    if (!sessions) return sessions.error();
    return progress_html(trainee, *sessions);
}

std::string progress_html(const std::string& trainee, const std::vector<SessionProgress>& sessions) {
    std::string html = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><meta name=\"viewport\" content=\"width=device-width\"><title>kumite progress — " +
                       escape_html(trainee) + "</title><style>" + report::k_page_style + k_style + "</style></head><body>\n<h1>Progress of <span id=\"trainee\">" + escape_html(trainee) +
                       "</span></h1>";
    const long long incomplete = std::count_if(sessions.begin(), sessions.end(), [](const SessionProgress& s) { return !s.session.complete; });
    html += "<p class=\"overview\"><span id=\"sessions-count\">" + std::to_string(sessions.size()) + "</span> session" + (sessions.size() == 1 ? "" : "s");
    if (!sessions.empty()) {
        const std::string first = day(sessions.front().session.started_utc), last = day(sessions.back().session.started_utc);
        html += first == last ? ", on <span id=\"first-day\">" + escape_html(first) + "</span>"
                              : ", from <span id=\"first-day\">" + escape_html(first) + "</span> to <span id=\"last-day\">" + escape_html(last) + "</span>";
    }
    if (incomplete > 0) html += " (" + std::to_string(incomplete) + " did not end: marked incomplete)";
    html += "</p>";
    if (sessions.empty()) return html + "<p>No sessions stored.</p></body></html>\n";
    html += sessions_table(sessions) + trends_html(sessions) + comparisons_html(sessions);
    html += "<h2>How to read it</h2><p class=\"notes\">The response time runs from the blow's first visible motion to the trainee's first defensive "
            "motion; answers that began before the blow showed are counted as early and left out of the times. An answer is in time when it began "
            "before the blow reached its target and the blow did not land (a guard held where the blow came counts too), late when it began "
            "after that or the blow landed anyway. The median is the middle answer; p25–p75 is the middle half of them. "
            "The fighter's blows landed, were blocked or missed; your strikes landed on the fighter or were defended by it (blocked or slipped). "
            "A session marked incomplete did not end (stopped or crashed): its numbers are those stored before it stopped.</p>";
    return html + "\n</body></html>\n";
}

} // namespace kumite::training
