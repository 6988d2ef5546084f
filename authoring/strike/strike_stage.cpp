// One strike's stage (strike_stage.h).

#include "strike_stage.h"

namespace kumite {

const char* side_name(Side side) { return side == Side::left ? "left" : side == Side::right ? "right" : "none"; }

std::string strike_order_description(std::string_view semantics, Side side, StrikeKind kind, StrikeHeight height) {
    std::string text(semantics);
    if (side != Side::none) text += std::string(" ") + side_name(side);
    if (kind != StrikeKind::none) text += std::string(" ") + strike_kind_name(kind);
    if (height != StrikeHeight::none) text += std::string(" ") + strike_height_name(height);
    return text;
}

Result<std::unique_ptr<StrikeStage>> strike_stage_create(const MotionDatabaseView& db, BvhFile character, const std::string& character_name,
                                                         const StrikeRequest& request, const std::string& database_name) {
    auto stage = std::make_unique<StrikeStage>();
    stage->character = std::move(character);
    Result<RestAnatomy> anatomy = rest_anatomy_build(stage->character.clip, stage->character.body_map);
    if (!anatomy) return make_error(ErrorCode::invalid, "character " + character_name + ": " + anatomy.error().message);
    stage->anatomy = std::move(*anatomy);

    stage->retriever = std::make_unique<Retriever>(db, request.settings);
    const std::string& command = request.semantics;
    const int semantics = stage->retriever->semantics_id(command);
    if (semantics < 0 || command == "rest" || command.starts_with("step_")) {
        std::string known;
        for (const DbClip& clip : db.clips) {
            const std::string name(db.string(clip.semantics));
            if (db_clip_is_strike(clip) && known.find(name) == std::string::npos) known += (known.empty() ? "" : ", ") + name;
        }
        return make_error(ErrorCode::invalid, database_name + ": no '" + command + "' strikes in this database (it has: " + known + ")");
    }
    if (stage->retriever->candidate_count(semantics, request.side, request.kind, request.height) == 0) {
        return make_error(ErrorCode::invalid, database_name + ": " + strike_order_description(command, request.side, request.kind, request.height) +
                                                  ": the database holds no such strike (kumite db-info lists what it has)");
    }
    stage->rig = std::make_unique<CharacterRig>(stage->character.clip.skeleton, stage->anatomy);
    stage->rig->stand_at_origin(stage->standing, db);
    stage->rig->still_feature(stage->feature);
    stage->query.pose_feature = stage->feature;
    stage->query.heading = stage->rig->heading();
    stage->query.semantics = semantics;
    stage->query.side = request.side;
    stage->query.kind = request.kind;
    stage->query.height = request.height;
    stage->query.character = stage->rig->size();
    return stage;
}

} // namespace kumite
