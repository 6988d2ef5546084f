#pragma once
// Forward kinematics: local joint transforms to model (world) transforms. Allocation-free: the caller sizes
// the output spans to the skeleton's joint count. Positions in metres, in the clip's world axes.

#include "kumite/core/clip.h"

#include <span>

namespace kumite {

// model_positions / model_rotations: [joint_count] outputs. The root is placed at pose.root_translation;
// every other joint at its parent's transform applied to its local translation (or rest offset).
void forward_kinematics(std::span<Eigen::Vector3d> model_positions, std::span<Eigen::Quaterniond> model_rotations,
                        const Skeleton& skeleton, const PoseView& pose);

// End Site positions for a pose whose joints went through forward_kinematics: [end_site_count] output.
void end_site_positions(std::span<Eigen::Vector3d> end_site_model_positions, const Skeleton& skeleton,
                        std::span<const Eigen::Vector3d> model_positions,
                        std::span<const Eigen::Quaterniond> model_rotations);

// The largest | |child - parent| - rest length | over the bones of a pose whose joints use their rest offsets
// (metres): how far a pose stretches or shrinks its skeleton. With `pelvis`, the links from the joints above it
// (a Root on the floor, Bandai's joint_Root) to it are left out: they carry the root motion, not a bone.
double bone_length_error(const Skeleton& skeleton, std::span<const Eigen::Vector3d> model_positions, int pelvis = -1);

} // namespace kumite
