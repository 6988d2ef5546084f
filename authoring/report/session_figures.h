#pragma once
// The session report's figures, as inline SVG: a fighter's timeline across the bout and the room seen from above.
// Every mark has a class naming what it is (tl-strike, tv-target, ...) and a <title> with its details.

#include "session_log.h"

#include <string>

namespace kumite::report {

// The floor area the top views show (world x right, z down the page, metres), the same for every fighter so that
// the user's head path is drawn once and reused.
struct RoomView {
    double min_x = -1.0, min_z = -1.0, metres = 2.0; // the square shown
    double size_px = 380.0, margin_px = 44.0;
    double x_px(double x) const { return margin_px + (x - min_x) / metres * size_px; }
    double z_px(double z) const { return margin_px + (z - min_z) / metres * size_px; }
};
RoomView room_view(const SessionLog& log);

// <path id="head-path"> of the user's head over the floor (thinned for drawing; empty without track lines), to be
// placed once in the page's <defs>.
std::string head_path_svg(const SessionLog& log, const RoomView& view);

// The fighter's orders, strikes, the user's strikes and the defences, tracker losses and character switches on a
// time axis in seconds, wrapped in bands of at most k_band_s.
inline constexpr double k_band_s = 300.0;
std::string timeline_svg(const FighterLog& fighter, double duration_s);

// The room from above: the user's head path, the fighter's position, each strike's target (hit or missed) and the
// aim's prediction error as a segment from the target to where the part aimed at was at the contact.
std::string top_view_svg(const FighterLog& fighter, const RoomView& view, bool has_head_path);

// The legends of the two figures, as HTML.
std::string timeline_legend_html();
std::string top_view_legend_html();

} // namespace kumite::report
