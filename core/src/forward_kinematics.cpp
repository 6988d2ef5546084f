#include "kumite/core/forward_kinematics.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace kumite {

void forward_kinematics(std::span<Eigen::Vector3d> model_positions, std::span<Eigen::Quaterniond> model_rotations,
                        const Skeleton& skeleton, const PoseView& pose) {
    const int joints = skeleton.joint_count();
    assert(static_cast<int>(model_positions.size()) >= joints);
    assert(static_cast<int>(model_rotations.size()) >= joints);
    assert(static_cast<int>(pose.local_rotations.size()) == joints);
    const bool animated_translations = !pose.local_translations.empty();

    for (int joint = 0; joint < joints; ++joint) {
        const int parent = skeleton.parents[joint];
        if (parent < 0) {
            model_positions[joint] = pose.root_translation;
            model_rotations[joint] = pose.local_rotations[joint];
            continue;
        }
        const Eigen::Vector3d& local_translation =
            animated_translations ? pose.local_translations[joint] : skeleton.rest_offsets[joint];
        model_positions[joint] = model_positions[parent] + model_rotations[parent] * local_translation;
        model_rotations[joint] = model_rotations[parent] * pose.local_rotations[joint];
    }
}

void end_site_positions(std::span<Eigen::Vector3d> end_site_model_positions, const Skeleton& skeleton,
                        std::span<const Eigen::Vector3d> model_positions,
                        std::span<const Eigen::Quaterniond> model_rotations) {
    assert(end_site_model_positions.size() >= skeleton.end_sites.size());
    for (size_t i = 0; i < skeleton.end_sites.size(); ++i) {
        const EndSite& end_site = skeleton.end_sites[i];
        end_site_model_positions[i] =
            model_positions[end_site.joint] + model_rotations[end_site.joint] * end_site.offset_in_joint;
    }
}

double bone_length_error(const Skeleton& skeleton, std::span<const Eigen::Vector3d> positions, int pelvis) {
    double worst = 0.0;
    for (int joint = 1; joint < skeleton.joint_count(); ++joint) {
        if (pelvis >= 0 && skeleton.is_ancestor(joint, pelvis)) continue;
        const double length = (positions[joint] - positions[skeleton.parents[joint]]).norm();
        worst = std::max(worst, std::abs(length - skeleton.rest_offsets[joint].norm()));
    }
    return worst;
}

} // namespace kumite
