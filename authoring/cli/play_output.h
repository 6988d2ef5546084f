#pragma once
// What `kumite play` writes about a bout besides the motion: one JSON object per event (docs/reports.md, "What a
// bout writes"), the lines that frame the bout (bout_start, bout_end) and sample the room (track: the user's head every
// k_track_period_s; fighter_position: where a fighter stands, on the floor, whenever it moved k_position_step_m),
// the report, and the user's recording. The session report (authoring/report) is drawn from these lines alone.

#include "kumite/runtime/bout.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace kumite::cli {

inline constexpr double k_track_period_s = 0.1;
inline constexpr double k_position_step_m = 0.05;

// How the bout was started, as the command line said it.
struct PlaySetup {
    std::string tracker;
    std::string database;
    long long seed = 1;
};

nlohmann::json play_event_json(const Bout& bout, const BoutEvent& bout_event);
nlohmann::json play_report_json(const Bout& bout);
nlohmann::json bout_start_json(const Bout& bout, const PlaySetup& setup);
nlohmann::json bout_end_json(const Bout& bout);
// What the user is when it is a recorded person (else none): which capture, placed where, and how far it got.
std::optional<nlohmann::json> tracker_source_json(const Bout& bout);
// One line of the user's recording: t, head, hands (nan when a hand is not tracked); nothing while the tracker has
// no head (a gap, as a replay reads it).
void write_user_line(std::ostream& out, const Bout& bout);

// A drill's part as it starts (a drill_part line), when the bout runs a drill.
class DrillPartWatch {
public:
    std::optional<nlohmann::json> changed(const Bout& bout);
private:
    int m_part = -1;
};
// The drill as it was run: its name and parts (their times, levels, attacks).
nlohmann::json drill_report_json(const Bout& bout);

// The room over time, thinned: the head at a fixed period, each fighter when it has moved.
class RoomSampler {
public:
    void sample(const Bout& bout, std::vector<nlohmann::json>& lines); // appends this frame's lines, if any
private:
    double m_next_track_s = 0.0;
    std::vector<Eigen::Vector3d> m_last_position;
};

} // namespace kumite::cli
