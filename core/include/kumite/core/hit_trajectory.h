#pragma once
// The hit point trajectory of a strike clip: where the hit segment goes over the clip, seen from each pose the
// strike could start from (in that pose's heading frame), and the axis-aligned box that holds all of it. The
// retrieval keeps a clip only when the target falls in (or near) its box.

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

struct HitTrajectory {
    int first_frame = 0;                                    // candidate starts: first_frame .. hit_frame - 1
    int hit_frame = 0;
    int last_frame = 0;
    std::vector<std::vector<Eigen::Vector3d>> from_start;  // [start - first_frame][t - start], metres, heading frame
    AlignedBox box_in_heading;                              // over every start and frame
};

// `hit_joint` is the hit segment's joint; frames are clip frames with first <= hit <= last.
HitTrajectory hit_trajectory_compute(const Clip& clip, const RestAnatomy& anatomy, int hit_joint, int first_frame,
                                     int hit_frame, int last_frame);

// The heading frame of a pose of this skeleton (pelvis on the floor, facing the hips' forward).
HeadingFrame pose_heading(const Skeleton& skeleton, const RestAnatomy& anatomy, std::span<const Eigen::Vector3d> model_positions,
                          std::span<const Eigen::Quaterniond> model_rotations);

} // namespace kumite
