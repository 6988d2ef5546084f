#pragma once
// The characters shipped in data/characters: one BVH per character whose first frame is its rest pose; the
// file's stem is the character's name.

#include "arguments.h"
#include "kumite/formats/bvh_reader.h"

#include <filesystem>
#include <string>
#include <vector>

namespace kumite::cli {

// $KUMITE_CHARACTERS_DIR, else data/characters in the working directory, else the repository's beside the
// executable (build/bin/kumite -> data/characters).
std::filesystem::path default_characters_dir();

struct CharacterEntry {
    std::string name;
    std::filesystem::path file;
};
std::vector<CharacterEntry> list_characters(const std::filesystem::path& folder);

// Reads the character NAME; an unknown name is an error listing the known ones.
Result<BvhFile> load_character(const std::filesystem::path& folder, const std::string& name);

FlagSpec characters_dir_flag();

} // namespace kumite::cli
