#pragma once
// What the viewport shows of a strike, computed from the capture (never typed): the hit segment's joint over the
// trimmed frames, the contact point at the hit frame, and the hit-path box — the box of the path from the first
// frame to the hit in the first frame's heading frame (the bake's start box of that pose), with its corners
// placed back in the world. Positions are world metres in the capture's axes.

#include "capture_library.h"

#include "kumite/core/hit_trajectory.h"

#include <array>

namespace kumite::annotate {

struct ClipTrajectory {
    std::vector<Eigen::Vector3d> points_world;         // [frame - first_frame] the contact point
    int hit_index = 0;                                 // hit_frame - first_frame
    Eigen::Vector3d contact_world = Eigen::Vector3d::Zero();
    std::array<Eigen::Vector3d, 8> box_corners_world{}; // corner k: x from bit 0, y from bit 1, z from bit 2 (min/max)
    AlignedBox box_in_first_heading;                   // the path first..hit, first frame's heading frame
    AlignedBox box_in_heading;                         // union over every start (what the bake stores per clip)
};

// The path of the contact point of a clip of `semantics` (contact_point.h: a joint, or a block's forearm). Fails
// when the capture has no anatomy, the segment no joint, or the frames are out of order or range.
Result<ClipTrajectory> clip_trajectory_compute(const LoadedCapture& capture, std::string_view semantics, BodyPart segment,
                                               int first_frame, int hit_frame, int last_frame);

} // namespace kumite::annotate
