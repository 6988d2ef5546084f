#pragma once
// The characters shipped in data/characters (one BVH per character whose first frame is its rest pose; the file's
// stem is the character's name), and where the project's data folders are, for every tool that needs them.

#include "kumite/formats/bvh_reader.h"

#include <filesystem>
#include <string>
#include <vector>

namespace kumite {

// $ENVIRONMENT_VARIABLE, else `relative` in the working directory, else the repository's found from the
// executable (build/bin/kumite -> data/...), else `relative` as it is.
std::filesystem::path locate_data_folder(const char* environment_variable, const std::filesystem::path& relative);

// $KUMITE_CHARACTERS_DIR, else data/characters (see locate_data_folder).
std::filesystem::path default_characters_dir();

struct CharacterEntry {
    std::string name;
    std::filesystem::path file;
};
// The characters of `folder`, sorted by name.
std::vector<CharacterEntry> list_characters(const std::filesystem::path& folder);

// Reads the character NAME; an unknown name is an error listing the known ones.
Result<BvhFile> load_character(const std::filesystem::path& folder, const std::string& name);

} // namespace kumite
