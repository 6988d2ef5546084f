#pragma once
// The skeleton and body map of a glTF character from its skin's joints (formats/src only): the body tree of the
// rig (gltf_rig.h), a hips joint hung under the trunk re-hung above it, and the body map from a VRM humanoid,
// names and structure, in that order of trust.

#include "gltf_rig.h"
#include "gltf_vrm.h"
#include "kumite/core/body_map.h"
#include "kumite/core/result.h"

#include <Eigen/Core>

#include <filesystem>
#include <string>
#include <vector>

namespace kumite::gltf {

// The skin's joints, indexed as the skin lists them.
struct SkinJoints {
    std::vector<int> parent;                 // nearest ancestor that is a joint, -1 for none
    std::vector<int> node_depth;             // depth of the joint's node in the node tree
    std::vector<std::string> names;
    std::vector<Eigen::Matrix4d> rest;       // rest world transforms
    std::vector<Eigen::Vector3d> positions;  // their translations
    std::vector<Eigen::Vector3d> tips;       // the farthest rest point of the mesh each moves most, from it (zero: none)
};

struct BodySkeleton {
    Skeleton skeleton;                       // parents first, identity rest rotations, world-axis offsets
    std::vector<int> skeleton_of_skin;       // [skin joint] skeleton joint, -1 when left out
    BodyMap body_map;
    std::vector<std::string> warnings;
};

// `weights[k]`: skin joint k's weight summed over the vertices. `vrm`: the avatar's bone map (on nodes; `skin_nodes[k]` is skin joint k's node), or null.
BodySkeleton body_skeleton(const SkinJoints& joints, const std::vector<double>& weights, const VrmHumanoid* vrm, const std::vector<int>& skin_nodes);

// Refuses a body map without every part a strike needs, listing them all and how to give them (`sidecar`, a
// .bodymap.json beside the file).
Result<void> check_strike_parts(const BodyMap& body_map, const std::filesystem::path& sidecar);

} // namespace kumite::gltf
