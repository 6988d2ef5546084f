#include "kumite/core/hit_trajectory.h"

#include "kumite/core/forward_kinematics.h"

#include <algorithm>
#include <cassert>

namespace kumite {

double AlignedBox::distance_to(const Eigen::Vector3d& point) const {
    const Eigen::Vector3d below = (min - point).cwiseMax(0.0);
    const Eigen::Vector3d above = (point - max).cwiseMax(0.0);
    return (below + above).norm();
}

HeadingFrame pose_heading(const Skeleton&, const RestAnatomy& anatomy, std::span<const Eigen::Vector3d> positions,
                          std::span<const Eigen::Quaterniond> rotations) {
    const int pelvis = anatomy.body_map.joint(BodyPart::pelvis);
    const Eigen::Vector3d facing = (rotations[pelvis] * anatomy.rest_frames[pelvis]) * Eigen::Vector3d::UnitZ();
    return heading_frame_from(positions[pelvis], facing, anatomy.floor_y);
}

HitTrajectory hit_trajectory_compute(const Clip& clip, const RestAnatomy& anatomy, int hit_joint, int first_frame, int hit_frame,
                                     int last_frame) {
    assert(0 <= first_frame && first_frame <= hit_frame && hit_frame <= last_frame && last_frame < clip.frame_count());
    const Skeleton& skeleton = clip.skeleton;
    std::vector<Eigen::Vector3d> positions(skeleton.joint_count());
    std::vector<Eigen::Quaterniond> rotations(skeleton.joint_count());
    std::vector<Eigen::Vector3d> hit_points;
    std::vector<HeadingFrame> headings;
    for (int frame = first_frame; frame <= last_frame; ++frame) {
        forward_kinematics(positions, rotations, skeleton, clip.pose(frame));
        hit_points.push_back(positions[hit_joint]);
        headings.push_back(pose_heading(skeleton, anatomy, positions, rotations));
    }
    HitTrajectory trajectory;
    trajectory.first_frame = first_frame;
    trajectory.hit_frame = hit_frame;
    trajectory.last_frame = last_frame;
    for (int start = first_frame; start < std::max(hit_frame, first_frame + 1); ++start) {
        const HeadingFrame& heading = headings[start - first_frame];
        std::vector<Eigen::Vector3d> path;
        for (int frame = start; frame <= last_frame; ++frame) {
            path.push_back(heading.to_heading(hit_points[frame - first_frame]));
            trajectory.box_in_heading.extend(path.back());
        }
        trajectory.from_start.push_back(std::move(path));
    }
    return trajectory;
}

} // namespace kumite
