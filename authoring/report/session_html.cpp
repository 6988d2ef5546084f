// The session report's page (session_html.h): summary tables, then one section per fighter.

#include "session_html.h"

#include "session_figures.h"
#include "session_motion.h"
#include "session_responses.h"
#include "svg_plot.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace kumite::report {

namespace {

constexpr const char* k_style = R"(
body { font-family: system-ui, "DejaVu Sans", sans-serif; color: #222; margin: 24px 32px; max-width: 1200px; line-height: 1.35; }
.source { color: #555; font-size: 13px; }
.stopped { background: #fff3cd; border: 1px solid #E69F00; padding: 6px 10px; font-size: 14px; }
table { border-collapse: collapse; font-size: 13px; margin: 4px 16px 8px 0; }
td, th { border-bottom: 1px solid #e3e3e3; padding: 2px 10px 2px 0; text-align: left; vertical-align: top; }
td.n, th.n { text-align: right; } td.over { color: #b00; font-weight: bold; }
.tables { display: flex; flex-wrap: wrap; align-items: flex-start; }
.figures { display: flex; flex-wrap: wrap; align-items: flex-start; gap: 8px; }
.histograms { display: grid; grid-template-columns: 280px 280px; gap: 4px 16px; }
svg .title { font-size: 12px; font-weight: 600; } svg .tick { font-size: 10px; fill: #444; } svg .label { font-size: 11px; fill: #333; }
svg .note { font-size: 12px; fill: #888; } svg .axis { stroke: #555; stroke-width: 1; fill-opacity: 0; } svg .grid { stroke: #ddd; stroke-width: 1; }
)";

// Microseconds for people: "12 µs", "2.45 ms".
std::string duration_text(double us) { return us < 1000.0 ? fixed(us, 0) + " µs" : fixed(us / 1000.0, 2) + " ms"; }

std::string percent(long long part, long long whole) {
    return whole > 0 ? " (" + fixed(100.0 * double(part) / double(whole), 0) + "%)" : std::string();
}

// A table row: a label and a value cell carrying a class a reader (or a test) can find.
std::string row(const std::string& label, const std::string& value, const std::string& css_class = {}) {
    return "<tr><th>" + escape_html(label) + "</th><td class=\"n" + (css_class.empty() ? "" : " " + css_class) + "\">" + value + "</td></tr>";
}

std::string count_row(const std::string& label, long long count, const std::string& css_class, long long of = -1) {
    return row(label, "<span class=\"count\">" + std::to_string(count) + "</span>" + (of >= 0 ? percent(count, of) : std::string()), css_class);
}

std::string json_text(const nlohmann::json* object, const char* key) {
    if (!object || !object->is_object()) return {};
    const auto found = object->find(key);
    if (found == object->end()) return {};
    if (found->is_string()) return found->get<std::string>();
    if (found->is_boolean()) return found->get<bool>() ? "on" : "off";
    if (found->is_number()) return found->dump();
    return {};
}

std::optional<double> json_number(const nlohmann::json* object, std::initializer_list<const char*> path) {
    const nlohmann::json* at = object;
    for (const char* key : path) {
        if (!at || !at->is_object() || !at->contains(key)) return std::nullopt;
        at = &(*at)[key];
    }
    if (!at->is_number()) return std::nullopt;
    const double value = at->get<double>();
    return std::isfinite(value) ? std::optional<double>(value) : std::nullopt;
}

constexpr double k_warning_s = 0.2; // from a cue to a move, a person's

struct FighterCounts {
    long long orders = 0, queued = 0, performed = 0, refused = 0, expired = 0;
    long long strikes = 0, hits = 0, blocked_by_user = 0;
    long long user_strikes = 0, blocked = 0, slipped = 0, landed = 0, missed = 0, unfinished = 0, unseen = 0, blocks = 0, slips = 0,
              block_clips = 0;
    long long kept_off = 0; // blocked or slipped where the hand would have landed (on course)
    long long warned = 0;   // of those and the ones that landed: the hand's approach lasted a person's 0.2 s or more
    long long hit_reactions = 0, captured_hit_reactions = 0, hit_reaction_blows = 0;
    long long losses = 0;
    double lost_s = 0.0;
};

FighterCounts count(const FighterLog& fighter, double duration_s) {
    FighterCounts c;
    c.orders = static_cast<long long>(fighter.orders.size());
    for (const OrderRecord& order : fighter.orders) c.queued += order.queued;
    for (const OrderEnd& end : fighter.order_ends) {
        (end.how == OrderEnd::How::performed ? c.performed : end.how == OrderEnd::How::refused ? c.refused : c.expired) += 1;
    }
    c.strikes = static_cast<long long>(fighter.strikes.size());
    for (const StrikeRecord& strike : fighter.strikes) {
        c.hits += strike.hit;
        c.blocked_by_user += !strike.blocked_by.empty();
    }
    c.user_strikes = static_cast<long long>(fighter.user_strikes.size());
    for (const UserStrikeRecord& strike : fighter.user_strikes) {
        if (strike.outcome == "blocked") ++c.blocked;
        else if (strike.outcome == "slipped") ++c.slipped;
        else if (strike.outcome == "hit_by_user") ++c.landed;
        else if (strike.outcome == "missed") ++c.missed;
        else ++c.unfinished;
        c.unseen += !strike.detected;
        c.slips += strike.move == "slip";
        c.blocks += strike.move == "block" || strike.move == "block_clip" || strike.move == "synthesized";
        c.block_clips += strike.move == "block_clip";
        c.kept_off += strike.kept_off;
        c.warned += (strike.kept_off || strike.outcome == "hit_by_user") && strike.approach_s >= k_warning_s;
    }
    c.hit_reactions = fighter.hit_reactions;
    c.captured_hit_reactions = fighter.captured_hit_reactions;
    c.hit_reaction_blows = fighter.hit_reaction_blows;
    c.losses = static_cast<long long>(fighter.tracker_losses.size());
    for (const TrackerLoss& loss : fighter.tracker_losses) c.lost_s += (loss.back_s >= 0.0 ? loss.back_s : duration_s) - loss.lost_s;
    return c;
}

std::string orders_table(const FighterCounts& c) {
    return "<table class=\"orders\"><tr><th colspan=\"2\">orders</th></tr>" + count_row("ordered", c.orders, "n-orders") +
           count_row("of them queued (fighter busy)", c.queued, "n-queued") + count_row("performed", c.performed, "n-performed", c.orders) +
           count_row("refused", c.refused, "n-refused") + count_row("expired", c.expired, "n-expired") + "</table>";
}

std::string strikes_table(const FighterLog& fighter, const FighterCounts& c) {
    // Strikes and hits by what was struck: semantics, kind, height.
    std::map<std::string, std::pair<long long, long long>> by_kind;
    for (const StrikeRecord& strike : fighter.strikes) {
        std::string key = strike.command.empty() ? std::string("strike") : strike.command;
        for (const std::string* part : {&strike.kind, &strike.height}) {
            if (!part->empty() && *part != "none") key += " " + *part;
        }
        auto& entry = by_kind[key];
        entry.first += 1;
        entry.second += strike.hit;
    }
    std::string html = "<table class=\"strikes\"><tr><th>strikes</th><th class=\"n\">strikes</th><th class=\"n\">hits</th></tr>";
    for (const auto& [key, counts] : by_kind) {
        html += "<tr class=\"by-kind\"><td>" + escape_html(key) + "</td><td class=\"n\">" + std::to_string(counts.first) + "</td><td class=\"n\">" +
                std::to_string(counts.second) + percent(counts.second, counts.first) + "</td></tr>";
    }
    html += "<tr><th>all</th><td class=\"n n-strikes\">" + std::to_string(c.strikes) + "</td><td class=\"n n-hits\">" + std::to_string(c.hits) +
            percent(c.hits, c.strikes) + "</td></tr>";
    return html + "</table>";
}

std::string user_table(const FighterCounts& c) {
    const long long defended = c.blocked + c.slipped;
    return "<table class=\"user-strikes\"><tr><th colspan=\"2\">the user's strikes</th></tr>" + count_row("strikes", c.user_strikes, "n-user-strikes") +
           count_row("blocked", c.blocked, "n-blocked", c.user_strikes) + count_row("slipped", c.slipped, "n-slipped", c.user_strikes) +
           count_row("landed on the fighter", c.landed, "n-landed", c.user_strikes) + count_row("missed", c.missed, "n-missed", c.user_strikes) +
           (c.unfinished ? count_row("not ended when the events did", c.unfinished, "n-unfinished") : std::string()) +
           count_row("defended of those that would land", defended, "n-defended", defended + c.landed) +
           count_row("... counting only blocks and slips of blows on course", c.kept_off, "n-kept-off", c.kept_off + c.landed) +
           count_row("of those blows, ones whose hand came on for 0.2 s or more (the time a person needs to move)", c.warned, "n-warned",
                     c.kept_off + c.landed) +
           count_row("not seen coming", c.unseen, "n-unseen") + count_row("defences: blocks", c.blocks, "n-blocks") +
           count_row("of those, captured blocks", c.block_clips, "n-block-clips", c.blocks) +
           count_row("defences: slips", c.slips, "n-slips") +
           count_row("landed strikes answered by a hit reaction", c.hit_reaction_blows, "n-reaction-blows", c.landed) +
           count_row("hit reactions", c.hit_reactions, "n-hit-reactions") +
           count_row("of those, captured reactions", c.captured_hit_reactions, "n-captured-reactions", c.hit_reactions) + "</table>";
}

std::string fighter_title(const SessionLog& log, int index, const FighterLog& fighter) {
    std::string title = "Fighter " + std::to_string(index + 1);
    std::string names = json_text(log.start ? &*log.start : nullptr, "character");
    for (const CharacterSwitch& change : fighter.characters) names += (names.empty() ? "" : " → ") + change.name;
    return names.empty() ? title : title + " — " + names;
}

std::string fighter_section(const SessionLog& log, int index, const FighterLog& fighter, const RoomView& view, double duration_s, bool has_head_path) {
    const FighterCounts c = count(fighter, duration_s);
    std::string html = "<section class=\"fighter\" id=\"fighter-" + std::to_string(index + 1) + "\"><h2>" + escape_html(fighter_title(log, index, fighter)) + "</h2>";
    html += "<div class=\"tables\">" + orders_table(c) + strikes_table(fighter, c) + user_table(c) + "<table class=\"other\"><tr><th colspan=\"2\">other</th></tr>" +
            count_row("tracker losses", c.losses, "n-losses") + row("time without the head", fixed(c.lost_s, 1) + " s") +
            count_row("joint-limit violations", fighter.joint_limit_violations, "n-violations") + "</table></div>";
    html += "<h3>Timeline</h3>" + timeline_svg(fighter, duration_s);
    html += responses_section_html(fighter);
    std::vector<double> latency_s, speed_mps, overshoot_m, prediction_m;
    for (const OrderEnd& end : fighter.order_ends) {
        if (end.how == OrderEnd::How::performed && end.waited_s >= 0.0) latency_s.push_back(end.waited_s);
    }
    for (const StrikeRecord& strike : fighter.strikes) {
        if (strike.effector_speed_mps >= 0.0) speed_mps.push_back(strike.effector_speed_mps);
        if (strike.overshoot_m >= 0.0) overshoot_m.push_back(strike.overshoot_m);
        if (strike.prediction_error_m >= 0.0) prediction_m.push_back(strike.prediction_error_m);
    }
    html += "<div class=\"figures\"><div><h3>The room from above</h3>" + top_view_svg(fighter, view, has_head_path) + "</div><div><h3>Distributions</h3><div class=\"histograms\">" +
            histogram_svg(latency_s, {"command → strike start", "ms", 1000.0, "latency"}) +
            histogram_svg(speed_mps, {"effector speed at contact", "m/s", 1.0, "speed"}) +
            histogram_svg(overshoot_m, {"overshoot past the target (impacts)", "cm", 100.0, "overshoot"}) +
            histogram_svg(prediction_m, {"aim's prediction error at contact", "cm", 100.0, "prediction"}) + "</div></div></div>";
    return html + "</section>";
}

std::string other_fighters_table(const SessionLog& log, double duration_s) {
    std::string html = "<section class=\"other-fighters\"><h2>The other fighters</h2><table><tr><th>fighter</th><th class=\"n\">orders</th><th class=\"n\">performed</th>"
                       "<th class=\"n\">refused</th><th class=\"n\">expired</th><th class=\"n\">strikes</th><th class=\"n\">hits</th><th class=\"n\">user strikes</th>"
                       "<th class=\"n\">blocked</th><th class=\"n\">slipped</th><th class=\"n\">landed</th></tr>";
    int shown = 0;
    for (const auto& [index, fighter] : log.fighters) {
        if (shown++ < k_detailed_fighters) continue;
        const FighterCounts c = count(fighter, duration_s);
        html += "<tr class=\"fighter-row\"><td>" + std::to_string(index + 1) + "</td>";
        for (const long long n : {c.orders, c.performed, c.refused, c.expired, c.strikes, c.hits, c.user_strikes, c.blocked, c.slipped, c.landed}) {
            html += "<td class=\"n\">" + std::to_string(n) + "</td>";
        }
        html += "</tr>";
    }
    return html + "</table></section>";
}

} // namespace

std::string session_html(const SessionLog& log, const nlohmann::json* play_report, std::string_view source) {
    const nlohmann::json* start = log.start ? &*log.start : nullptr;
    const nlohmann::json* end = log.end ? &*log.end : nullptr;
    const double duration_s = json_number(end, {"duration_s"}).value_or(log.last_t_s);
    std::string html = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><meta name=\"viewport\" content=\"width=device-width\">"
                       "<title>kumite session" + (source.empty() ? std::string() : " — " + escape_html(source)) + "</title><style>" + k_page_style + k_style +
                       "</style></head><body>\n<h1>kumite session report</h1>";
    html += "<p class=\"source\">" + (source.empty() ? std::string("events of a bout") : "events: " + escape_html(source)) + " — " + std::to_string(log.lines) +
            " lines read" + (log.unknown_lines ? ", " + std::to_string(log.unknown_lines) + " of types this report does not show" : std::string()) + "</p>";
    if (log.stopped) html += "<p class=\"stopped\">Reading stopped at " + escape_html(*log.stopped) + ": this report shows what came before it.</p>";
    else if (!end) html += "<p class=\"stopped\">The events end without the bout's last line (bout_end): the bout was cut short or the file is incomplete.</p>";

    // The bout as a whole.
    FighterCounts total;
    for (const auto& [index, fighter] : log.fighters) {
        const FighterCounts c = count(fighter, duration_s);
        for (auto [sum, part] : {std::pair{&total.orders, c.orders}, {&total.performed, c.performed}, {&total.refused, c.refused}, {&total.expired, c.expired},
                                 {&total.strikes, c.strikes}, {&total.hits, c.hits}, {&total.blocked_by_user, c.blocked_by_user}, {&total.user_strikes, c.user_strikes}, {&total.blocked, c.blocked},
                                 {&total.slipped, c.slipped}, {&total.landed, c.landed}, {&total.missed, c.missed},
                                 {&total.hit_reactions, c.hit_reactions}, {&total.hit_reaction_blows, c.hit_reaction_blows}}) {
            *sum += part;
        }
        total.losses = std::max(total.losses, c.losses);
        total.lost_s = std::max(total.lost_s, c.lost_s);
    }
    html += "<h2>Summary</h2><div class=\"tables\"><table class=\"bout\">";
    html += row("duration", fixed(duration_s, 1) + " s", "duration");
    if (const std::optional<double> frames = json_number(end, {"frames"})) html += row("frames", fixed(*frames, 0));
    html += row("fighters", std::to_string(std::max<std::size_t>(log.fighters.size(), std::size_t(json_number(start, {"fighters"}).value_or(0.0)))));
    for (const auto& [label, key] : {std::pair{"character at the start", "character"}, {"aim", "aim"}, {"defence", "defence"}, {"tracker", "tracker"}, {"seed", "seed"}}) {
        if (const std::string value = json_text(start, key); !value.empty()) html += row(label, escape_html(value));
    }
    if (const std::string blocks = json_text(start, "blocks"); !blocks.empty()) {
        const std::optional<double> limit = json_number(start, {"block_speed_limit"});
        html += row("blocks", escape_html(blocks) + (limit ? ", the arm at most " + fixed(*limit, 2) + " times as fast as its clip" : std::string()), "blocks");
    }
    if (log.tracker_source) {
        html += row("user", "recorded person: " + escape_html(json_text(&*log.tracker_source, "capture")) + ", " +
                                fixed(json_number(&*log.tracker_source, {"distance_m"}).value_or(0.0), 2) + " m away");
    }
    // Frame times are measured on the wall clock: the report has them, the events (the same every run) do not.
    const nlohmann::json* timing = play_report;
    if (!json_number(timing, {"frame_time_us", "p99"})) {
        html += row("frame time", "not in the events: give the bout's report (--report REPORT.json)", "frame-time");
    } else if (const std::optional<double> p99 = json_number(timing, {"frame_time_us", "p99"})) {
        html += row("frame time", "p99 " + duration_text(*p99) + ", mean " + duration_text(json_number(timing, {"frame_time_us", "mean"}).value_or(0.0)) +
                                      ", max " + duration_text(json_number(timing, {"frame_time_us", "max"}).value_or(0.0)),
                    "frame-time");
    }
    if (const std::optional<double> missed = json_number(timing, {"missed_frames"})) html += row("frames over 16.7 ms", fixed(*missed, 0));
    html += count_row("tracker losses", total.losses, "n-losses") + row("time without the head", fixed(total.lost_s, 1) + " s");
    html += "</table><table class=\"totals\">" + count_row("orders", total.orders, "n-orders") + count_row("performed", total.performed, "n-performed", total.orders) +
            count_row("refused", total.refused, "n-refused") + count_row("expired", total.expired, "n-expired");
    if (const std::optional<double> waiting = json_number(end, {"orders_waiting_at_end"})) html += row("waiting at the end", fixed(*waiting, 0));
    html += count_row("strikes", total.strikes, "n-strikes") + count_row("hits", total.hits, "n-hits", total.strikes);
    // The user's guard in the fight (user_guard.enabled): the strikes it stopped, when there were any.
    if (total.blocked_by_user > 0) html += count_row("blocked by the user's guard", total.blocked_by_user, "n-blocked-by-user", total.strikes);
    html +=
            count_row("the user's strikes", total.user_strikes, "n-user-strikes") + count_row("blocked", total.blocked, "n-blocked", total.user_strikes) +
            count_row("slipped", total.slipped, "n-slipped", total.user_strikes) + count_row("landed", total.landed, "n-landed", total.user_strikes) +
            count_row("missed", total.missed, "n-missed", total.user_strikes) +
            count_row("hit reactions", total.hit_reactions, "n-hit-reactions") +
            count_row("landed strikes answered", total.hit_reaction_blows, "n-reaction-blows", total.landed) + "</table></div>";
    html += motion_html(end);

    const RoomView view = room_view(log);
    const std::string head_path = head_path_svg(log, view);
    html += "<svg width=\"0\" height=\"0\" style=\"position:absolute\" aria-hidden=\"true\"><defs>" + head_path + "</defs></svg>";
    if (log.fighters.empty()) html += "<p>No fighter events.</p>";
    else html += "<h3>Legend</h3>" + timeline_legend_html() + top_view_legend_html();
    int shown = 0;
    for (const auto& [index, fighter] : log.fighters) {
        if (shown++ >= k_detailed_fighters) break;
        html += fighter_section(log, index, fighter, view, duration_s, !head_path.empty());
    }
    if (static_cast<int>(log.fighters.size()) > k_detailed_fighters) html += other_fighters_table(log, duration_s);
    return html + "\n</body></html>\n";
}

} // namespace kumite::report
