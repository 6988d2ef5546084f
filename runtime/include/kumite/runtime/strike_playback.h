#pragma once
// A strike played once on a character from a standing guard, start to end, and measured: what `kumite adapt`
// records and reports, what its filmstrip draws, and what the annotation window's preview plays. Offline (it
// allocates); the frame loop uses StrikeAdapter directly.
//
// Frames of `motion` are `lead_frames` copies of the guard, then the adapted strike from its start frame to the
// clip's last frame, at the database's rate. Positions are world metres (Y up), per frame in skeleton order.

#include "kumite/core/strike_adaptation.h"

#include <vector>

namespace kumite {

struct StrikePlayback {
    Clip motion;                                  // on the character's skeleton
    std::vector<Eigen::Vector3d> model_positions; // [frame * joints + joint], world
    std::vector<Eigen::Vector3d> effector_path;   // [frame], world
    std::vector<double> past_target_m;            // [frame]: how far past the stop point along the approach
    std::vector<unsigned> joint_violations;       // [frame]: joint_limits.h masks
    std::vector<double> frame_cost_us;            // [adapted frame]: time of StrikeAdapter::step
    int effector_joint = -1;
    int contact_frame = 0;                        // in motion's frames; the clip's annotated hit
    int hit_frame = 0;                            // the clip's annotated hit, in motion's frames
    Eigen::Vector3d target = Eigen::Vector3d::Zero();
    Eigen::Vector3d effector_at_contact = Eigen::Vector3d::Zero();
    Eigen::Vector3d approach_direction = Eigen::Vector3d::UnitZ();
    Reach reach_at_contact = Reach::limb;
    double contact_error_m = 0.0;
    double overshoot_m = 0.0;                     // largest distance past the target after the contact
    double effector_speed_at_contact_mps = 0.0;   // over the frame before the contact
    int joint_limit_violations = 0;               // joints out of limits, summed over frames
    double bone_length_error_m = 0.0;
    double foot_drift_m = 0.0;                    // planted support feet, on the floor
    double support_foot_lift_m = 0.0;
    std::array<bool, 2> support_feet{};

    int joint_count() const { return motion.skeleton.joint_count(); }
    std::span<const Eigen::Vector3d> positions(int frame) const {
        return {model_positions.data() + std::size_t(frame) * joint_count(), std::size_t(joint_count())};
    }
};

// Plays `plan` on `rig` from `standing` (the guard, feet planted at its ankles). `impact` false lets the strike
// follow through (a dodged strike).
StrikePlayback strike_playback_run(const CharacterRig& rig, const MotionDatabaseView& database, const Pose& standing,
                                   const StrikePlan& plan, int lead_frames, bool impact = true);

} // namespace kumite
