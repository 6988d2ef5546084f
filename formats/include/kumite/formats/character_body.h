#pragma once
// A character's skinned body on the skeleton it moves with: the glTF body beside a BVH character (NAME.glb beside
// NAME.bvh), or the glTF character file itself. The body's joints are found in the skeleton by name, so its mesh
// indexes the skeleton the fighter animates; the two rest poses must agree (same joints where the mesh is bound,
// each within 1% of the height), otherwise the body would not sit on the bones and is refused.

#include "kumite/core/result.h"
#include "kumite/core/skeleton.h"
#include "kumite/formats/gltf_reader.h"

#include <filesystem>
#include <optional>
#include <string>

namespace kumite {

// The body's mesh with its joint indices and bind_to_rest moved onto `skeleton`.
Result<SkinnedMesh> body_on_skeleton(const GltfCharacter& body, const Skeleton& skeleton, const std::string& body_source);

// The body of character NAME in `folder` (or NAME a path to a .glb/.gltf), on `skeleton`; nullopt for a character
// without one (a BVH alone).
Result<std::optional<SkinnedMesh>> load_character_body(const std::filesystem::path& folder, const std::string& name, const Skeleton& skeleton);

} // namespace kumite
