#pragma once
// A captured block played on the fighter's arm (fighter_defence.h, block_clips.h): when a block starts, the captured
// clip that meets the fist's course (if one fits and its elbow can put the forearm there); each frame the clip's
// arm at the played frame, timed by the fist, its wrist offset onto the course; the arm held to a speed (the clip's
// times the limit, and never faster than the clip in the hold and the way back); the arm's speed measured for the
// block's event. Owns: the database's block clips, the one chosen, how far it has played, the arm shown last frame
// (relative to the shoulder) and whether it was held back. Touches: the defence (use_block_clip, note_arm_speed).

#include "kumite/core/mir.h"
#include "kumite/core/rest_anatomy.h"
#include "kumite/runtime/block_clips.h"
#include "kumite/runtime/defence.h"

#include <Eigen/Core>

#include <span>

namespace kumite {

class CapturedBlockArm {
public:
    explicit CapturedBlockArm(const MotionDatabaseView& db) : m_clips(db) {}

    // Before the defence's update: a block that started last frame (shown then at weight 0) measures its first step
    // from the arm shown then (`defender`, at `shown_s`).
    void measure_from_shown(const Defence& defence, const DefenderBody& defender, double shown_s);
    // A block just started (the defence's): a captured one instead when one fits. `mir` is the frame shown (the
    // elbow's swivel reference), `heading_yaw_rad` the fighter's heading.
    void start(Defence& defence, const RestAnatomy& anatomy, const DefenderBody& defender, const MirFrame& mir, double heading_yaw_rad, double now_s);

    // The arm was held back last frame and is not where the blend put it: it goes on to the guard at the clip's speed.
    bool lagging() const { return m_lagging; }
    void forget_lag() { m_lagging = false; }
    // The wrist (relative to the shoulder, world axes) asked this frame: the clip's arm over `frame` (the shown frame
    // with the block's edits: the clip's arm is written into it), offset onto the course, blended from the guard's
    // wrist by `weight`; `bend` (the elbow's) turned towards the clip's. `before`: the undefended pose's positions.
    Eigen::Vector3d clip_wrist(const Defence& defence, const RestAnatomy& anatomy, std::span<const Eigen::Vector3d> before, double weight,
                               double heading_yaw_rad, double now_s, MirFrame& frame, Eigen::Vector3d& bend);
    // `wrist` and `bend` held to the clip's speed times `speed_ratio` (0: no limit) since the arm shown last frame;
    // never faster than the clip once the fist is past or over (the hold and the release) or when `lagging`.
    void limit_speed(const Defence& defence, const LimbChain& chain, const Eigen::Vector3d& reference, double swivel, bool lagging, double now_s,
                     Eigen::Vector3d& wrist, Eigen::Vector3d& bend);
    // The blocking arm as shown this frame (world): its speeds told to the defence, kept for the next.
    struct ShownArm {
        Eigen::Vector3d shoulder = Eigen::Vector3d::Zero(), elbow = Eigen::Vector3d::Zero(), wrist = Eigen::Vector3d::Zero();
    };
    void note_shown(Defence& defence, const ShownArm& arm, double now_s);

private:
    BlockClips m_clips;                   // the database's captured blocks
    BlockClipChoice m_choice;             // the one being played (block_clip moves)
    double m_last_s = -1.0;               // when they were measured; < 0: not yet in this block
    ShownArm m_last_shown;                // the blocking arm as shown then (world)
    bool m_measure_from_shown = false;    // a block started last frame: measured from the pose shown then
    bool m_lagging = false;               // the arm was held back to its clip's speed last frame: not where the blend put it
    double m_played = 0.0;                // clip frames of the captured block played since its start frame
    double m_played_s = 0.0;              // when
};

} // namespace kumite
