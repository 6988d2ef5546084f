#pragma once
// VRM avatars (formats/src only): a .vrm is a glTF binary whose `VRM` (0.x) or `VRMC_vrm` (1.0) extension names
// the node of each humanoid bone. That map outranks joint names and structure.
//
//   0.x: extensions.VRM.humanoid.humanBones = [{"bone": "leftUpperArm", "node": 12}, ...]
//   1.0: extensions.VRMC_vrm.humanoid.humanBones = {"leftUpperArm": {"node": 12}, ...}

#include "kumite/core/body_map.h"

#include <tiny_gltf.h>

#include <optional>
#include <string>
#include <vector>

namespace kumite::gltf {

struct VrmBone {
    BodyPart part;
    int node;
};

struct VrmHumanoid {
    std::string version; // "0.x" or "1.0"
    std::vector<VrmBone> bones; // the bones kumite has a part for, nodes checked to exist
    std::vector<std::string> warnings;
};

// The humanoid bone map of a VRM file; none when the file carries neither extension. A malformed map (not an
// object, a node out of range) gives warnings and leaves those bones out.
std::optional<VrmHumanoid> vrm_humanoid(const tinygltf::Model& model);

} // namespace kumite::gltf
