#pragma once
// The thresholds of strike detection (strike_detection.h) that were chosen by measurement, by name, so that an
// evaluation can choose them on some performers and score them on another (scripts/suggest_lopo.py, leave one
// performer out) and `kumite suggest --thresholds` can try other values. Lengths are in arm lengths (shoulder to
// wrist), speeds in arm lengths per second, times in seconds. The defaults are the values that evaluation chose.

#include "kumite/core/result.h"

#include <string_view>

namespace kumite {

struct StrikeThresholds {
    // Straight punches (an extension peak): how far out from the chest on the floor plane the fist gets, at least.
    double punch_reach = 0.8;
    // How much a punch's extension grows in the 0.6 s before its hit (a punch is thrown; an arm held out is not).
    double punch_rise = 0.3;
    // Both arms thrust out together within this long (two-handed push, a dance, a wave): neither is a punch.
    double both_arms_s = 0.1;
    // Bent-arm punches (hooks, uppercuts: the fist swings, the arm does not straighten): the fist's peak speed
    // relative to the pelvis, at least.
    double swing_speed = 10.0;
    // ... and the other hand's height over its shoulder at the hit, at least: a boxer's other hand stays up at the
    // guard; a karateka's pulled back to the hip (hikite) goes with a block or an elbow strike that swings the fist.
    double swing_guard_height = -0.25;
    // An uppercut (a swing ending with the forearm upright) comes up from below: how far the fist rose in the 0.3 s
    // before the hit, at least. A middle block or a back-fist swings an upright forearm across at shoulder height.
    double uppercut_rise = 0.9;
    // A cover or a middle block (an upright forearm raised before the head or beside it, strike_covers.h): how far the
    // wrist rises to at least the head's height, and how far that is above where the hand usually is, at least.
    double cover_rise = 0.12;
    // ... and the forearm upright there: the sine of its slope, at least (0.7: within ~45 degrees of vertical).
    double cover_upright = 0.7;
};

// Reads "name=value,name=value" over the defaults; an unknown name or a value that is not a number is an error that
// lists the names.
Result<StrikeThresholds> strike_thresholds_parse(std::string_view text);

} // namespace kumite
