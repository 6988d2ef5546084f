#pragma once
// Where on the user a strike aims, and how far the fighter's arms reach it (fighter.h): the head, else the highest
// of chin, chest and solar plexus under it (TargetPart), scaled by the user's size. Functions of what they are
// given, no state.

#include "fighter/character_body.h"

#include "kumite/runtime/fighter_settings.h"

#include <Eigen/Core>

namespace kumite {

inline constexpr int k_target_part_count = 4;
// The points a strike may aim at, highest first.
inline constexpr TargetPart k_target_parts[k_target_part_count] = {TargetPart::head, TargetPart::chin, TargetPart::chest, TargetPart::solar_plexus};

// The first part an order of `height` aims at (an index of k_target_parts): high or any, the head; middle, the
// chest; low, the solar plexus. Lower parts are looked at after it when it is out of reach or covered.
inline int first_target_part(StrikeHeight height) { return height == StrikeHeight::middle ? 2 : height == StrikeHeight::low ? 3 : 0; }

// How far under the user's head the target part `part` (an index of k_target_parts) is: 0.10, 0.30 and 0.45 m under
// a 1.65 m head, scaled by the user's size (head height / 1.65 m).
double drop_under_head_m(int part, const Eigen::Vector3d& head);
// The point a strike at part `part` meets, from the head: the part's drop under it, and `surface_depth_m` towards
// `fighter` on the floor plane (a fist or foot lands on the face or the front of the body, not at the head's
// centre inside it).
Eigen::Vector3d aim_offset(int part, const Eigen::Vector3d& head, const Eigen::Vector3d& fighter, double surface_depth_m);

// How far from the pelvis (horizontally, metres) the arms of `body`, as shown, reach the user's head: the
// shoulder's lead plus what 90% of the arm spans at the head's height above the shoulder, plus a lean of 0.1 leg
// lengths. When the head is beyond the arms, the same at the highest body point under it that they reach
// (`fallback`); zero when none.
double strike_reach_m(const CharacterBody& body, const Eigen::Vector3d& head, bool fallback);

} // namespace kumite
