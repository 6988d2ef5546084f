#pragma once
// The nearest point to `point` inside a few half-spaces { x : normals[k] . x <= bounds[k] } through the origin's
// neighbourhood (3D, at most k_halfspace_max of them): an exact small quadratic program, solved by trying every
// set of one to three active constraints (the optimum of a 3D problem has at most three). Continuous in `point`
// and the bounds; allocation-free. Returns `point` when it is inside already, and `fallback` when the half-spaces
// have no common point near it (never for half-spaces that all contain a common point, e.g. the origin).

#include <Eigen/Core>

#include <span>

namespace kumite {

inline constexpr int k_halfspace_max = 8;

Eigen::Vector3d nearest_within_halfspaces(const Eigen::Vector3d& point, std::span<const Eigen::Vector3d> normals,
                                          std::span<const double> bounds, const Eigen::Vector3d& fallback);

} // namespace kumite
