#pragma once
// The command line's --characters-dir flag; the catalog itself is kumite/formats/character_catalog.h.

#include "arguments.h"
#include "kumite/formats/character_catalog.h"

namespace kumite::cli {

FlagSpec characters_dir_flag();

} // namespace kumite::cli
