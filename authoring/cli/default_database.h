#pragma once
// The motion database `kumite play`, `query` and `adapt` use when none is given: $KUMITE_DB, else the reference
// annotations (data/annotations/reference.json) baked once into a cache folder ($KUMITE_CACHE_DIR, else
// $XDG_CACHE_HOME/kumite, else ~/.cache/kumite) and baked again when the annotations, their captures or the
// database format change (one line on stderr says so). Without captures the error says how to get them.
// $KUMITE_ANNOTATIONS names other annotations to bake by default.

#include "arguments.h"

#include "kumite/core/result.h"

#include <filesystem>

namespace kumite::cli {

Result<std::filesystem::path> default_database_path();

// The database a command was given (its first positional), else default_database_path().
Result<std::filesystem::path> database_path_from(const Arguments& arguments);

} // namespace kumite::cli
