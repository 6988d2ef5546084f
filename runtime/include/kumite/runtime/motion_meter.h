#pragma once
// The fighters' motion measured from outside, every frame: the fastest wrist,
// ankle, elbow and knee in each kind of move (a frame's kind: the defence's move when one shows, else the strike's
// kind while striking, else the state), and the distance kept to the user's head between strikes (rest and
// approach, pelvis to head on the floor). A frame where a fighter changed character is not measured (another
// skeleton). Fixed memory: sized for the fighters at construction, nothing allocated after.

#include "kumite/runtime/fighter.h"
#include "kumite/runtime/joint_speeds.h"
#include "kumite/runtime/value_histogram.h"

#include <array>
#include <vector>

namespace kumite {

class MotionMeter {
public:
    explicit MotionMeter(int fighters);

    // A fighter after its step at `t_s` (its pose on the character whose anatomy is `anatomy`), the user's head.
    void measure(int fighter_index, double t_s, const Fighter& fighter, const MotionDatabaseView& db, const RestAnatomy& anatomy,
                 const Eigen::Vector3d* head);

    // The fastest of all fighters, per kind, and how many frames were of each kind.
    const std::array<JointSpeeds, k_move_kind_count>& fastest() const { return m_fastest; }
    const std::array<long long, k_move_kind_count>& frames() const { return m_frames; }
    JointSpeeds fastest_overall() const;
    // When the fastest wrist and ankle of each kind were measured (bout time, s; -1 none): where to look.
    struct PeakTimes {
        double wrist_at_s = -1.0, ankle_at_s = -1.0;
    };
    const std::array<PeakTimes, k_move_kind_count>& peak_times() const { return m_peak_times; }
    // Between strikes: the distance to the user's head on the floor, metres and leg lengths of the character.
    const ValueHistogram& distance_m() const { return m_distance_m; }
    const ValueHistogram& distance_legs() const { return m_distance_legs; }

    // The kind of move a fighter's frame is.
    static MoveKind move_kind(const Fighter& fighter, const MotionDatabaseView& db);

private:
    struct Last {
        bool valid = false;
        int character = -1;
        double t_s = 0.0;
        LimbSample sample;
    };
    std::vector<Last> m_last;
    std::array<JointSpeeds, k_move_kind_count> m_fastest{};
    std::array<long long, k_move_kind_count> m_frames{};
    std::array<PeakTimes, k_move_kind_count> m_peak_times{};
    ValueHistogram m_distance_m{1e-3, 100.0}, m_distance_legs{1e-3, 100.0};
};

} // namespace kumite
