#include "kumite/runtime/strike_playback.h"

#include "kumite/core/forward_kinematics.h"

#include <algorithm>
#include <chrono>

namespace kumite {
namespace {

void append_pose(StrikePlayback& playback, const Pose& pose) {
    Clip& motion = playback.motion;
    clip_append_pose(motion, pose.view());
    const int joints = motion.skeleton.joint_count();
    std::vector<Eigen::Quaterniond> rotations(joints);
    const std::size_t first = playback.model_positions.size();
    playback.model_positions.resize(first + joints);
    forward_kinematics({playback.model_positions.data() + first, std::size_t(joints)}, rotations, motion.skeleton, pose.view());
}

} // namespace

StrikePlayback strike_playback_run(const CharacterRig& rig, const MotionDatabaseView& db, const Pose& standing,
                                   const StrikePlan& plan, int lead_frames, bool impact) {
    StrikePlayback playback;
    const Skeleton& skeleton = rig.skeleton();
    const RestAnatomy& anatomy = rig.anatomy();
    playback.motion.skeleton = skeleton;
    playback.motion.frame_time_s = db.meta.frame_time_s;
    playback.target = plan.target_world;

    // The guard, encoded, with both feet planted where it has them.
    std::vector<Eigen::Vector3d> standing_positions(skeleton.joint_count());
    std::vector<Eigen::Quaterniond> standing_rotations(skeleton.joint_count());
    forward_kinematics(standing_positions, standing_rotations, skeleton, standing.view());
    MirEncoder encoder(skeleton, anatomy);
    MirFrame current;
    encoder.encode(current, standing.view());
    const std::array<Eigen::Vector3d, 2> ankles = {standing_positions[anatomy.limbs[int(Limb::leg_l)].extremity],
                                                   standing_positions[anatomy.limbs[int(Limb::leg_r)].extremity]};

    StrikeAdapter adapter(rig, db);
    adapter.begin(plan, current, {true, true}, ankles);
    adapter.set_impact(impact);
    playback.effector_joint = adapter.effector_joint();
    playback.support_feet = adapter.support_feet();
    playback.approach_direction = adapter.approach_direction();
    playback.contact_frame = lead_frames + adapter.contact_index();
    playback.hit_frame = lead_frames + (int(db.clips[plan.clip].hit_frame) - plan.start_frame);

    for (int i = 0; i < lead_frames; ++i) {
        append_pose(playback, standing);
        playback.effector_path.push_back(standing_positions[playback.effector_joint]);
        playback.past_target_m.push_back(0.0);
        playback.joint_violations.push_back(0u);
    }
    Pose pose;
    adapter.step(0, pose); // sizes the pose
    for (int i = 0; i < adapter.frame_count(); ++i) {
        const auto started = std::chrono::steady_clock::now();
        const AdaptedFrame frame = adapter.step(i, pose);
        playback.frame_cost_us.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - started).count());
        if (frame.contact) {
            playback.effector_at_contact = frame.effector;
            playback.reach_at_contact = frame.reach;
        }
        playback.past_target_m.push_back(frame.past_target_m);
        playback.joint_violations.push_back(frame.joint_violations);
        playback.overshoot_m = std::max(playback.overshoot_m, frame.past_target_m);
        playback.joint_limit_violations += joint_violation_count(frame.joint_violations);
        playback.bone_length_error_m = std::max(playback.bone_length_error_m, bone_length_error(skeleton, adapter.positions(), anatomy.body_map.joint(BodyPart::pelvis)));
        for (int foot = 0; foot < 2; ++foot) {
            if (!adapter.support_feet()[foot]) continue;
            const Eigen::Vector3d ankle = adapter.positions()[anatomy.limbs[int(Limb::leg_l) + foot].extremity];
            const Eigen::Vector3d pin = adapter.support_pins()[foot];
            playback.foot_drift_m = std::max(playback.foot_drift_m, Eigen::Vector2d(ankle.x() - pin.x(), ankle.z() - pin.z()).norm());
            playback.support_foot_lift_m = std::max(playback.support_foot_lift_m, ankle.y() - pin.y());
        }
        append_pose(playback, pose);
        playback.effector_path.push_back(frame.effector);
    }
    playback.contact_error_m = (playback.effector_at_contact - plan.target_world).norm();
    if (playback.contact_frame > 0) {
        const Eigen::Vector3d before = playback.effector_path[playback.contact_frame - 1];
        playback.effector_speed_at_contact_mps = (playback.effector_at_contact - before).norm() / db.meta.frame_time_s;
    }
    return playback;
}

} // namespace kumite
