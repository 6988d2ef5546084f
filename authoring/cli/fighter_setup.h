#pragma once
// What `kumite query` and `kumite adapt` share: the database, a character standing at the origin in the guard,
// its retriever, and the order (--command, --side, --kind, --height) read from the command line.

#include "arguments.h"

#include "kumite/core/character_rig.h"
#include "kumite/core/retrieval.h"
#include "kumite/formats/bvh_reader.h"
#include "kumite/formats/motion_database_file.h"

#include <memory>

namespace kumite::cli {

struct FighterSetup {
    std::string database_path;  // as given, or the default (default_database.h)
    MotionDatabase database;
    BvhFile character;
    RestAnatomy anatomy;
    std::unique_ptr<CharacterRig> rig;
    std::unique_ptr<Retriever> retriever;
    Pose standing;                                   // the guard at the origin, facing +Z
    std::array<float, k_feature_dimensions> feature{};
    RetrievalQuery query;                            // everything but the target
};

// Reads DB (positional 0, or the default database when absent), --character, --command, --side, --kind, --height,
// --scaling (an order the database cannot serve is refused). Returns the exit status on failure
// (after printing why): 2 for usage errors, 1 for bad input.
std::optional<int> fighter_setup(FighterSetup& setup, const CommandSpec& spec, const Arguments& arguments);

// Parses "X,Y,Z" (metres, finite); `where` names it in the error.
Result<Eigen::Vector3d> parse_point(const std::string& text, const std::string& where);

const char* side_name(Side side);
// "punch left hook high": an order in words, the parts given only.
std::string strike_order_description(std::string_view semantics, Side side, StrikeKind kind, StrikeHeight height);
// The --kind and --height flags of query and adapt.
FlagSpec kind_flag();
FlagSpec height_flag();

} // namespace kumite::cli
