#pragma once
// The clip the fighter plays between strikes (fighter.h): the guard looped, a step (possibly shortened, its feet
// locked while planted, the guard's arms kept up), blended in from the pose shown when it started. Owns: the clip,
// when it started, its placement on the floor, the step's scale, the feet's pins and their release, the blend's
// start frame, the guard's arms, two scratch frames. Touches: the body (writes its MIR frame and pose). Reads: the
// database.

#include "fighter/character_body.h"

#include "kumite/core/heading_frame.h"
#include "kumite/core/mir_edit.h"
#include "kumite/core/retrieval.h"

#include <array>

namespace kumite {

class MotionPlayer {
public:
    // `guard_clip`: whose first frame's arms a step keeps.
    MotionPlayer(const MotionDatabaseView& db, int guard_clip);

    // Plays `clip` from `t_s`, blended in from `from` over the blend time, placed on the floor on `align_on`; a step
    // scaled by `step_scale` moves the hips that share of its way (the feet locked while planted). With
    // `guard_arms` the arms are the guard's, carried on the clip's chest (a fighter steps with its guard up).
    void start(int clip, double t_s, const MirFrame& from, const HeadingFrame& align_on, double leg_length, double step_scale = 1.0,
               bool guard_arms = false);
    void skip_blend() { m_blend_start_s = -1e9; } // the clip shows at once
    // The clip at `t_s` onto the body (its MIR frame and pose), the feet locked on a shortened step.
    void play(double t_s, CharacterBody& body, double blend_s);

    int clip() const { return m_clip; }
    bool over(double t_s) const; // its last frame is reached
    // This frame's foot pins (a shortened step's planted feet): what the defence's edits keep.
    const LimbPins& pins() const { return m_pins; }
    // Frames kept here that hold a whole MIR frame (for sizing: CharacterBody).
    std::array<MirFrame*, 3> frames() { return {&m_clip_frame, &m_next_frame, &m_blend_from}; }

private:
    void lock_feet(double t_s, int pose, CharacterBody& body);

    const MotionDatabaseView& m_db;
    int m_clip = -1;
    double m_clip_start_s = 0.0;
    FloorAlignment m_clip_to_world;
    double m_clip_scale = 1.0; // horizontal scale of the clip's hip path (shortened steps)
    bool m_guard_arms = false; // the clip's arms replaced by the guard's
    MirFrame m_guard_frame;    // the guard clip's first frame
    Eigen::Vector3d m_clip_hip_start = Eigen::Vector3d::Zero();
    std::array<bool, 2> m_foot_pinned{}; // [left, right]
    std::array<Eigen::Vector3d, 2> m_foot_pin{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    std::array<Eigen::Vector3d, 2> m_foot_release_offset{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    std::array<double, 2> m_foot_release_s{-1e9, -1e9};
    LimbPins m_pins;
    MirFrame m_blend_from;
    double m_blend_start_s = -1e9;
    MirFrame m_clip_frame, m_next_frame; // scratch
};

} // namespace kumite
