#pragma once
// What `kumite query` and `kumite adapt` share: the database, a character standing at the origin in the guard,
// its retriever, and the order (--command, --side, --kind, --height) read from the command line.

#include "arguments.h"

#include "strike_stage.h"

#include "kumite/formats/motion_database_file.h"

#include <memory>

namespace kumite::cli {

struct FighterSetup {
    std::string database_path;  // as given, or the default (default_database.h)
    MotionDatabase database;
    std::unique_ptr<StrikeStage> stage; // the character in its guard, its retriever, the query but its target
};

// Reads DB (positional 0, or the default database when absent), --character, --command, --side, --kind, --height,
// --scaling (an order the database cannot serve is refused). Returns the exit status on failure
// (after printing why): 2 for usage errors, 1 for bad input.
std::optional<int> fighter_setup(FighterSetup& setup, const CommandSpec& spec, const Arguments& arguments);

// Parses "X,Y,Z" (metres, finite); `where` names it in the error.
Result<Eigen::Vector3d> parse_point(const std::string& text, const std::string& where);

// The --kind and --height flags of query and adapt.
FlagSpec kind_flag();
FlagSpec height_flag();

} // namespace kumite::cli
