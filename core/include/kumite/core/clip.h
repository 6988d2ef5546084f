#pragma once
// Clip: a skeleton and its frames sampled at a fixed rate. A frame is a root translation, one local rotation
// per joint and, when the source animated them, one local translation per joint (it then replaces the rest
// offset, the root's included). Lengths are metres, in the file's own axes (Y up).

#include "kumite/core/skeleton.h"

#include <Eigen/Geometry>

#include <span>
#include <vector>

namespace kumite {

// A read-only view of one pose; local_translations is empty when the joints use their rest offsets.
struct PoseView {
    Eigen::Vector3d root_translation;                      // metres, world
    std::span<const Eigen::Quaterniond> local_rotations;   // [joint] in the parent's frame
    std::span<const Eigen::Vector3d> local_translations;   // [joint] metres, in the parent's frame, or empty
};

// An owned pose, e.g. the output of sampling between frames.
struct Pose {
    Eigen::Vector3d root_translation = Eigen::Vector3d::Zero();
    std::vector<Eigen::Quaterniond> local_rotations;
    std::vector<Eigen::Vector3d> local_translations;

    PoseView view() const { return {root_translation, local_rotations, local_translations}; }
};

struct Clip {
    Skeleton skeleton;
    double frame_time_s = 1.0 / 30.0; // 0 when the source did not say its rate (see has_frame_rate)
    std::vector<Eigen::Vector3d> root_translations;  // [frame]
    std::vector<Eigen::Quaterniond> local_rotations; // [frame * joint_count + joint]
    std::vector<Eigen::Vector3d> local_translations; // empty, or [frame * joint_count + joint]

    int frame_count() const { return static_cast<int>(root_translations.size()); }
    // Whether the clip knows its rate. Positions per frame need none; speeds, timing and resampling do, and their
    // callers refuse a clip without one (a capture whose file says `Frame Time: 0`).
    bool has_frame_rate() const { return frame_time_s > 0.0; }
    double duration_s() const { return frame_count() > 0 ? (frame_count() - 1) * frame_time_s : 0.0; }
    bool has_local_translations() const { return !local_translations.empty(); }
    PoseView pose(int frame) const;

    // The rest pose: identity rotations, rest offsets, root at its rest offset.
    Pose rest_pose() const;
};

// Appends a frame. A pose with local translations (the pelvis below a Root joint, moved by the decoder) gives the
// clip local translations; frames appended before without them get the rest offsets.
void clip_append_pose(Clip& clip, const PoseView& pose);

// Writes the pose at time_s (clamped to the clip; frame 0 when the clip has no rate): slerp between the neighbouring frames' rotations, lerp
// between translations. `pose` is resized once to the skeleton and reused across calls.
void clip_sample(Pose& pose, const Clip& clip, double time_s);

} // namespace kumite
