#include "kumite/core/character_rig.h"

#include "kumite/core/forward_kinematics.h"
#include "kumite/core/hit_trajectory.h"
#include "kumite/core/pose_features.h"

namespace kumite {

CharacterRig::CharacterRig(const Skeleton& skeleton, const RestAnatomy& anatomy)
    : m_skeleton(skeleton), m_anatomy(anatomy), m_decoder(skeleton, anatomy, {}), m_positions(skeleton.joint_count()),
      m_rotations(skeleton.joint_count()) {}

CharacterSize CharacterRig::size() const {
    return {m_anatomy.leg_length, 0.5 * (m_anatomy.limbs[int(Limb::arm_l)].length() + m_anatomy.limbs[int(Limb::arm_r)].length())};
}

void CharacterRig::decode(Pose& out, const MotionDatabaseView& database, std::uint32_t pose_index, const FloorAlignment& clip_to_world) {
    db_mir_frame_load(m_frame, database.mir_frames[pose_index]);
    m_decoder.decode(out, m_frame);
    pose_move_on_floor(out, clip_to_world);
}

void CharacterRig::stand_at_origin(Pose& out, const MotionDatabaseView& database) {
    const DbClip* guard = nullptr;
    for (const DbClip& clip : database.clips) {
        if (database.string(clip.semantics) == "rest") {
            guard = &clip;
            break;
        }
    }
    if (guard) {
        decode(out, database, guard->first_pose);
    } else {
        out.root_translation = m_skeleton.rest_offsets[0];
        out.local_rotations.assign(m_skeleton.joint_count(), Eigen::Quaterniond::Identity());
        out.local_translations.clear();
    }
    measure(out.view());
    const HeadingFrame current = heading();
    FloorAlignment to_origin{-current.yaw_rad, 0.0, 0.0};
    const Eigen::Vector3d turned = to_origin.apply(Eigen::Vector3d(current.origin.x(), 0.0, current.origin.z()));
    to_origin.x = -turned.x();
    to_origin.z = -turned.z();
    pose_move_on_floor(out, to_origin);
    measure(out.view());
}

void CharacterRig::measure(const PoseView& pose) { forward_kinematics(m_positions, m_rotations, m_skeleton, pose); }

HeadingFrame CharacterRig::heading() const { return pose_heading(m_skeleton, m_anatomy, m_positions, m_rotations); }

void CharacterRig::feature_points(std::span<Eigen::Vector3d> out) const { pose_feature_points(out, m_anatomy.body_map, m_positions); }

void CharacterRig::still_feature(std::span<float> out) const {
    std::array<Eigen::Vector3d, k_feature_cloud_size> window;
    feature_points(std::span(window).first(k_feature_point_count));
    for (int sample = 1; sample < k_feature_window; ++sample) {
        std::copy_n(window.begin(), k_feature_point_count, window.begin() + sample * k_feature_point_count);
    }
    pose_feature_build(out, window, heading(), m_anatomy.leg_length);
}

void pose_move_on_floor(Pose& pose, const FloorAlignment& motion) {
    pose.root_translation = motion.apply(pose.root_translation);
    if (!pose.local_rotations.empty()) {
        pose.local_rotations[0] = Eigen::Quaterniond(Eigen::AngleAxisd(motion.angle_rad, Eigen::Vector3d::UnitY())) * pose.local_rotations[0];
    }
}

} // namespace kumite
