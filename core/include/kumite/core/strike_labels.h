#pragma once
// What kind of strike a clip holds and at what height it lands, and how `kumite suggest` proposes both from the
// hit path alone.
//
// Kinds. Punches: straight (jab or cross: the fist travels forward), hook (it sweeps across, towards the body's
// midline), uppercut (it rises). Kicks: front (the foot rises forward), roundhouse (it sweeps round the body,
// across the front), side (it extends sideways, out to the kicking leg's side). Blocks (the defence's moves, whose
// contact point is the forearm, contact_point.h): rising (the forearm sweeps up over the head), downward (down
// across the front of the hips), inward (across the body towards the midline), outward (from the midline out to the
// blocking arm's side). `other` for strikes that are
// none of these (a slash); `none` means unlabelled (old annotation files, non-strikes).
//
// Heights, from the hit point (the hit segment's joint at the hit frame) above the floor, relative to the actor
// standing: low below the hip (ankle height + leg length), high above the shoulder (hip height + the rest
// distance from the hips' midpoint to the shoulders' midpoint), middle between.
//
// Proposal rule. Fighters stand bladed and turn as they strike, so directions are taken from the strike itself,
// not from where the hips face: the strike line is the horizontal direction from the limb's root (shoulder or hip
// joint) to the hit point at the hit frame; the approach is the hit point's motion over the last 40% of the time
// from the first frame to the hit (at least 0.2 s and 2 frames), split into along the line, sideways to it (horizontal) and
// up (world vertical).
// - punch: uppercut when the approach rises more than it moves horizontally; hook when it moves sideways more
//   than along the line (the fist sweeps round, the arm bent); else straight (the arm extends along the line).
// - kick: roundhouse when the foot moves sideways more than along the line; side when the line is more than 55
//   degrees from where the hips face at the hit (the body turned side-on); else front.
// - block: rising when the forearm ends above the shoulder having risen; downward when it ends below halfway from
//   hip to shoulder having come down; else inward or outward by the sideways motion's sign relative to
//   the blocking arm's side.
// - any other semantics: other.

#include "kumite/core/body_map.h"
#include "kumite/core/rest_anatomy.h"

#include <cstdint>
#include <optional>
#include <string_view>

namespace kumite {

enum class StrikeKind : std::uint8_t { none = 0, straight, hook, uppercut, front, roundhouse, side, other, rising, downward, inward, outward };
inline constexpr int k_strike_kind_count = 12;
enum class StrikeHeight : std::uint8_t { none = 0, low, middle, high };
inline constexpr int k_strike_height_count = 4;

const char* strike_kind_name(StrikeKind kind);     // "none", "straight", ...
const char* strike_height_name(StrikeHeight height);
std::optional<StrikeKind> strike_kind_from_name(std::string_view name);
std::optional<StrikeHeight> strike_height_from_name(std::string_view name);
// The kinds that belong to a semantics: punch -> straight, hook, uppercut, other; kick -> front, roundhouse, side,
// other; block -> rising, downward, inward, outward, other; anything else -> other.
bool strike_kind_fits(std::string_view semantics, StrikeKind kind);

struct StrikeLabels {
    StrikeKind kind = StrikeKind::none;
    StrikeHeight height = StrikeHeight::none;
    // The measures behind them, for reports: the hit point's height above the floor (metres) and the thresholds,
    // and the approach (metres).
    double hit_height_m = 0.0;
    double hip_height_m = 0.0;
    double shoulder_height_m = 0.0;
    double approach_along_m = 0.0;    // towards the hit point along the strike line
    double approach_sideways_m = 0.0; // horizontal, across the strike line (unsigned)
    double approach_up_m = 0.0;
    double hips_to_line_deg = 0.0;    // where the hips face at the hit, to the strike line
};

// The standing heights that split low, middle and high for an actor (metres above its floor).
struct StrikeHeightThresholds {
    double hip_m = 0.0;
    double shoulder_m = 0.0;
};
StrikeHeightThresholds strike_height_thresholds(const RestAnatomy& anatomy);
StrikeHeight strike_height_of(double hit_height_m, const StrikeHeightThresholds& thresholds);

// Proposes a strike's kind and height from its clip frames first_frame .. hit_frame. `segment` is the hit body part.
StrikeLabels strike_labels_propose(const Clip& clip, const RestAnatomy& anatomy, std::string_view semantics, BodyPart segment,
                                   int first_frame, int hit_frame);

} // namespace kumite
