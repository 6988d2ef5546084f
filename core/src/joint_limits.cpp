#include "kumite/core/joint_limits.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace kumite {

Eigen::Vector3d limb_bend_direction(const Eigen::Vector3d& root, const Eigen::Vector3d& middle, const Eigen::Vector3d& extremity,
                                    double bent_rad) {
    const Eigen::Vector3d upper = middle - root, lower = extremity - middle, line = extremity - root;
    if (upper.norm() < 1e-9 || lower.norm() < 1e-9 || line.norm() < 1e-9) return Eigen::Vector3d::Zero();
    const double bent = std::acos(std::clamp(upper.normalized().dot(lower.normalized()), -1.0, 1.0));
    if (bent < bent_rad) return Eigen::Vector3d::Zero();
    const Eigen::Vector3d axis = line.normalized();
    const Eigen::Vector3d away = upper - upper.dot(axis) * axis;
    return away.norm() < 1e-9 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(away.normalized());
}

bool limb_bend_flipped(const Eigen::Vector3d& bend, const Eigen::Vector3d& clip_bend, const JointLimits& limits) {
    if (bend.isZero() || clip_bend.isZero()) return false;
    return bend.dot(clip_bend) < std::cos(limits.flip_rad);
}

double trunk_turn(const RestAnatomy& anatomy, std::span<const Eigen::Quaterniond> rotations) {
    const int pelvis = anatomy.body_map.joint(BodyPart::pelvis), chest = anatomy.body_map.joint(BodyPart::chest);
    if (pelvis < 0 || chest < 0) return 0.0;
    const Eigen::Quaterniond pelvis_frame = rotations[pelvis] * anatomy.rest_frames[pelvis];
    const Eigen::Quaterniond chest_frame = rotations[chest] * anatomy.rest_frames[chest];
    return pelvis_frame.angularDistance(chest_frame);
}

int joint_violation_count(unsigned mask) { return std::popcount(mask); }

} // namespace kumite
