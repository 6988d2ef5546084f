#pragma once
// The characters shipped in data/characters (one BVH per character whose first frame is its rest pose, the file's
// stem the character's name; glTF bodies beside them), and where the project's data folders are, for every tool that needs them.

#include "kumite/formats/bvh_reader.h"

#include <filesystem>
#include <string>
#include <vector>

namespace kumite {

// $ENVIRONMENT_VARIABLE, else `relative` in the working directory, else the repository's found from the
// executable or the shared library this code is in (build/bin/kumite, build/lib/libkumite.so, build/python/kumite*.so
// -> data/...), else `relative` as it is.
std::filesystem::path locate_data_folder(const char* environment_variable, const std::filesystem::path& relative);

// $KUMITE_CHARACTERS_DIR, else data/characters (see locate_data_folder).
std::filesystem::path default_characters_dir();

struct CharacterEntry {
    std::string name;
    std::filesystem::path file; // the skeleton and rest pose: the .bvh, else the glTF file
    std::filesystem::path body; // the skinned body (.glb/.gltf), if any
};
// The characters of `folder`, sorted by name: each .bvh (with NAME.glb or NAME.gltf beside it as its body), and each
// glTF file without a BVH of its name (skeleton and body from the one file).
std::vector<CharacterEntry> list_characters(const std::filesystem::path& folder);

// True for an existing .bvh, .glb or .gltf file: a character of one's own, passed by path.
bool character_file_exists(const std::filesystem::path& path);

// Reads a character file: BVH, or glTF (its skeleton and rest pose; gltf_reader.h).
Result<BvhFile> read_character_file(const std::filesystem::path& path);

// Reads the character NAME of `folder`, or NAME as a path to a .bvh/.glb/.gltf file; an unknown name is an error
// listing the known ones.
Result<BvhFile> load_character(const std::filesystem::path& folder, const std::string& name);

} // namespace kumite
