// The session report's timeline and top view (session_figures.h).

#include "session_figures.h"

#include "svg_plot.h"

#include <algorithm>
#include <cmath>

namespace kumite::report {

namespace {

enum class Glyph { hit, miss, order, order_queued, refused, expired, blocked, slipped, landed, user_missed, unknown, block, slip };

// A mark centred at (x, y), with its class and tooltip. Shapes differ as well as colours.
std::string glyph(Glyph kind, double x, double y, const std::string& css_class, const std::string& title) {
    const std::string at = px(x) + "," + px(y);
    const std::string tip = "<title>" + escape_html(title) + "</title>";
    const std::string cls = " class=\"" + css_class + "\"";
    switch (kind) {
    case Glyph::hit:
        return "<circle" + cls + " cx=\"" + px(x) + "\" cy=\"" + px(y) + "\" r=\"4.5\" fill=\"" + colour::blue + "\">" + tip + "</circle>";
    case Glyph::miss:
        return "<path" + cls + " d=\"M" + px(x - 4) + "," + px(y - 4) + "l8,8m0,-8l-8,8\" stroke=\"" + colour::vermillion +
               "\" stroke-width=\"2.2\">" + tip + "</path>";
    case Glyph::order:
    case Glyph::order_queued:
        return "<path" + cls + " d=\"M" + at + "m-4.5,-5h9l-4.5,8z\" " +
               (kind == Glyph::order ? std::string("fill=\"") + colour::ink + "\"" : std::string("fill=\"white\" stroke=\"") + colour::ink + "\"") + ">" +
               tip + "</path>";
    case Glyph::refused:
        return "<path" + cls + " d=\"M" + px(x - 3.5) + "," + px(y - 3.5) + "l7,7m0,-7l-7,7\" stroke=\"" + colour::purple + "\" stroke-width=\"2\">" + tip +
               "</path>";
    case Glyph::expired:
        return "<circle" + cls + " cx=\"" + px(x) + "\" cy=\"" + px(y) + "\" r=\"3.5\" fill=\"white\" stroke=\"" + colour::orange +
               "\" stroke-width=\"2\">" + tip + "</circle>";
    case Glyph::blocked:
        return "<rect" + cls + " x=\"" + px(x - 4) + "\" y=\"" + px(y - 4) + "\" width=\"8\" height=\"8\" fill=\"" + colour::green + "\">" + tip + "</rect>";
    case Glyph::slipped:
        return "<path" + cls + " d=\"M" + at + "m0,-5.5l5,5.5l-5,5.5l-5,-5.5z\" fill=\"" + colour::sky + "\">" + tip + "</path>";
    case Glyph::landed:
        return "<path" + cls + " d=\"M" + at + "m0,-5.5l5,9h-10z\" fill=\"" + colour::vermillion + "\">" + tip + "</path>";
    case Glyph::user_missed:
        return "<circle" + cls + " cx=\"" + px(x) + "\" cy=\"" + px(y) + "\" r=\"3.5\" fill=\"white\" stroke=\"" + colour::grey + "\" stroke-width=\"1.5\">" +
               tip + "</circle>";
    case Glyph::unknown:
        return "<circle" + cls + " cx=\"" + px(x) + "\" cy=\"" + px(y) + "\" r=\"2\" fill=\"" + colour::grey + "\">" + tip + "</circle>";
    case Glyph::block:
    case Glyph::slip:
        return "<rect" + cls + " x=\"" + px(x - 1.5) + "\" y=\"" + px(y - 6) + "\" width=\"3\" height=\"12\" fill=\"" +
               (kind == Glyph::block ? colour::green : colour::sky) + "\">" + tip + "</rect>";
    }
    return {};
}

std::string seconds(double t_s) { return fixed(t_s, 2) + " s"; }

// "hit", "miss", or what of the user's guard blocked it.
std::string strike_result(const StrikeRecord& strike) {
    if (!strike.blocked_by.empty()) return "blocked by the user's " + strike.blocked_by;
    return strike.hit ? "hit" : "miss";
}

std::string strike_words(const StrikeRecord& strike) {
    std::string words = strike.command;
    for (const std::string* part : {&strike.kind, &strike.height, &strike.side}) {
        if (!part->empty() && *part != "none" && *part != "any") words += " " + *part;
    }
    return words;
}

Glyph user_strike_glyph(const std::string& outcome) {
    if (outcome == "blocked") return Glyph::blocked;
    if (outcome == "slipped") return Glyph::slipped;
    if (outcome == "hit_by_user") return Glyph::landed;
    if (outcome == "missed") return Glyph::user_missed;
    return Glyph::unknown;
}

std::string outcome_words(const std::string& outcome) {
    if (outcome == "hit_by_user") return "landed";
    if (outcome == "unknown" || outcome.empty()) return "not ended";
    return outcome;
}

constexpr const char* k_rows[] = {"orders", "strikes", "user strikes", "defences", "tracker", "character"};
constexpr int k_row_count = 6;

} // namespace

RoomView room_view(const SessionLog& log) {
    std::vector<double> xs, zs;
    auto take = [&](const RoomPoint& p) { xs.push_back(p.x), zs.push_back(p.z); };
    for (const RoomPoint& p : log.head_path) take(p);
    for (const auto& [index, fighter] : log.fighters) {
        for (const RoomPoint& p : fighter.positions) take(p);
        for (const StrikeRecord& strike : fighter.strikes) {
            if (strike.target) take(*strike.target);
        }
    }
    RoomView view;
    if (xs.empty()) return view;
    // The middle 99% of what was there: a glitch far away does not shrink the room to a dot.
    auto range = [](std::vector<double>& values) {
        std::sort(values.begin(), values.end());
        const std::size_t n = values.size();
        return std::pair{values[std::size_t(0.005 * double(n - 1))], values[std::size_t(0.995 * double(n - 1))]};
    };
    const auto [lo_x, hi_x] = range(xs);
    const auto [lo_z, hi_z] = range(zs);
    view.metres = std::clamp(std::max(hi_x - lo_x, hi_z - lo_z) + 0.8, 2.0, 40.0);
    view.min_x = (lo_x + hi_x) / 2.0 - view.metres / 2.0;
    view.min_z = (lo_z + hi_z) / 2.0 - view.metres / 2.0;
    return view;
}

std::string head_path_svg(const SessionLog& log, const RoomView& view) {
    if (log.head_path.empty()) return {};
    // Thinned for drawing: a point when the head has moved 2 cm on the floor, at most ~4000 points.
    std::vector<const RoomPoint*> kept;
    for (const RoomPoint& p : log.head_path) {
        if (kept.empty() || std::hypot(p.x - kept.back()->x, p.z - kept.back()->z) >= 0.02) kept.push_back(&p);
    }
    const std::size_t stride = kept.size() / 4000 + 1;
    std::string d;
    for (std::size_t i = 0; i < kept.size(); i += stride) {
        d += (i == 0 ? "M" : "L") + px(view.x_px(kept[i]->x)) + "," + px(view.z_px(kept[i]->z));
    }
    if (kept.size() == 1) d += "h0.1";
    return "<path id=\"head-path\" d=\"" + d + "\" fill=\"none\" stroke=\"" + colour::ink + "\" stroke-opacity=\"0.35\" stroke-width=\"1.2\"/>";
}

std::string timeline_svg(const FighterLog& fighter, double duration_s) {
    constexpr double width = 960.0, left = 96.0, right = 16.0, row_h = 20.0, axis_h = 30.0, gap = 14.0;
    const double plot_w = width - left - right;
    duration_s = std::max(duration_s, 1.0);
    const int bands = std::max(1, static_cast<int>(std::ceil(duration_s / k_band_s - 1e-9)));
    const double band_s = bands == 1 ? duration_s : k_band_s;
    const double band_h = row_h * k_row_count + axis_h;
    const double height = bands * band_h + (bands - 1) * gap + 6.0;
    std::string svg = "<svg class=\"timeline\" width=\"" + px(width) + "\" height=\"" + px(height) + "\" viewBox=\"0 0 " + px(width) + " " + px(height) +
                      "\" role=\"img\" aria-label=\"timeline\">";
    // Where a time goes: its band, and x within it; y of a row in that band.
    auto band_of = [&](double t) { return std::clamp(static_cast<int>(t / band_s), 0, bands - 1); };
    auto x_of = [&](double t) { return left + std::clamp((t - band_of(t) * band_s) / band_s, 0.0, 1.0) * plot_w; };
    auto y_of = [&](double t, int row) { return 4.0 + band_of(t) * (band_h + gap) + row * row_h + row_h / 2.0; };

    for (int band = 0; band < bands; ++band) {
        const double top = 4.0 + band * (band_h + gap);
        const double from = band * band_s, to = std::min(duration_s, from + band_s);
        for (int row = 0; row < k_row_count; ++row) {
            const double y = top + row * row_h;
            if (row % 2 == 0) svg += "<rect x=\"" + px(left) + "\" y=\"" + px(y) + "\" width=\"" + px(plot_w) + "\" height=\"" + px(row_h) + "\" fill=\"#f3f4f6\"/>";
            svg += "<text x=\"" + px(left - 8) + "\" y=\"" + px(y + row_h / 2 + 4) + "\" class=\"label\" text-anchor=\"end\">" + k_rows[row] + "</text>";
        }
        const double axis_y = top + row_h * k_row_count;
        const double band_w = (to - from) / band_s * plot_w;
        svg += "<line x1=\"" + px(left) + "\" y1=\"" + px(axis_y) + "\" x2=\"" + px(left + band_w) + "\" y2=\"" + px(axis_y) + "\" class=\"axis\"/>";
        const Ticks ticks = nice_ticks(from, to, 10);
        for (int i = 0; i < ticks.count; ++i) {
            const double t = ticks.at(i);
            if (t > to + 1e-9) break;
            const double x = left + (t - from) / band_s * plot_w;
            svg += "<line x1=\"" + px(x) + "\" y1=\"" + px(axis_y) + "\" x2=\"" + px(x) + "\" y2=\"" + px(axis_y + 4) + "\" class=\"axis\"/>";
            svg += "<text x=\"" + px(x) + "\" y=\"" + px(axis_y + 16) + "\" class=\"tick\" text-anchor=\"middle\">" + fixed(t, ticks.step < 1 ? 1 : 0) + "</text>";
        }
        svg += "<text x=\"" + px(left - 24) + "\" y=\"" + px(axis_y + 16) + "\" class=\"label\" text-anchor=\"end\">time (s)</text>";
    }

    for (const TrackerLoss& loss : fighter.tracker_losses) {
        // A loss drawn in each band it crosses.
        const double end = loss.back_s >= 0.0 ? loss.back_s : duration_s;
        for (double from = loss.lost_s; from < end - 1e-9;) {
            const double to = std::min(end, (band_of(from) + 1) * band_s);
            svg += "<rect class=\"tl-lost\" x=\"" + px(x_of(from)) + "\" y=\"" + px(y_of(from, 4) - 6) + "\" width=\"" +
                   px(std::max(1.5, (to - from) / band_s * plot_w)) + "\" height=\"12\" fill=\"" + colour::grey + "\"><title>tracker lost " +
                   seconds(loss.lost_s) + (loss.back_s >= 0.0 ? " to " + seconds(loss.back_s) : std::string(" until the end")) + "</title></rect>";
            if (bands == 1 || to <= from) break;
            from = to;
        }
    }
    for (const OrderRecord& order : fighter.orders) {
        svg += glyph(order.queued ? Glyph::order_queued : Glyph::order, x_of(order.t_s), y_of(order.t_s, 0), "tl-order",
                     seconds(order.t_s) + " order " + order.command + (order.queued ? " (queued: the fighter was busy)" : ""));
    }
    for (const OrderEnd& end : fighter.order_ends) {
        if (end.how == OrderEnd::How::performed) continue;
        const bool refused = end.how == OrderEnd::How::refused;
        svg += glyph(refused ? Glyph::refused : Glyph::expired, x_of(end.t_s), y_of(end.t_s, 0), refused ? "tl-refused" : "tl-expired",
                     seconds(end.t_s) + (refused ? " order refused: " : " order expired: ") + end.why);
    }
    for (const StrikeRecord& strike : fighter.strikes) {
        std::string title = seconds(strike.t_s) + " " + strike_words(strike) + ": " + strike_result(strike);
        if (strike.contact_error_m >= 0.0) title += ", contact error " + fixed(strike.contact_error_m * 100.0, 1) + " cm";
        if (!strike.clip.empty()) title += " (" + strike.clip + ")";
        svg += glyph(strike.hit ? Glyph::hit : Glyph::miss, x_of(strike.t_s), y_of(strike.t_s, 1), strike.hit ? "tl-strike hit" : "tl-strike miss", title);
    }
    for (const UserStrikeRecord& strike : fighter.user_strikes) {
        const double t = strike.end_s >= 0.0 ? strike.end_s : strike.seen_s;
        svg += glyph(user_strike_glyph(strike.outcome), x_of(t), y_of(t, 2), "tl-user-strike",
                     seconds(t) + " user's " + strike.hand + " hand at the " + strike.aimed_at + ": " + outcome_words(strike.outcome) +
                         (strike.detected ? "" : " (not seen coming)"));
        if (strike.seen_s >= 0.0 && (strike.move == "block" || strike.move == "slip" || strike.move == "block_clip" || strike.move == "synthesized")) {
            svg += glyph(strike.move == "slip" ? Glyph::slip : Glyph::block, x_of(strike.seen_s), y_of(strike.seen_s, 3), "tl-defence",
                         seconds(strike.seen_s) + " defence: " + strike.move);
        }
    }
    for (const CharacterSwitch& change : fighter.characters) {
        const double x = x_of(change.t_s), y = y_of(change.t_s, 5);
        const bool near_end = x > left + plot_w - 80.0; // the name to the left of the mark, inside the axes
        svg += "<g class=\"tl-character\"><line x1=\"" + px(x) + "\" y1=\"" + px(y - 7) + "\" x2=\"" + px(x) + "\" y2=\"" + px(y + 7) + "\" stroke=\"" +
               colour::ink + "\"/><text x=\"" + px(near_end ? x - 3 : x + 3) + "\" y=\"" + px(y + 4) + "\" class=\"tick\"" +
               (near_end ? " text-anchor=\"end\"" : "") + ">" + escape_html(change.name) + "</text><title>" +
               seconds(change.t_s) + " character " + escape_html(change.name) + "</title></g>";
    }
    return svg + "</svg>";
}

std::string top_view_svg(const FighterLog& fighter, const RoomView& view, bool has_head_path) {
    const double size = view.size_px + 2.0 * view.margin_px;
    std::string svg = "<svg class=\"top-view\" width=\"" + px(size) + "\" height=\"" + px(size) + "\" viewBox=\"0 0 " + px(size) + " " + px(size) +
                      "\" role=\"img\" aria-label=\"the room from above\">";
    const double lo = view.margin_px, hi = view.margin_px + view.size_px;
    svg += "<rect x=\"" + px(lo) + "\" y=\"" + px(lo) + "\" width=\"" + px(view.size_px) + "\" height=\"" + px(view.size_px) + "\" fill=\"#fafafa\" class=\"axis\"/>";
    // Metre grid and labels: x along the bottom, z up the left (z grows down the page: seen from above, Y up).
    const Ticks x_ticks = nice_ticks(view.min_x, view.min_x + view.metres, 6);
    const Ticks z_ticks = nice_ticks(view.min_z, view.min_z + view.metres, 6);
    const int decimals = x_ticks.step < 1.0 ? 1 : 0;
    for (int i = 0; i < x_ticks.count; ++i) {
        const double x = view.x_px(x_ticks.at(i));
        if (x > hi + 0.5) break;
        svg += "<line x1=\"" + px(x) + "\" y1=\"" + px(lo) + "\" x2=\"" + px(x) + "\" y2=\"" + px(hi) + "\" class=\"grid\"/>";
        svg += "<text x=\"" + px(x) + "\" y=\"" + px(hi + 16) + "\" class=\"tick\" text-anchor=\"middle\">" + fixed(x_ticks.at(i), decimals) + "</text>";
    }
    for (int i = 0; i < z_ticks.count; ++i) {
        const double z = view.z_px(z_ticks.at(i));
        if (z > hi + 0.5) break;
        svg += "<line x1=\"" + px(lo) + "\" y1=\"" + px(z) + "\" x2=\"" + px(hi) + "\" y2=\"" + px(z) + "\" class=\"grid\"/>";
        svg += "<text x=\"" + px(lo - 5) + "\" y=\"" + px(z + 4) + "\" class=\"tick\" text-anchor=\"end\">" + fixed(z_ticks.at(i), decimals) + "</text>";
    }
    svg += "<text x=\"" + px((lo + hi) / 2) + "\" y=\"" + px(hi + 34) + "\" class=\"label\" text-anchor=\"middle\">x (m)</text>";
    svg += "<text x=\"14\" y=\"" + px((lo + hi) / 2) + "\" class=\"label\" text-anchor=\"middle\" transform=\"rotate(-90 14 " + px((lo + hi) / 2) +
           ")\">z (m)</text>";
    // Drawn inside a nested viewport that clips: a far-away glitch stays out of the axes.
    svg += "<svg x=\"" + px(lo) + "\" y=\"" + px(lo) + "\" width=\"" + px(view.size_px) + "\" height=\"" + px(view.size_px) + "\" viewBox=\"" + px(lo) +
           " " + px(lo) + " " + px(view.size_px) + " " + px(view.size_px) + "\">";
    // The fighter: where it stood over the bout, and where it ended.
    if (!fighter.positions.empty()) {
        std::string d;
        for (std::size_t i = 0; i < fighter.positions.size(); ++i) {
            d += (i == 0 ? "M" : "L") + px(view.x_px(fighter.positions[i].x)) + "," + px(view.z_px(fighter.positions[i].z));
        }
        svg += "<path d=\"" + d + "\" fill=\"none\" stroke=\"" + colour::orange + "\" stroke-opacity=\"0.6\" stroke-width=\"1.2\"/>";
    }
    if (has_head_path) svg += "<use href=\"#head-path\" class=\"tv-head-path\"/>"; // over the fighter's path
    if (!fighter.positions.empty()) {
        const RoomPoint& last = fighter.positions.back();
        svg += "<rect class=\"tv-fighter\" x=\"" + px(view.x_px(last.x) - 6) + "\" y=\"" + px(view.z_px(last.z) - 6) +
               "\" width=\"12\" height=\"12\" fill=\"" + colour::orange + "\" stroke=\"" + colour::ink + "\"><title>the fighter at the end (" +
               fixed(last.x, 2) + ", " + fixed(last.z, 2) + ") m</title></rect>";
    }
    for (const StrikeRecord& strike : fighter.strikes) {
        if (!strike.target) continue;
        const double x = view.x_px(strike.target->x), z = view.z_px(strike.target->z);
        if (strike.aimed_point_at_contact) {
            svg += "<line class=\"tv-error\" x1=\"" + px(x) + "\" y1=\"" + px(z) + "\" x2=\"" + px(view.x_px(strike.aimed_point_at_contact->x)) + "\" y2=\"" +
                   px(view.z_px(strike.aimed_point_at_contact->z)) + "\" stroke=\"" + colour::purple + "\" stroke-width=\"1.5\"/>";
        }
        std::string title = seconds(strike.t_s) + " " + strike_words(strike) + ": " + strike_result(strike);
        if (strike.prediction_error_m >= 0.0) title += ", the " + strike.aim + " aim was " + fixed(strike.prediction_error_m * 100.0, 1) + " cm off";
        svg += glyph(strike.hit ? Glyph::hit : Glyph::miss, x, z, strike.hit ? "tv-target hit" : "tv-target miss", title);
    }
    return svg + "</svg></svg>";
}

std::string timeline_legend_html() {
    auto item = [](Glyph kind, const char* words) {
        return "<span class=\"key\"><svg width=\"14\" height=\"14\" viewBox=\"0 0 14 14\">" + glyph(kind, 7, 7, "key", words) + "</svg>" + words + "</span>";
    };
    return "<p class=\"legend\">" + item(Glyph::order, "order") + item(Glyph::order_queued, "order queued") + item(Glyph::refused, "order refused") +
           item(Glyph::expired, "order expired") + item(Glyph::hit, "strike hit") + item(Glyph::miss, "strike missed") +
           item(Glyph::blocked, "user's strike blocked") + item(Glyph::slipped, "slipped") + item(Glyph::landed, "landed") +
           item(Glyph::user_missed, "missed") + item(Glyph::block, "defence: block") + item(Glyph::slip, "defence: slip") +
           "<span class=\"key\"><svg width=\"14\" height=\"14\"><rect x=\"1\" y=\"3\" width=\"12\" height=\"8\" fill=\"" + colour::grey +
           "\"/></svg>tracker lost</span></p>";
}

std::string top_view_legend_html() {
    auto item = [](Glyph kind, const char* words) {
        return "<span class=\"key\"><svg width=\"14\" height=\"14\" viewBox=\"0 0 14 14\">" + glyph(kind, 7, 7, "key", words) + "</svg>" + words + "</span>";
    };
    return std::string("<p class=\"legend\"><span class=\"key\"><svg width=\"18\" height=\"14\"><line x1=\"1\" y1=\"7\" x2=\"17\" y2=\"7\" stroke=\"") +
           colour::ink + "\" stroke-opacity=\"0.35\" stroke-width=\"1.5\"/></svg>user's head</span><span class=\"key\"><svg width=\"14\" height=\"14\"><rect x=\"1\" y=\"1\" "
           "width=\"12\" height=\"12\" fill=\"" + colour::orange + "\" stroke=\"" + colour::ink + "\"/></svg>fighter (its path in orange)</span>" +
           item(Glyph::hit, "target, hit") + item(Glyph::miss, "target, missed") + "<span class=\"key\"><svg width=\"18\" height=\"14\"><line x1=\"1\" y1=\"7\" " +
           "x2=\"17\" y2=\"7\" stroke=\"" + colour::purple + "\" stroke-width=\"1.5\"/></svg>target → where the head was at the contact</span></p>";
}

} // namespace kumite::report
