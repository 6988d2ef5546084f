#pragma once
// Strike suggestions from a capture alone, for the animator to confirm.
//
// The rule, per limb, on the pose's own anatomy (so any size, unit or rest convention works):
// - punch, straight: the hand's extension |wrist - shoulder| / arm length peaks above 0.78 with the hand away from
//   the chest (StrikeThresholds::punch_reach on the floor plane: fighters stand bladed, so not necessarily where
//   the chest faces), no lower than 0.5 arm length below the shoulder (a low punch from a crouch reaches 0.4; an arm
//   swung while walking hangs 0.8 below) and not behind it along the hips' heading, and not during a kick (arms fly
//   out for balance then), not above the head by 0.3 arm length (a rising block), nor at the head's height under a
//   raised elbow with the arm still bent (a rising block on its way up), thrown (the extension grew by punch_rise
//   in the 0.6 s before: an arm held out in a karate guard is not), after the hand moved at 1.5 arm lengths per
//   second or more in the 0.3 s before; the hit frame is the extension peak (where the hand's speed falls to a
//   minimum). Both arms thrust out together (within both_arms_s) are a push or a dance, neither a punch;
// - punch, hook or uppercut: the fist swings (strike_swings.h) at swing_speed or more relative to the pelvis and
//   stops with the elbow bent, the fist in front at or over the shoulder, the forearm flat across (a hook) or
//   upright after rising from below (an uppercut), the other hand up at the guard (swing_guard_height; a
//   karateka's pulled back to the hip goes with blocks and elbow strikes); the hit frame is where the swing stops;
// - kick: the ankle rises above 0.35 leg length over its standing height, and in that raised interval the leg
//   straightens (hip-ankle distance above 0.85 leg length) with the ankle away from the hip on the floor plane
//   (0.3 leg length, any direction: front, side and round kicks) and at most 0.3 leg length behind it along the
//   hips' heading (a side kick turns the hips away; a leg swung back is no kick); the
//   hit frame is the highest frame among the straightest (full extension, where the foot would meet a target);
// - knee: a raised ankle whose leg stays folded (below 0.85) with the knee 0.3 leg length above its standing
//   height; the hit frame is the knee's highest point. Arm peaks from 0.6 s before a knee strike to its end are
//   the hands pulling the opponent's head onto it, not punches;
// - block: see detect_blocks in strike_detection.cpp (a rising or downward sweep of the forearm that stops in front
//   of the body, not thrust out at a target), and src/strike_covers.h (an upright forearm raised to the head's
//   height above where that hand usually is, and let down again: a middle block, a boxer's cover), not around a
//   punch of either hand; the hit frame is where the sweep stops, or where the raised wrist is highest;
// - reach (any part asked for by name): peaks of the part's distance from the pelvis, relative to its rest
//   distance, that stand 0.1 above the valleys on both sides.
// Peaks closer than 0.3 s keep the stronger. A strike spans from the extension valley before the hit to the one
// after (at most 1 s each way). Confidence grows with how far the peak clears its thresholds. Each strike's kind
// and height are proposed by strike_labels_propose over its span up to the hit.

#include "kumite/core/body_map.h"
#include "kumite/core/rest_anatomy.h"
#include "kumite/core/strike_labels.h"
#include "kumite/core/strike_thresholds.h"

#include <optional>
#include <vector>

namespace kumite {

enum class StrikeSemantics { punch, kick, knee, elbow, block, reach };

struct StrikeSuggestion {
    StrikeSemantics semantics = StrikeSemantics::punch;
    BodyPart segment = BodyPart::hand_r;
    Side side = Side::right;
    int hit_frame = 0;
    int first_frame = 0;
    int last_frame = 0;
    double confidence = 0.0; // 0..1
    StrikeLabels labels;     // proposed kind and height (strike_labels.h); none for reach peaks
};

// With `segment`, reports reach peaks of that part instead of punches and kicks. A clip without a frame rate
// (Clip::has_frame_rate) has no speeds: nothing is proposed; callers refuse it with a message first.
// `thresholds`: the measured thresholds by name (strike_thresholds.h), the chosen defaults unless an evaluation
// tries others.
std::vector<StrikeSuggestion> strikes_detect(const Clip& clip, const RestAnatomy& anatomy,
                                             std::optional<BodyPart> segment = std::nullopt, const StrikeThresholds& thresholds = {});

const char* strike_semantics_name(StrikeSemantics semantics);

} // namespace kumite
