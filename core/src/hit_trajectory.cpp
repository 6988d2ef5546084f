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

HitTrajectory hit_trajectory_from(std::vector<Eigen::Vector3d> hit_points, std::vector<HeadingFrame> headings, int hit_frame) {
    assert(hit_points.size() == headings.size() && 0 <= hit_frame && hit_frame < static_cast<int>(hit_points.size()));
    HitTrajectory trajectory;
    trajectory.hit_frame = hit_frame;
    trajectory.hit_points = std::move(hit_points);
    trajectory.headings = std::move(headings);
    trajectory.start_boxes.resize(hit_frame);
    for (int start = 0; start < hit_frame; ++start) {
        AlignedBox& box = trajectory.start_boxes[start];
        for (int frame = start; frame <= hit_frame; ++frame) box.extend(trajectory.point_from(start, frame));
        trajectory.box_in_heading.extend(box.min);
        trajectory.box_in_heading.extend(box.max);
    }
    return trajectory;
}

HitTrajectory hit_trajectory_compute(const Clip& clip, const RestAnatomy& anatomy, const ContactPoint& contact, int first_frame,
                                     int hit_frame, int last_frame) {
    assert(0 <= first_frame && first_frame <= hit_frame && hit_frame <= last_frame && last_frame < clip.frame_count());
    const Skeleton& skeleton = clip.skeleton;
    std::vector<Eigen::Vector3d> positions(skeleton.joint_count());
    std::vector<Eigen::Quaterniond> rotations(skeleton.joint_count());
    std::vector<Eigen::Vector3d> hit_points;
    std::vector<HeadingFrame> headings;
    for (int frame = first_frame; frame <= last_frame; ++frame) {
        forward_kinematics(positions, rotations, skeleton, clip.pose(frame));
        hit_points.push_back(contact.at(positions));
        headings.push_back(pose_heading(skeleton, anatomy, positions, rotations));
    }
    return hit_trajectory_from(std::move(hit_points), std::move(headings), hit_frame - first_frame);
}

} // namespace kumite
