#pragma once
// Bent-arm punches (hooks, uppercuts) of one arm, found by the fist's swing rather than by the arm's extension: a
// hook or an uppercut lands with the elbow bent, so it never reaches the extension a straight punch peaks at.
// Internal to strike_detection.cpp; positions in metres in the capture's world (Y up), per frame.

#include "kumite/core/strike_thresholds.h"

#include <Eigen/Core>

#include <vector>

namespace kumite {

struct ArmTrack {
    std::vector<Eigen::Vector3d> shoulder, elbow, wrist; // [frame], world metres
    double upper_length = 0.0, lower_length = 0.0;       // metres, from the rest pose
};

struct SwingPunch {
    int first_frame = 0; // where the swing starts (the fist's speed valley before it)
    int hit_frame = 0;   // where the swing stops (its speed falls under a fifth of the fastest)
    double strength = 0.0; // 0..1, how far the swing clears its thresholds
};

// `hips_forward`: the hips' heading on the floor plane per frame (unit); `head_y`: the head joint's height; `other`: the other arm; `left`: whether `arm`
// is the left one.
std::vector<SwingPunch> swing_punches_detect(const ArmTrack& arm, const ArmTrack& other, const std::vector<Eigen::Vector3d>& pelvis,
                                             const std::vector<Eigen::Vector3d>& hips_forward,
                                             const std::vector<double>& head_y, bool left, double dt,
                                             const StrikeThresholds& thresholds);

} // namespace kumite
