#include "play_summary.h"

#include <cstdio>
#include <map>

namespace kumite::cli {

namespace {

std::string fixed(double value, int decimals) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

double number_at(const nlohmann::json& object, const nlohmann::json::json_pointer& where) {
    return object.contains(where) && object.at(where).is_number() ? object.at(where).get<double>() : 0.0;
}

long long count_at(const nlohmann::json& object, const char* key) {
    return object.contains(key) && object.at(key).is_number() ? object.at(key).get<long long>() : 0;
}

// "punch 7 (6 hits, 5.2 m/s), kick 4 (3 hits, 6.4 m/s)": strikes and hits by semantics from the report's by_kind,
// the median speed at contact from its motion.
std::string strikes_by_semantics(const nlohmann::json& report) {
    std::map<std::string, std::pair<long long, long long>> by_semantics; // strikes, hits
    const auto by_kind = report.find("by_kind");
    if (by_kind == report.end() || !by_kind->is_object()) return {};
    for (const auto& [key, entry] : by_kind->items()) {
        auto& [strikes, hits] = by_semantics[key.substr(0, key.find(' '))];
        strikes += count_at(entry, "strikes");
        hits += count_at(entry, "hits");
    }
    std::string text;
    for (const auto& [semantics, counts] : by_semantics) {
        text += (text.empty() ? "" : ", ") + semantics + " " + std::to_string(counts.first) + " (" + std::to_string(counts.second) + " hits";
        const nlohmann::json::json_pointer speed("/motion/speed_at_contact_by_kind_mps/" + semantics + "/median");
        if (report.contains(speed)) text += ", " + fixed(report.at(speed).get<double>(), 1) + " m/s";
        text += ")";
    }
    return text;
}

} // namespace

std::string play_summary_text(const nlohmann::json& report, const std::vector<std::pair<std::string, std::string>>& files) {
    using pointer = nlohmann::json::json_pointer;
    const auto row = [](const std::string& label, const std::string& text) {
        return "  " + label + std::string(label.size() < 13 ? 13 - label.size() : 1, ' ') + text + "\n";
    };
    const long long frames = count_at(report, "frames");
    std::string text = "played " + fixed(double(frames) / 60.0, 1) + " s (" + std::to_string(frames) + " frames), " +
                       std::to_string(count_at(report, "fighters")) + " fighter(s), aim " + report.value("aim", std::string("latched")) + "\n";
    const nlohmann::json outcomes = report.value("order_outcomes", nlohmann::json::object());
    text += row("orders", std::to_string(count_at(report, "orders")) + ": " + std::to_string(count_at(outcomes, "performed")) + " performed, " +
                              std::to_string(count_at(outcomes, "expired")) + " expired, " + std::to_string(count_at(outcomes, "refused")) + " refused");
    const std::string kinds = strikes_by_semantics(report);
    text += row("strikes", std::to_string(count_at(report, "strikes")) + ": " + std::to_string(count_at(report, "hits")) + " hits, " +
                               std::to_string(count_at(report, "misses")) + " misses" +
                               (count_at(report, "blocked_by_user") > 0 ? " (" + std::to_string(count_at(report, "blocked_by_user")) + " blocked by the user)" : "") +
                               (kinds.empty() ? "" : "; " + kinds));
    const nlohmann::json user = report.value("user_strikes", nlohmann::json::object());
    const long long kept_off = count_at(user, "blocked") + count_at(user, "slipped"), landed = count_at(user, "hit_by_user");
    std::string defended = std::to_string(kept_off) + " of " + std::to_string(kept_off + landed);
    if (kept_off + landed > 0) defended += " (" + fixed(100.0 * double(kept_off) / double(kept_off + landed), 0) + "%)";
    text += row("user's blows", std::to_string(count_at(user, "seen")) + " seen: " + std::to_string(count_at(user, "blocked")) + " blocked, " +
                                    std::to_string(count_at(user, "slipped")) + " slipped, " + std::to_string(landed) + " landed; defended " + defended +
                                    (report.value("defence", true) ? "" : " (defence off)"));
    const nlohmann::json responses = report.value("user_responses", nlohmann::json::object());
    if (!responses.empty()) {
        std::string answers;
        for (const auto& [kind, r] : responses.items()) {
            const long long timed = count_at(r, "moved") - count_at(r, "anticipated");
            // In time counts a guard already in place too; moved, the answers with a motion (their median time).
            answers += (answers.empty() ? "" : "; ") + kind + " " + std::to_string(count_at(r, "blows")) + " (" +
                       std::to_string(std::llround(number_at(r, pointer("/quality/in_time")))) + " in time, " + std::to_string(count_at(r, "moved")) + " moved" +
                       (timed > 0 ? ", median " + fixed(number_at(r, pointer("/response_time_s/median")), 2) + " s" : "") + ")";
        }
        text += row("user answers", answers);
    }
    text += row("fastest", "wrist " + fixed(number_at(report, pointer("/motion/fastest/wrist_mps")), 1) + " m/s, ankle " +
                               fixed(number_at(report, pointer("/motion/fastest/ankle_mps")), 1) + " m/s");
    if (number_at(report, pointer("/motion/distance_between_strikes/frames")) > 0) {
        text += row("distance", fixed(number_at(report, pointer("/motion/distance_between_strikes/median_m")), 2) + " m median between strikes (" +
                                    fixed(number_at(report, pointer("/motion/distance_between_strikes/p5_m")), 2) + "-" +
                                    fixed(number_at(report, pointer("/motion/distance_between_strikes/p95_m")), 2) + " m, 5-95%)");
    }
    text += row("frame time", "mean " + fixed(number_at(report, pointer("/frame_time_us/mean")), 0) + " us, p99 " +
                                  fixed(number_at(report, pointer("/frame_time_us/p99")), 0) + " us, " + std::to_string(count_at(report, "missed_frames")) + " missed");
    for (const auto& [what, path] : files) text += row(what, path);
    return text;
}

} // namespace kumite::cli
