#include "kumite/core/root_from_feet.h"

#include "kumite/core/forward_kinematics.h"

#include <algorithm>
#include <limits>

namespace kumite {

bool root_is_pinned(const Clip& clip) {
    if (clip.frame_count() < 2 || clip.has_local_translations()) return false;
    for (const Eigen::Vector3d& root : clip.root_translations) {
        if (root != clip.root_translations.front()) return false;
    }
    return true;
}

RootFromFeetReport root_motion_from_feet(Clip& clip, int left_ankle, int right_ankle, double switch_margin_m) {
    RootFromFeetReport report;
    const int frames = clip.frame_count();
    if (frames == 0) return report;
    std::vector<Eigen::Vector3d> positions(clip.skeleton.joint_count());
    std::vector<Eigen::Quaterniond> rotations(clip.skeleton.joint_count());
    std::vector<Eigen::Vector3d> ankles[2];
    ankles[0].resize(frames);
    ankles[1].resize(frames);
    for (int frame = 0; frame < frames; ++frame) {
        forward_kinematics(positions, rotations, clip.skeleton, clip.pose(frame));
        ankles[0][frame] = positions[left_ankle] - clip.root_translations[frame];
        ankles[1][frame] = positions[right_ankle] - clip.root_translations[frame];
    }
    double floor_ankle_y = std::numeric_limits<double>::infinity();
    for (int frame = 0; frame < frames; ++frame) floor_ankle_y = std::min({floor_ankle_y, ankles[0][frame].y(), ankles[1][frame].y()});

    const Eigen::Vector3d first_root = clip.root_translations.front();
    int support = ankles[0][0].y() <= ankles[1][0].y() ? 0 : 1;
    Eigen::Vector3d horizontal_offset = Eigen::Vector3d::Zero(); // root minus its pinned place, horizontal part
    double slide = 0.0;
    for (int frame = 0; frame < frames; ++frame) {
        const int other = 1 - support;
        if (frame > 0 && ankles[other][frame].y() < ankles[support][frame].y() - switch_margin_m) {
            report.support_slide_before_m = std::max(report.support_slide_before_m, slide);
            support = other;
            slide = 0.0;
        } else if (frame > 0) {
            Eigen::Vector3d step = ankles[support][frame] - ankles[support][frame - 1];
            step.y() = 0.0;
            horizontal_offset -= step; // the body moves instead of the foot it stands on
            slide += step.norm();
        }
        const double lowest = std::min(ankles[0][frame].y(), ankles[1][frame].y());
        Eigen::Vector3d root = first_root + horizontal_offset;
        root.y() = first_root.y() + (floor_ankle_y - lowest); // the lower ankle keeps one height
        clip.root_translations[frame] = root;
        report.root_travel_m = std::max(report.root_travel_m, (root - first_root).norm());
    }
    report.support_slide_before_m = std::max(report.support_slide_before_m, slide);
    return report;
}

} // namespace kumite
