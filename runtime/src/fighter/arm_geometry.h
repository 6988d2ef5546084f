#pragma once
// The arm's geometry for blocks (fighter_defence.h, captured_block_arm.h): an elbow that keeps its bend, the wrist
// that puts a forearm's contact point on a course, a blend about the shoulder, and an arm's move held to a speed.
// Functions of what they are given, no state.

#include "kumite/core/rest_anatomy.h"

#include <Eigen/Core>

namespace kumite {

// The elbow's swivel that keeps its bend `bend` (carried over to the shoulder->wrist line `root` -> `wrist`), or
// `fallback` when the limb has no bend there.
double swivel_keeping_bend(const Eigen::Vector3d& root, const Eigen::Vector3d& wrist, const Eigen::Vector3d& bend, const Eigen::Vector3d& reference,
                           double fallback);

// The wrist offset that puts a block's contact point (a third of the way from the wrist to the elbow) on `target`,
// for an arm from `root` to `wrist` whose elbow keeps the bend `bend`: the elbow follows the wrist, so a few passes.
Eigen::Vector3d contact_offset(const LimbChain& chain, const Eigen::Vector3d& root, const Eigen::Vector3d& wrist, const Eigen::Vector3d& bend,
                               const Eigen::Vector3d& reference, const Eigen::Vector3d& target);

// `from` turned towards `to` (both from a limb's root) by `weight` of the angle between them, its length blended
// alike: the extremity keeps its distance from the root all the way, as a straight blend does not.
Eigen::Vector3d blend_about_root(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double weight);

// The arm's move this frame cut to at most `max_step` (wrist and elbow, relative to the shoulder): the largest share
// of the way from the arm shown last frame (`last_wrist`, `last_elbow`) to the asked one (`wrist`, its elbow bending
// towards `bend`; `swivel` where it has no bend), wrist and elbow turned about the shoulder as the block's blend
// turns them, the elbow's bend then as the decoder will place it. Whether it had to.
bool limit_arm_step(const LimbChain& chain, const Eigen::Vector3d& reference, double swivel, const Eigen::Vector3d& last_wrist,
                    const Eigen::Vector3d& last_elbow, double max_step, Eigen::Vector3d& wrist, Eigen::Vector3d& bend);

} // namespace kumite
