#include "fighter_setup.h"

#include "capture_loading.h"
#include "character_catalog.h"
#include "default_database.h"

#include <cstdio>

namespace kumite::cli {

Result<Eigen::Vector3d> parse_point(const std::string& text, const std::string& where) {
    Eigen::Vector3d point;
    char extra = 0;
    if (std::sscanf(text.c_str(), " %lf , %lf , %lf %c", &point.x(), &point.y(), &point.z(), &extra) != 3 || !point.allFinite()) {
        return make_error(ErrorCode::invalid, where + ": expected X,Y,Z in metres, not '" + text + "'");
    }
    if (point.cwiseAbs().maxCoeff() > 1000.0) { // a room is metres wide; this is a typo or a wrong unit
        return make_error(ErrorCode::invalid, where + ": " + text + " is more than 1 km away (metres expected)");
    }
    return point;
}

FlagSpec kind_flag() { return {"kind", "KIND", "which kind: straight, hook, uppercut (punches), front, roundhouse, side (kicks), other, any (default)"}; }
FlagSpec height_flag() { return {"height", "low|middle|high|any", "where the strike lands on its actor (default any)"}; }

std::optional<int> fighter_setup(FighterSetup& setup, const CommandSpec& spec, const Arguments& arguments) {
    const std::optional<std::string> character_name = arguments.value("character");
    const std::optional<std::string> command = arguments.value("command");
    if (!character_name) return usage_error(spec, "--character NAME is required");
    if (!command) return usage_error(spec, "--command SEMANTICS is required (punch, kick, ...)");
    Side side = Side::none;
    if (const std::optional<std::string> name = arguments.value("side"); name && *name != "any") {
        if (*name != "left" && *name != "right") return usage_error(spec, "--side must be left, right or any, not '" + *name + "'");
        side = *name == "left" ? Side::left : Side::right;
    }
    StrikeKind kind = StrikeKind::none;
    if (const std::optional<std::string> name = arguments.value("kind"); name && *name != "any") {
        const std::optional<StrikeKind> parsed = strike_kind_from_name(*name);
        if (!parsed || *parsed == StrikeKind::none || !strike_kind_fits(*command, *parsed)) {
            return usage_error(spec, "--kind '" + *name + "' is not a kind of " + *command +
                                         (*command == "punch" ? " (straight, hook, uppercut, other, any)" : *command == "kick" ? " (front, roundhouse, side, other, any)" : " (other, any)"));
        }
        kind = *parsed;
    }
    StrikeHeight height = StrikeHeight::none;
    if (const std::optional<std::string> name = arguments.value("height"); name && *name != "any") {
        const std::optional<StrikeHeight> parsed = strike_height_from_name(*name);
        if (!parsed || *parsed == StrikeHeight::none) return usage_error(spec, "--height must be low, middle, high or any, not '" + *name + "'");
        height = *parsed;
    }
    RetrievalSettings settings;
    if (const std::optional<std::string> scaling = arguments.value("scaling")) {
        if (*scaling != "leg" && *scaling != "limb") return usage_error(spec, "--scaling must be leg or limb");
        settings.scaling = *scaling == "leg" ? RetrievalScaling::leg_length : RetrievalScaling::limb_length;
    }
    const std::optional<std::string> folder = arguments.value("characters-dir");
    Result<BvhFile> character = load_character(folder ? std::filesystem::path(*folder) : default_characters_dir(), *character_name);
    if (!character) return usage_error(spec, character.error().message);

    Result<std::filesystem::path> path = database_path_from(arguments);
    if (!path) return input_error(path.error().message);
    setup.database_path = path->string();
    Result<MotionDatabase> database = MotionDatabase::open(*path, arguments.has("verify"));
    if (!database) return input_error(database.error().message);
    setup.database = std::move(*database);
    Result<std::unique_ptr<StrikeStage>> stage =
        strike_stage_create(setup.database.view(), std::move(*character), *character_name, {*command, side, kind, height, settings}, setup.database_path);
    if (!stage) return input_error(stage.error().message);
    setup.stage = std::move(*stage);
    return std::nullopt;
}

} // namespace kumite::cli
