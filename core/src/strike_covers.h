#pragma once
// Blocks that raise an upright forearm before the head or beside it: a karateka's middle and outward blocks
// (uchi-uke, soto-uke, shuto-uke) and a boxer's covers (the gloves brought up to the face, or to one side of the head,
// and held). The sweeping blocks (rising age-uke, downward gedan-barai) are found by their sweep in
// strike_detection.cpp. Internal to strike_detection.cpp; positions in metres in the capture's world (Y up).

#include "strike_swings.h"

#include "kumite/core/strike_thresholds.h"

#include <Eigen/Core>

#include <vector>

namespace kumite {

struct CoverBlock {
    int first_frame = 0;   // where the wrist starts to rise (its lowest point in the 0.6 s before)
    int hit_frame = 0;     // where it is highest over the head
    double strength = 0.0; // 0..1, how far it clears its thresholds
};

// `head`: the head joint per frame; `hips_forward`: the hips' heading on the floor plane per frame (unit); `left`:
// whether `arm` is the left one.
std::vector<CoverBlock> cover_blocks_detect(const ArmTrack& arm, const std::vector<Eigen::Vector3d>& head,
                                            const std::vector<Eigen::Vector3d>& hips_forward, bool left, double dt,
                                            const StrikeThresholds& thresholds);

} // namespace kumite
