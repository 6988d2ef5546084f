#pragma once
// The fingers of a skeleton closed into fists. Captures drive no fingers, so a body with finger joints would hold
// its bind pose's open hands (straight fingers, like claws); a fighter guards and strikes with closed fists.
// Computed once per skeleton, from its rest pose alone (identity rest rotations, Y up), so it holds on any rig:
//
//   - The fingers of a hand are the chains from the hand joint to each leaf below it; a joint shared by several
//     chains is the palm. A chain's tip is its leaf's End Site (or the leaf). A finger has two joints at least
//     (a lone joint below the wrist is the palm's bone or a prop's) and reaches 40% of the longest one's reach.
//   - The thumb is the chain whose tip reaches least far along the forearm's line (under 80% of the next one's).
//   - The palm's normal: across the knuckles (from the knuckle nearest the thumb to the farthest) crossed with the
//     hand's direction (wrist to the knuckles), its sign the hand's side (a right hand's palm is on the other side
//     of a left one's); without a thumb, down and towards the body, square to the hand.
//   - Each finger bends about its own axis, square to its direction (knuckle to tip) and to the palm's normal,
//     towards the palm: 90 degrees at its knuckle (its first joint past the palm: joints nearer the wrist than 30%
//     of the tip's distance are in the palm; two joints at least past it), 100 at the middle joint, 60 at the last.
//   - The thumb folds across: its first joint turns it onto the two fingers nearest it, its tip laid on the front
//     of their curled middle joints, the other thumb joints bending in the same plane when it is longer than the way.
//
// A hand with no joint below it (the shipped mannequins) keeps identity rotations: nothing changes.

#include "kumite/core/body_map.h"
#include "kumite/core/skeleton.h"

#include <Eigen/Geometry>

#include <span>
#include <vector>

namespace kumite {

// [joint] local rotation, in the parent's frame, of each finger joint in a fist; identity for every other joint.
// `rest_positions`: [joint] model positions of the rest pose (metres).
std::vector<Eigen::Quaterniond> fist_local_rotations(const Skeleton& skeleton, const BodyMap& body_map,
                                                     std::span<const Eigen::Vector3d> rest_positions);

} // namespace kumite
