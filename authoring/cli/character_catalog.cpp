#include "character_catalog.h"

namespace kumite::cli {

FlagSpec characters_dir_flag() {
    return {"characters-dir", "DIR", "where the character files are (default data/characters)"};
}

} // namespace kumite::cli
