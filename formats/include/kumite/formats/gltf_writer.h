#pragma once
// A motion on a character as a glTF 2.0 binary (.glb) that Blender, Unity, Unreal and Godot open with the body
// moving: one node per joint (translation = the rest offset, identity rest rotation, as the project's skeletons
// are), one animation with every joint's local rotation per frame and the root's position per frame (and the
// joints' translations when the clip has them), times frame * frame time, LINEAR. Given a body (its joints
// indexing the clip's skeleton: character_body.h), its skinned mesh is written bound to those joints with
// bind_to_rest as the inverse bind matrices, so the file's rest pose shows the body as it was read.

#include "kumite/core/clip.h"
#include "kumite/core/result.h"
#include "kumite/formats/gltf_reader.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace kumite {

// The .glb bytes. `body` may be null (a skeleton that moves, without a mesh).
Result<std::string> gltf_animation_glb(const Clip& motion, const SkinnedMesh* body, std::string_view animation_name);

// Written atomically (a temporary, then a rename).
Result<void> gltf_write_animation_file(const std::filesystem::path& path, const Clip& motion, const SkinnedMesh* body,
                                       std::string_view animation_name = "kumite");

} // namespace kumite
