#include "session_motion.h"

#include "svg_plot.h"

namespace kumite::report {
namespace {

double number(const nlohmann::json& object, const char* key) {
    const auto found = object.find(key);
    return found != object.end() && found->is_number() ? found->get<double>() : 0.0;
}

// A joint's speed and the library's: "11.1 / 12.0", marked when over it.
std::string speed_cell(const nlohmann::json& entry, const char* key, int decimals) {
    const double value = number(entry, key);
    const auto library = entry.find("library");
    const double bar = library != entry.end() && library->is_object() ? number(*library, key) : 0.0;
    const bool over = bar > 0.0 && value > bar;
    return std::string("<td class=\"n") + (over ? " over" : "") + "\">" + fixed(value, decimals) + (bar > 0.0 ? " / " + fixed(bar, decimals) : "") + "</td>";
}

} // namespace

std::string motion_html(const nlohmann::json* bout_end) {
    if (!bout_end || !bout_end->is_object() || !bout_end->contains("motion") || !(*bout_end)["motion"].is_object()) {
        return "<p class=\"motion-missing\">No motion measures in these events (the bout_end line has none).</p>";
    }
    const nlohmann::json& motion = (*bout_end)["motion"];
    std::string html = "<h2>Motion</h2><div class=\"tables\"><table class=\"motion\"><tr><th>move</th><th class=\"n\">frames</th>"
                       "<th class=\"n\">wrist m/s</th><th class=\"n\">ankle m/s</th><th class=\"n\">elbow rad/s</th><th class=\"n\">knee rad/s</th></tr>";
    if (motion.contains("by_move") && motion["by_move"].is_object()) {
        for (const auto& [move, entry] : motion["by_move"].items()) {
            if (!entry.is_object()) continue;
            html += "<tr class=\"move-" + escape_html(move) + "\"><th>" + escape_html(move) + "</th><td class=\"n\">" + fixed(number(entry, "frames"), 0) + "</td>" +
                    speed_cell(entry, "wrist_mps", 1) + speed_cell(entry, "ankle_mps", 1) + speed_cell(entry, "elbow_radps", 1) +
                    speed_cell(entry, "knee_radps", 1) + "</tr>";
        }
    }
    html += "</table><table class=\"distance\"><tr><th colspan=\"2\">between strikes</th></tr>";
    if (motion.contains("distance_between_strikes") && motion["distance_between_strikes"].is_object()) {
        const nlohmann::json& distance = motion["distance_between_strikes"];
        html += "<tr><th>distance to the user, median</th><td class=\"n distance-median\">" + fixed(number(distance, "median_m"), 2) + " m (" +
                fixed(number(distance, "median_legs"), 2) + " legs)</td></tr>";
        html += "<tr><th>p5 – p95</th><td class=\"n\">" + fixed(number(distance, "p5_m"), 2) + " – " + fixed(number(distance, "p95_m"), 2) + " m</td></tr>";
    }
    if (motion.contains("speed_at_contact_by_kind_mps") && motion["speed_at_contact_by_kind_mps"].is_object()) {
        for (const auto& [kind, speeds] : motion["speed_at_contact_by_kind_mps"].items()) {
            if (!speeds.is_object()) continue;
            html += "<tr><th>" + escape_html(kind) + " speed at contact, median</th><td class=\"n contact-" + escape_html(kind) + "\">" +
                    fixed(number(speeds, "median"), 1) + " m/s (" + fixed(number(speeds, "count"), 0) + ")</td></tr>";
        }
    }
    return html + "</table></div><p class=\"note\">Each speed is the fastest of the bout, over the fastest of the library's clips of that kind played on " +
           escape_html(motion.value("library_character", std::string("the starting character"))) + " (recoveries: the fastest strike's; hold: the guard's); a marked cell is over it.</p>";
}

} // namespace kumite::report
