#pragma once
// The --characters-dir flag every command that takes a character shares, and recording a motion on a character
// (--record OUT.bvh or OUT.glb).

#include "arguments.h"

#include "kumite/core/clip.h"
#include "kumite/core/result.h"
#include "kumite/formats/bvh_reader.h"
#include "kumite/formats/character_catalog.h"

#include <filesystem>
#include <optional>
#include <string>

namespace kumite::cli {

FlagSpec characters_dir_flag();
// --characters-dir, else data/characters.
std::filesystem::path characters_folder(const Arguments& arguments);

// Why `path` cannot take a recording (kumite writes binary .glb, not .gltf), or nullopt: checked before the work.
std::optional<std::string> recording_path_problem(const std::string& path);

// Writes `motion` (on `character`'s skeleton) to `path`: a .glb with the character's body when it has one
// (character NAME of `folder`, or NAME a path to a glTF file), otherwise a BVH in the character's own layout
// and unit. .gltf is refused (kumite writes binary glTF).
Result<void> write_recording(const std::string& path, const Clip& motion, const BvhFile& character, const std::filesystem::path& folder,
                             const std::string& character_name);

} // namespace kumite::cli
