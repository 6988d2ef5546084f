// The user's answers to the fighter's blows in the session report (session_responses.h).

#include "session_responses.h"

#include "svg_plot.h"

#include <map>
#include <vector>

namespace kumite::report {
namespace {

constexpr const char* k_kinds[] = {"block", "parry", "slip", "duck", "step_back", "none"};
constexpr const char* k_qualities[] = {"in_time", "late", "none"};

struct AttackCounts {
    long long blows = 0, moved = 0, anticipated = 0, countered = 0, counters_landed = 0;
    std::map<std::string, long long> kinds, quality, results;
    std::vector<double> times_s; // answers after the blow became visible
};

std::string cell(long long count, long long of, const std::string& css_class) {
    std::string text = std::to_string(count);
    if (of > 0 && count > 0) text += " <span class=\"share\">(" + fixed(100.0 * double(count) / double(of), 0) + "%)</span>";
    return "<td class=\"n " + css_class + "\">" + text + "</td>";
}

std::string label(std::string_view name) {
    std::string text(name);
    for (char& c : text) c = c == '_' ? ' ' : c;
    return escape_html(text);
}

} // namespace

std::string responses_section_html(const FighterLog& fighter) {
    if (fighter.responses.empty()) return {};
    std::map<std::string, AttackCounts> by_attack;
    for (const ResponseRecord& r : fighter.responses) {
        AttackCounts& a = by_attack[r.attack];
        ++a.blows;
        a.moved += r.moved;
        a.countered += r.countered;
        a.counters_landed += r.counter_landed;
        ++a.kinds[r.response];
        ++a.quality[r.quality];
        ++a.results[r.result];
        if (r.moved && r.response_time_s > -1e8) {
            if (r.response_time_s < 0.0) ++a.anticipated;
            else a.times_s.push_back(r.response_time_s);
        }
    }
    std::string html = "<h3>The user's answers to the fighter's blows</h3><table class=\"responses\"><tr><th>attack</th><th class=\"n\">blows</th>"
                       "<th class=\"n\">landed</th><th class=\"n\">answered</th><th class=\"n\">before it showed</th><th class=\"n\">median response</th>";
    for (const char* kind : k_kinds) html += "<th class=\"n\">" + label(kind) + "</th>";
    for (const char* quality : k_qualities) html += "<th class=\"n\">" + std::string(quality == std::string_view("none") ? "no answer" : label(quality)) + "</th>";
    html += "<th class=\"n\">countered (landed)</th></tr>";
    std::string histograms;
    for (const auto& [attack, a] : by_attack) {
        html += "<tr class=\"attack\"><th>" + escape_html(attack) + "</th>" + cell(a.blows, 0, "blows") + cell(a.results.count("hit") ? a.results.at("hit") : 0, a.blows, "landed") +
                cell(a.moved, a.blows, "answered") + cell(a.anticipated, 0, "anticipated") + "<td class=\"n median\">" + (a.times_s.empty() ? "–" : fixed(median(a.times_s), 2) + " s") + "</td>";
        for (const char* kind : k_kinds) html += cell(a.kinds.count(kind) ? a.kinds.at(kind) : 0, a.blows, std::string("kind-") + kind);
        for (const char* quality : k_qualities) html += cell(a.quality.count(quality) ? a.quality.at(quality) : 0, a.blows, std::string("quality-") + quality);
        html += "<td class=\"n countered\">" + std::to_string(a.countered) + " (" + std::to_string(a.counters_landed) + ")</td></tr>";
        histograms += histogram_svg(a.times_s, {"response time: " + attack, "ms", 1000.0, "response-time"});
    }
    html += "</table><p class=\"legend\">The response time runs from the blow's first visible motion (its fist or foot closing on the target at "
            "0.5 m/s) to the user's first defensive motion: the head going back or off the blow's line at 0.4 m/s, or a glove moving towards "
            "its path at 0.5 m/s; an answer that began before the blow showed is counted apart. A block without an answer is a guard held where the blow came.</p>";
    return html + "<div class=\"histograms\">" + histograms + "</div>";
}

} // namespace kumite::report
