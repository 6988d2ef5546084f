// kumite suggest: punches and kicks proposed from captures alone (see core/strike_detection.h for the rule).

#include "capture_loading.h"
#include "commands.h"
#include "kumite/core/strike_detection.h"
#include "kumite/formats/annotation_file.h"

#include <iomanip>
#include <iostream>

namespace kumite::cli {

const CommandSpec& suggest_spec() {
    static const CommandSpec spec{
        "suggest",
        "FILE.bvh... [--segment PART] [--json]",
        "Proposes the strikes in captures: punches (hand extension peaks in front of the chest after a fast\n"
        "move) and kicks (ankle raised in front of the hip), each with its hit frame and span. With --segment\n"
        "PART, reports the extension peaks of that body part instead (semantics 'reach'). --write-annotations\n"
        "turns every suggestion into a clip (mirrored too), with paths relative to --mocap-root when under it.",
        1, 100000,
        {{"segment", "PART", "a body part (hand_l, foot_r, head, ...): report its extension peaks"},
         {"write-annotations", "OUT.json", "write every suggestion as a clip of an annotation file ready for bake"},
         unit_flag(), strict_flag(), mocap_root_flag(), body_map_flag(), json_flag()}};
    return spec;
}

namespace {

nlohmann::json strikes_json(const std::vector<StrikeSuggestion>& strikes) {
    nlohmann::json list = nlohmann::json::array();
    for (const StrikeSuggestion& strike : strikes) {
        list.push_back({{"semantics", strike_semantics_name(strike.semantics)},
                        {"segment", std::string(body_part_name(strike.segment))},
                        {"side", strike.side == Side::left ? "left" : strike.side == Side::right ? "right" : "none"},
                        {"hit_frame", strike.hit_frame},
                        {"first", strike.first_frame},
                        {"last", strike.last_frame},
                        {"confidence", strike.confidence}});
    }
    return list;
}

} // namespace

int run_suggest(int argc, char** argv) {
    Arguments arguments;
    if (std::optional<int> status = parse_command_line(suggest_spec(), argc, argv, arguments)) return *status;
    Result<CaptureOptions> options = capture_options_from(arguments);
    if (!options) return usage_error(suggest_spec(), options.error().message);
    std::optional<BodyPart> segment;
    if (const std::optional<std::string> name = arguments.value("segment")) {
        segment = body_part_from_name(*name);
        if (!segment) return usage_error(suggest_spec(), "unknown body part '" + *name + "' (e.g. hand_l, foot_r, head)");
    }

    nlohmann::json files = nlohmann::json::array();
    RawAnnotations annotations;
    for (const std::string& path : arguments.positionals) {
        Result<BvhFile> file = load_capture(path, *options);
        if (!file) return input_error(file.error().message);
        Result<RestAnatomy> anatomy = rest_anatomy_build(file->clip, file->body_map);
        if (!anatomy) return input_error(path + ": " + anatomy.error().message);
        const std::vector<StrikeSuggestion> strikes = strikes_detect(file->clip, *anatomy, segment);
        files.push_back({{"file", path}, {"strikes", strikes_json(strikes)}});
        const std::string source = source_relative_to_root(resolve_capture_path(path, options->mocap_root), options->mocap_root);
        for (const StrikeSuggestion& strike : strikes) annotations.clips.push_back(clip_from_suggestion(strike, source));
    }
    if (const std::optional<std::string> output = arguments.value("write-annotations")) {
        if (Result<void> valid = annotations.validate(*output); !valid) return input_error(valid.error().message);
        if (Result<void> written = annotations_write_file(*output, annotations); !written) return input_error(written.error().message);
    }

    if (arguments.has("json")) {
        print_json(files.size() == 1 ? nlohmann::json{{"strikes", files[0]["strikes"]}} : nlohmann::json{{"files", files}});
        return k_exit_ok;
    }
    for (const auto& file : files) {
        std::cout << file["file"].get<std::string>() << ": " << file["strikes"].size() << " strikes\n";
        for (const auto& strike : file["strikes"]) {
            std::cout << "  " << std::left << std::setw(6) << strike["semantics"].get<std::string>() << std::setw(8)
                      << strike["segment"].get<std::string>() << " hit " << std::setw(5) << strike["hit_frame"].get<int>()
                      << " frames " << strike["first"].get<int>() << "-" << strike["last"].get<int>() << "  confidence "
                      << std::fixed << std::setprecision(2) << strike["confidence"].get<double>() << "\n";
        }
    }
    return k_exit_ok;
}

} // namespace kumite::cli
