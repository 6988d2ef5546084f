#pragma once
// The characters a bout can switch between: every character of a folder (formats/character_catalog.h), plus a
// character file of one's own given by path, each with its skinned body when it has one; and which one starts.

#include "kumite/formats/character_catalog.h"
#include "kumite/runtime/bout.h"

#include <filesystem>
#include <string>
#include <vector>

namespace kumite {

struct BoutCast {
    std::vector<CharacterEntry> entries;   // where each came from, in the characters' order
    std::vector<BoutCharacter> characters; // read, with their bodies
    int start = 0;                         // the starting one
};

// `wanted`: a character of `folder` by name, or a .bvh/.glb/.gltf path (it joins the others under its stem); empty:
// the first of the folder. Errors: an empty folder or an unreadable file (io, parse), an unknown name (invalid).
Result<BoutCast> load_bout_cast(const std::filesystem::path& folder, std::string wanted);

} // namespace kumite
