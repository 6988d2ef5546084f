#pragma once
// glTF 2.0 characters (.glb, or .gltf with its buffers): the skin's joints as the project's skeleton, plus the
// skinned mesh to draw it with. Read with tinygltf (Debian's libtinygltf-dev, compiled into this library without
// image decoding: only geometry, skin and base colour are used).
//
// The skeleton: the joints of the file's skins (skin 0's first) that make the body, each parented to its nearest ancestor
// that is a joint too (one root); control joints (IK targets, IK/FK copies) are left out and IK rigs' detached feet
// attached back to their legs, with warnings in `character.warnings` (src/gltf_rig.h). Its rest pose is the nodes'
// own transforms (TRS or matrix) through the whole node tree, so a scale (a Mixamo armature at 0.01) or an axis
// change on an ancestor is baked in — or the bind pose from the inverse bind matrices when the nodes are not in it:
// rest offsets are world-axis vectors between joints in metres (glTF's unit), Y up, identity rotations at rest,
// as the BVH reader gives. The clip has one frame, the rest pose. The body map comes from a VRM humanoid bone map,
// the joint names (Mixamo, Unreal, Blender/Rigify, VRM/VRoid among others) and the skeleton's structure.
//
// The mesh (kumite/core/skinned_mesh.h): every triangle primitive skinned by any skin, positions and normals in
// bind space, up to 4 joints and weights per vertex (renormalised; indices into the skeleton), the material's
// base colour, and bind_to_rest from the inverse bind matrices.
//
// Refused, with a message naming what and where (node, accessor, primitive index): not glTF; truncated or
// inconsistent buffers; accessors out of their buffer views; indices or joints out of range; NaN or infinite
// numbers; no skin; a skin with no joints or more than k_gltf_max_joints; a skeleton with no whole humanoid body
// (pelvis, chest, head, arms and legs: every missing part listed); a standing height outside 0.3-5 m.

#include "kumite/core/result.h"
#include "kumite/core/skinned_mesh.h"
#include "kumite/formats/bvh_reader.h"

#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>
#include <vector>

namespace kumite {

inline constexpr int k_gltf_max_joints = 1024;
inline constexpr std::size_t k_gltf_max_vertices = 4'000'000;
inline constexpr std::size_t k_gltf_max_file_bytes = std::size_t(512) << 20;

struct GltfCharacter {
    BvhFile character; // skeleton, one rest frame, body map, a BVH layout (root: position + ZXY, joints: ZXY)
    SkinnedMesh mesh;
    int node_count = 0;
};

// `bytes` are a .glb, or a .gltf's JSON (external buffers are read relative to `base_dir`).
// `body_map_file`, when it exists, fixes or completes the detected body map (a .bodymap.json; gltf_read_file
// passes the sidecar beside the file).
Result<GltfCharacter> gltf_parse(std::span<const std::uint8_t> bytes, std::string_view source_name, const std::filesystem::path& base_dir = {},
                                 const std::filesystem::path& body_map_file = {});
Result<GltfCharacter> gltf_read_file(const std::filesystem::path& path);

// True for names ending in .glb, .gltf or .vrm (any case).
bool is_gltf_path(const std::filesystem::path& path);

} // namespace kumite
