#include "kumite/core/clip.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace kumite {

PoseView Clip::pose(int frame) const {
    assert(frame >= 0 && frame < frame_count());
    const size_t joints = static_cast<size_t>(skeleton.joint_count());
    const size_t first = static_cast<size_t>(frame) * joints;
    PoseView view{root_translations[frame], std::span(local_rotations).subspan(first, joints), {}};
    if (has_local_translations()) view.local_translations = std::span(local_translations).subspan(first, joints);
    return view;
}

Pose Clip::rest_pose() const {
    Pose pose;
    pose.root_translation = skeleton.joint_count() > 0 ? skeleton.rest_offsets[0] : Eigen::Vector3d::Zero();
    pose.local_rotations.assign(skeleton.joint_count(), Eigen::Quaterniond::Identity());
    return pose;
}

void clip_append_pose(Clip& clip, const PoseView& pose) {
    assert(pose.local_rotations.size() == static_cast<std::size_t>(clip.skeleton.joint_count()));
    const std::vector<Eigen::Vector3d>& rest = clip.skeleton.rest_offsets;
    if (!pose.local_translations.empty() && !clip.has_local_translations()) {
        for (int frame = 0; frame < clip.frame_count(); ++frame) clip.local_translations.insert(clip.local_translations.end(), rest.begin(), rest.end());
    }
    if (!pose.local_translations.empty()) clip.local_translations.insert(clip.local_translations.end(), pose.local_translations.begin(), pose.local_translations.end());
    else if (clip.has_local_translations()) clip.local_translations.insert(clip.local_translations.end(), rest.begin(), rest.end());
    clip.root_translations.push_back(pose.root_translation);
    clip.local_rotations.insert(clip.local_rotations.end(), pose.local_rotations.begin(), pose.local_rotations.end());
}

void clip_sample(Pose& pose, const Clip& clip, double time_s) {
    const int joints = clip.skeleton.joint_count();
    assert(clip.frame_count() > 0);
    pose.local_rotations.resize(joints);
    pose.local_translations.resize(clip.has_local_translations() ? joints : 0);

    const double frame_position = clip.has_frame_rate() ? std::clamp(time_s / clip.frame_time_s, 0.0, double(clip.frame_count() - 1)) : 0.0;
    const int frame0 = static_cast<int>(std::floor(frame_position));
    const int frame1 = std::min(frame0 + 1, clip.frame_count() - 1);
    const double alpha = frame_position - frame0;

    const PoseView a = clip.pose(frame0);
    const PoseView b = clip.pose(frame1);
    pose.root_translation = (1.0 - alpha) * a.root_translation + alpha * b.root_translation;
    for (int joint = 0; joint < joints; ++joint) {
        pose.local_rotations[joint] = a.local_rotations[joint].slerp(alpha, b.local_rotations[joint]);
        if (!pose.local_translations.empty()) {
            pose.local_translations[joint] =
                (1.0 - alpha) * a.local_translations[joint] + alpha * b.local_translations[joint];
        }
    }
}

} // namespace kumite
