#pragma once
// The hit point trajectory of a strike clip: where the hit segment goes over the clip, seen from each pose the
// strike could start from (in that pose's heading frame), and the axis-aligned box that holds all of it. The
// retrieval keeps a clip only when the target falls in (or near) its box.

#include "kumite/core/contact_point.h"
#include "kumite/core/heading_frame.h"
#include "kumite/core/rest_anatomy.h"

#include <limits>
#include <span>
#include <vector>

namespace kumite {

struct AlignedBox {
    Eigen::Vector3d min = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector3d max = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());

    void extend(const Eigen::Vector3d& point) {
        min = min.cwiseMin(point);
        max = max.cwiseMax(point);
    }
    bool empty() const { return (min.array() > max.array()).any(); }
    bool contains(const Eigen::Vector3d& point) const {
        return (point.array() >= min.array()).all() && (point.array() <= max.array()).all();
    }
    double distance_to(const Eigen::Vector3d& point) const; // 0 inside
};

// Over a clip's frames: the hit joint's world positions and each frame's heading frame.
struct HitTrajectory {
    int hit_frame = 0;
    std::vector<Eigen::Vector3d> hit_points;  // [frame] world, metres
    std::vector<HeadingFrame> headings;       // [frame]
    std::vector<AlignedBox> start_boxes;      // [start < hit_frame] the path start..hit_frame in start's heading frame
    AlignedBox box_in_heading;                // union of the start boxes

    // The hit joint at `frame` seen from the heading frame of `start`.
    Eigen::Vector3d point_from(int start, int frame) const { return headings[start].to_heading(hit_points[frame]); }
};

// Fills the boxes from the points and headings (same length, hit_frame inside).
HitTrajectory hit_trajectory_from(std::vector<Eigen::Vector3d> hit_points, std::vector<HeadingFrame> headings, int hit_frame);

// From a clip: forward kinematics over frames first..last, `contact` the point that hits (contact_point.h); frames
// in the result count from `first_frame`.
HitTrajectory hit_trajectory_compute(const Clip& clip, const RestAnatomy& anatomy, const ContactPoint& contact, int first_frame,
                                     int hit_frame, int last_frame);

// The heading frame of a pose of this skeleton (pelvis on the floor, facing the hips' forward).
HeadingFrame pose_heading(const Skeleton& skeleton, const RestAnatomy& anatomy, std::span<const Eigen::Vector3d> model_positions,
                          std::span<const Eigen::Quaterniond> model_rotations);

} // namespace kumite
