#pragma once
// Pose features: the point cloud that Kovar's distance compares, stored canonically. A feature is the positions
// of the feature parts (motion_database.h) over a short window of frames, expressed in the heading frame of the
// newest frame and divided by the leg length, so poses of differently sized performers and characters compare.
// Being heading-aligned, features also work as plain vectors for a nearest-neighbour index; Kovar's closed-form
// alignment on top removes what the heading estimate leaves.

#include "kumite/core/heading_frame.h"
#include "kumite/core/motion_database.h"
#include "kumite/core/pose_distance.h"

#include <span>

namespace kumite {

// The feature parts' model positions, in k_feature_parts order. `out` holds k_feature_point_count points.
void pose_feature_points(std::span<Eigen::Vector3d> out, const BodyMap& body_map, std::span<const Eigen::Vector3d> model_positions);

// `window_points`: k_feature_window groups of k_feature_point_count points, oldest first, world metres.
// `out`: k_feature_dimensions floats.
void pose_feature_build(std::span<float> out, std::span<const Eigen::Vector3d> window_points, const HeadingFrame& newest_heading,
                        double leg_length);

// Point `point` (0 .. k_feature_cloud_size - 1) of a planar feature, and its setter.
Eigen::Vector3d pose_feature_point(std::span<const float> feature, int point);
void pose_feature_set_point(std::span<float> feature, int point, const Eigen::Vector3d& value);

// Kovar's distance between two features (sum of squared distances in leg lengths), minimised over a rotation
// about Y and a floor translation in closed form; no trigonometry.
double pose_feature_distance(std::span<const float> a, std::span<const float> b);

// The alignment that puts feature b onto feature a (as kovar_alignment on their points).
FloorAlignment pose_feature_alignment(std::span<const float> a, std::span<const float> b);

} // namespace kumite
