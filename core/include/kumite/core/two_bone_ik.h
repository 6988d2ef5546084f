#pragma once
// Analytic two-bone inverse kinematics with a swivel angle: places the middle joint (elbow, knee) so that the
// chain root -> middle -> extremity has the given bone lengths, ends at the target (or as close as the lengths
// allow) and turns around the root->target line by `swivel` from `reference`. Positions in metres, world.

#include <Eigen/Geometry>

namespace kumite {

struct TwoBoneSolution {
    Eigen::Vector3d middle;    // elbow / knee position
    Eigen::Vector3d extremity; // the reached position (the target when reachable)
    bool reachable = true;
};

TwoBoneSolution two_bone_ik(const Eigen::Vector3d& root, const Eigen::Vector3d& target, double upper_length,
                            double lower_length, double swivel, const Eigen::Vector3d& reference);

// The smallest rotation taking direction `from` to direction `to` (both non-zero).
Eigen::Quaterniond rotation_between(const Eigen::Vector3d& from, const Eigen::Vector3d& to);

// `reference` made orthogonal to `axis` (unit); falls back to another axis when they are nearly parallel.
Eigen::Vector3d orthogonal_reference(const Eigen::Vector3d& axis, const Eigen::Vector3d& reference);

} // namespace kumite
