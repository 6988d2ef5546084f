#pragma once
// The standing height of a skeleton, in the clip's length unit: from the lowest foot point to the top of the head
// when standing. Used to detect a capture's unit and to compare characters' sizes.
//
// When the rest pose (identity rotations) is upright (head above pelvis above feet), the height is the vertical
// extent of the rest pose, End Sites included. Captures whose rest pose is not upright (Bandai's bones lie along
// +X) are measured by bone lengths: ankle height + shin + thigh + hip-to-pelvis drop + the trunk chain up to the
// head top, the two short vertical pieces taken as medians over the frames, so every clip of one skeleton gets
// nearly the same height. A skeleton without a recognisable pelvis, head and foot is
// measured by the largest extent of its rest pose.

#include "kumite/core/body_map.h"
#include "kumite/core/clip.h"

namespace kumite {

struct StandingHeight {
    double height = 0.0;
    double ankle_height = 0.0; // the lower ankle above the lowest foot point, measured the same way (0: no feet)
    enum class Method { rest_pose, chain_lengths, rest_pose_extent } method = Method::rest_pose;
};

StandingHeight standing_height(const Clip& clip, const BodyMap& body_map);

// Where a capture's floor is and how high a flat-footed ankle stands above it, in the clip's unit (metres
// once read). The floor is the lowest foot point over the frames, snapped to y = 0 when
// within 5 cm of it (captures stand on y = 0, but a foot modelled without sole points, like Bandai's zero-length
// toe End Site, never reaches it); the ankle height is the 10th percentile of the lower ankle above that floor
// (flat-footed; clips spent mostly on the toes would lift a median). A clip without frames uses its rest pose.
struct FloorEstimate {
    double floor_y = 0.0;
    double ankle_height = 0.0;
};
inline constexpr double k_floor_snap_m = 0.05;
FloorEstimate floor_estimate(const Clip& clip, const BodyMap& body_map);

} // namespace kumite
