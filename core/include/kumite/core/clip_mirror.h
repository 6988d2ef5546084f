#pragma once
// Mirroring a clip left <-> right: every joint trades its motion with its partner (LeftHand <-> RightHand, by
// the side marks of the names), reflected in the world across the plane x = 0. Rest poses need not be physical
// (Bandai's puts the hips' left-right axis along Y and the chest's along Z), so each joint has its own local
// reflection, found from its children's offsets: a local rotation q becomes R_parent q_partner R_joint. The
// skeleton must be symmetric: those reflections must map every child offset's direction onto its partner's. The result is a
// clip on the same skeleton where a right kick becomes a left kick.

#include "kumite/core/body_map.h"
#include "kumite/core/clip.h"
#include "kumite/core/result.h"

#include <vector>

namespace kumite {

struct MirrorSymmetry {
    Eigen::Matrix3d reflection = Eigen::Vector3d(-1, 1, 1).asDiagonal(); // world: x -> -x
    std::vector<int> partner;                                             // [joint] partner (itself on the midline)
    std::vector<Eigen::Matrix3d> local_reflections;                       // [joint] in the joint's rest frame

    // The local rotation of `joint` in the mirrored clip, from its partner's local rotation.
    Eigen::Quaterniond mirror_local_rotation(int joint, const Eigen::Quaterniond& partner_rotation, int parent) const;
};

// Finds partners and reflections; an error names the first joint without a partner or out of symmetry. Offsets
// pair up by direction: the reflected direction must land within `direction_tolerance` (about radians) of the
// partner's, and an offset shorter than `tolerance_m` must have a short partner. Lengths may differ: captured
// skeletons are measured on real, slightly asymmetric bodies (CMU's finger bases differ by 10%); the mirrored
// motion keeps each side's own bone lengths.
// `translation_animated` ([joint], may be empty) marks joints whose offset the motion replaces (BVH position
// channels): when a joint's child offsets do not fit, it is tried again without those, whose rest offsets then
// say nothing about symmetry (Bandai's dance captures put the hips' rest offset 11 cm off the midline, then
// animate it).
Result<MirrorSymmetry> mirror_symmetry_find(const Skeleton& skeleton, double tolerance_m = 1e-3, double direction_tolerance = 0.1,
                                            const std::vector<bool>& translation_animated = {});

Clip clip_mirror(const Clip& clip, const MirrorSymmetry& symmetry);

} // namespace kumite
