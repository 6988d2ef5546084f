#include "bake_clip.h"

#include "kumite/core/foot_contacts.h"
#include "kumite/core/forward_kinematics.h"
#include "kumite/core/hit_trajectory.h"
#include "kumite/core/pose_features.h"

#include <cmath>

namespace kumite::bake {
namespace {

// The capture's frames first..last resampled at frame_time_s (slerp between source frames).
Clip trim_and_resample(const Clip& capture, int first, int last, double frame_time_s) {
    Clip clip;
    clip.skeleton = capture.skeleton;
    clip.frame_time_s = frame_time_s;
    const double start_s = first * capture.frame_time_s;
    const double duration_s = (last - first) * capture.frame_time_s;
    // Frame times in files are rounded (0.0333333 for 30 fps): a hundredth of a frame of slack keeps the last one.
    const int frames = static_cast<int>(std::floor(duration_s / frame_time_s + 0.01)) + 1;
    Pose pose;
    for (int frame = 0; frame < frames; ++frame) {
        clip_sample(pose, capture, start_s + frame * frame_time_s);
        clip.root_translations.push_back(pose.root_translation);
        clip.local_rotations.insert(clip.local_rotations.end(), pose.local_rotations.begin(), pose.local_rotations.end());
        if (capture.has_local_translations()) {
            clip.local_translations.insert(clip.local_translations.end(), pose.local_translations.begin(), pose.local_translations.end());
        }
    }
    return clip;
}

void store(float (&out)[3], const Eigen::Vector3d& v) {
    for (int axis = 0; axis < 3; ++axis) out[axis] = static_cast<float>(v[axis]);
}

constexpr float k_empty_box = 1e30f; // min = +k_empty_box, max = -k_empty_box: contains nothing

void set_empty(float (&min)[3], float (&max)[3]) {
    for (int axis = 0; axis < 3; ++axis) {
        min[axis] = k_empty_box;
        max[axis] = -k_empty_box;
    }
}

Side mirrored_side(Side side) { return side == Side::left ? Side::right : side == Side::right ? Side::left : Side::none; }

} // namespace

std::string mirrored_clip_name(const std::string& name) { return name + "~mirror"; }

BakedClip bake_clip(const RawAnnotatedClip& annotation, bool mirrored, const BakeSource& source, double frame_time_s, int feature_stride) {
    const Clip& capture = source.file.clip;
    const RestAnatomy& anatomy = source.anatomy;
    BakedClip baked;
    baked.name = mirrored ? mirrored_clip_name(annotation.name) : annotation.name;
    baked.semantics = annotation.semantics;
    baked.motion = trim_and_resample(capture, annotation.first_frame, annotation.last_frame, frame_time_s);
    if (mirrored) baked.motion = clip_mirror(baked.motion, *source.symmetry);
    const Clip& motion = baked.motion;
    const int frames = motion.frame_count();

    DbClip& record = baked.record;
    record.actor = static_cast<std::uint32_t>(source.actor);
    record.frame_count = static_cast<std::uint32_t>(frames);
    record.source_first_frame = static_cast<std::uint32_t>(annotation.first_frame);
    record.flags = (mirrored ? db_clip_mirrored : 0u) | (annotation.is_strike() ? db_clip_strike : 0u);
    const Side side = mirrored ? mirrored_side(annotation.side) : annotation.side;
    record.side = static_cast<std::uint32_t>(side);
    record.kind = static_cast<std::uint8_t>(annotation.kind);     // a mirror is the same kind at the same height
    record.height = static_cast<std::uint8_t>(annotation.height);
    ContactPoint contact;
    if (annotation.segment) {
        const BodyPart segment = mirrored ? body_part_mirrored(*annotation.segment) : *annotation.segment;
        record.segment = static_cast<std::int32_t>(segment);
        contact = contact_point_of(annotation.semantics, segment, anatomy.body_map);
    }
    if (annotation.hit_frame) {
        const double hit_s = (*annotation.hit_frame - annotation.first_frame) * capture.frame_time_s;
        record.hit_frame = std::clamp(static_cast<int>(std::lround(hit_s / frame_time_s)), 0, frames - 1);
    }

    // Per frame: MIR, model transforms, heading, feature points, ankles.
    MirEncoder encoder(motion.skeleton, anatomy);
    MirFrame mir;
    const int joints = motion.skeleton.joint_count();
    std::vector<Eigen::Vector3d> positions(joints);
    std::vector<Eigen::Quaterniond> rotations(joints);
    std::vector<Eigen::Vector3d> feature_points(std::size_t(frames) * k_feature_point_count);
    std::vector<HeadingFrame> headings(frames);
    std::array<std::vector<Eigen::Vector3d>, 2> ankles{std::vector<Eigen::Vector3d>(frames), std::vector<Eigen::Vector3d>(frames)};
    std::vector<Eigen::Vector3d> hit_points(frames, Eigen::Vector3d::Zero());
    baked.poses.resize(frames);
    baked.mir_frames.resize(frames);
    for (int frame = 0; frame < frames; ++frame) {
        encoder.encode(mir, motion.pose(frame));
        db_mir_frame_store(baked.mir_frames[frame], mir);
        forward_kinematics(positions, rotations, motion.skeleton, motion.pose(frame));
        headings[frame] = pose_heading(motion.skeleton, anatomy, positions, rotations);
        pose_feature_points(std::span(feature_points).subspan(std::size_t(frame) * k_feature_point_count, k_feature_point_count),
                            anatomy.body_map, positions);
        ankles[0][frame] = positions[anatomy.limbs[int(Limb::leg_l)].extremity];
        ankles[1][frame] = positions[anatomy.limbs[int(Limb::leg_r)].extremity];
        if (contact.valid()) hit_points[frame] = contact.at(positions) - Eigen::Vector3d(0.0, anatomy.floor_y, 0.0);
        headings[frame].origin.y() = 0.0; // stored positions put the capture's floor at y = 0
        DbPose& pose = baked.poses[frame];
        pose.frame = static_cast<std::uint32_t>(frame);
        pose.heading[0] = static_cast<float>(headings[frame].origin.x());
        pose.heading[1] = static_cast<float>(headings[frame].origin.z());
        pose.heading[2] = static_cast<float>(headings[frame].yaw_rad);
        store(pose.hit_point, hit_points[frame]);
        set_empty(pose.start_box_min, pose.start_box_max);
    }

    // Foot contacts.
    for (int foot = 0; foot < 2; ++foot) {
        for (const ContactInterval& contact : foot_contacts_detect(ankles[foot], frame_time_s, anatomy.leg_length,
                                                                    anatomy.floor_y + anatomy.ankle_height)) {
            for (int frame = contact.first_frame; frame <= contact.last_frame; ++frame) {
                baked.poses[frame].flags |= foot == 0 ? db_pose_left_foot_planted : db_pose_right_foot_planted;
            }
        }
    }

    // Features: the window t - 2 stride, t - stride, t (clamped to the clip) in the heading frame of t.
    baked.features.resize(std::size_t(frames) * k_feature_dimensions);
    std::vector<Eigen::Vector3d> window(k_feature_cloud_size);
    for (int frame = 0; frame < frames; ++frame) {
        for (int sample = 0; sample < k_feature_window; ++sample) {
            const int at = std::max(0, frame - (k_feature_window - 1 - sample) * feature_stride);
            std::copy_n(feature_points.begin() + std::size_t(at) * k_feature_point_count, k_feature_point_count,
                        window.begin() + sample * k_feature_point_count);
        }
        pose_feature_build(std::span(baked.features).subspan(std::size_t(frame) * k_feature_dimensions, k_feature_dimensions), window,
                           headings[frame], anatomy.leg_length);
    }

    // Hit trajectory boxes: from each start before the hit frame, the path up to the hit in the start's heading.
    set_empty(record.box_min, record.box_max);
    if (record.flags & db_clip_strike) {
        const HitTrajectory trajectory = hit_trajectory_from(std::move(hit_points), std::move(headings), record.hit_frame);
        for (int start = 0; start < record.hit_frame; ++start) {
            store(baked.poses[start].start_box_min, trajectory.start_boxes[start].min);
            store(baked.poses[start].start_box_max, trajectory.start_boxes[start].max);
        }
        if (!trajectory.box_in_heading.empty()) {
            store(record.box_min, trajectory.box_in_heading.min);
            store(record.box_max, trajectory.box_in_heading.max);
        }
    }
    return baked;
}

} // namespace kumite::bake
