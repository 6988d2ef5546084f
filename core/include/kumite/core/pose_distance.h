#pragma once
// Kovar's pose distance (Kovar, Gleicher & Pighin 2002): the weighted sum of squared distances between two point
// clouds (joint positions, usually over a short window of frames), minimised over a rotation about the vertical
// axis and a translation on the floor. The minimum has a closed form; nothing iterates. Positions in metres.

#include <Eigen/Core>

#include <span>

namespace kumite {

// The rigid floor motion that best puts cloud b onto cloud a: p -> R_y(angle) p + (x, 0, z).
struct FloorAlignment {
    double angle_rad = 0.0;
    double x = 0.0;
    double z = 0.0;

    Eigen::Vector3d apply(const Eigen::Vector3d& point) const;
};

// points_a, points_b: [n] matching points; weights: [n] non-negative, not all zero (empty = all 1).
FloorAlignment kovar_alignment(std::span<const Eigen::Vector3d> points_a, std::span<const Eigen::Vector3d> points_b,
                               std::span<const double> weights = {});

// The minimised weighted sum of squared distances (metres squared); the alignment used, if asked for.
double kovar_distance(std::span<const Eigen::Vector3d> points_a, std::span<const Eigen::Vector3d> points_b,
                      std::span<const double> weights = {}, FloorAlignment* alignment = nullptr);

} // namespace kumite
