#pragma once
// One strike, on its own: a character standing at the origin in the guard, its retriever over a database, and the
// order (semantics, side, kind, height) checked against what the database holds. What `kumite query`, `kumite
// adapt` and the Python module's query and adapt share.

#include "kumite/core/character_rig.h"
#include "kumite/core/retrieval.h"
#include "kumite/formats/bvh_reader.h"
#include "kumite/formats/motion_database_file.h"

#include <memory>
#include <string>

namespace kumite {

struct StrikeRequest {
    std::string semantics;                    // "punch", "kick", ...
    Side side = Side::none;                   // none: either
    StrikeKind kind = StrikeKind::none;       // none: any
    StrikeHeight height = StrikeHeight::none; // none: any
    RetrievalSettings settings;
};

struct StrikeStage {
    BvhFile character;
    RestAnatomy anatomy;
    std::unique_ptr<CharacterRig> rig;
    std::unique_ptr<Retriever> retriever;
    Pose standing;                        // the guard at the origin, facing +Z
    std::array<float, k_feature_dimensions> feature{};
    RetrievalQuery query;                 // everything but the target
};

// `database_name` and `character_name` name them in errors. Errors (invalid): a character whose body parts are not
// found, a semantics the database lacks (listing those it has), an order no strike of the database fits.
Result<std::unique_ptr<StrikeStage>> strike_stage_create(const MotionDatabaseView& database, BvhFile character, const std::string& character_name,
                                                         const StrikeRequest& request, const std::string& database_name);

// "punch left hook high": an order in words, the parts given only.
std::string strike_order_description(std::string_view semantics, Side side, StrikeKind kind, StrikeHeight height);
const char* side_name(Side side); // "left", "right", "none"

} // namespace kumite
