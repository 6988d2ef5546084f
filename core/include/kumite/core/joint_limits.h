#pragma once
// Plausible joints after adaptation. The clip is a real person's motion, so its own elbows, knees and trunk are
// plausible; what adaptation may break is how they bend once the hand or foot is moved:
//  - a limb's bend: the direction in which its elbow or knee bulges away from the root->extremity line. Moving the
//    extremity re-solves the limb around a new line, and a swivel measured from a fixed reference can then put the
//    elbow or knee on the other side: a knee that bends backwards. A bend more than `flip_rad` away from the
//    clip's own bend at the same frame is a violation (both limbs bent at least `bent_rad`; a straight limb has no
//    bend, and the analytic solve never straightens a limb beyond straight, so it cannot hyperextend);
//  - the trunk: the chest's rotation away from the pelvis (anatomical frames) beyond `trunk_turn_rad`.
// Positions in metres, world; rotations model (world) rotations, [joint].

#include "kumite/core/rest_anatomy.h"

#include <span>

namespace kumite {

struct JointLimits {
    double flip_rad = 90.0 * 3.14159265358979 / 180.0;
    double bent_rad = 15.0 * 3.14159265358979 / 180.0;
    double trunk_turn_rad = 75.0 * 3.14159265358979 / 180.0; // the reference clips reach 46 degrees
};

// The unit direction from the root->extremity line to the middle joint, or zero when the limb is bent less than
// `bent_rad` (no defined bend).
Eigen::Vector3d limb_bend_direction(const Eigen::Vector3d& root, const Eigen::Vector3d& middle, const Eigen::Vector3d& extremity,
                                    double bent_rad = JointLimits{}.bent_rad);

// Whether a limb bending towards `bend` (unit or zero) bends the other way from `clip_bend` (unit or zero).
bool limb_bend_flipped(const Eigen::Vector3d& bend, const Eigen::Vector3d& clip_bend, const JointLimits& limits = {});

// The chest's rotation away from the pelvis (anatomical frames), radians.
double trunk_turn(const RestAnatomy& anatomy, std::span<const Eigen::Quaterniond> rotations);

// Bit `limb` (Limb) of a violation mask: that elbow or knee; k_trunk_violation: the trunk.
inline constexpr unsigned k_trunk_violation = 1u << 4;
int joint_violation_count(unsigned mask);

} // namespace kumite
