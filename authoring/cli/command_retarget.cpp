// kumite retarget: a capture encoded in the morphology-independent representation and decoded onto a character.

#include "capture_loading.h"
#include "character_catalog.h"
#include "commands.h"
#include "kumite/core/retarget_clip.h"
#include "kumite/formats/atomic_file.h"

#include <iostream>

namespace kumite::cli {

const CommandSpec& retarget_spec() {
    static const CommandSpec spec{
        "retarget",
        "IN.bvh --character NAME|FILE.glb -o OUT.bvh|OUT.glb [--report OUT.json]",
        "Encodes a capture in the morphology-independent representation and decodes it onto a character of\n"
        "data/characters: bone lengths are the character's, limbs keep their extension, planted feet stay planted.\n"
        "The output BVH has the character's hierarchy, channels and unit; the report measures the result.",
        1, 1,
        {{"character", "NAME", "target character (see kumite characters)"},
         {"output", "OUT.bvh|OUT.glb", "where to write the retargeted capture (also -o); .glb: with the character's body"},
         {"report", "OUT.json", "write the quality report as JSON"},
         unit_flag(), strict_flag(), fps_flag(), mocap_root_flag(), body_map_flag(), characters_dir_flag(), json_flag()}};
    return spec;
}

namespace {

nlohmann::json report_json(const RetargetReport& report, const std::string& character, const std::filesystem::path& output) {
    return {{"character", character},
            {"output", output.string()},
            {"frames", report.frames},
            {"contacts", report.contacts},
            {"bone_length_error_m", report.bone_length_error_m},
            {"foot_drift_m", report.foot_drift_m},
            {"floor_penetration_m", report.floor_penetration_m},
            {"limb_extension_error", report.limb_extension_error},
            {"encode_decode_us", {{"median", report.encode_decode_us_median}, {"p99", report.encode_decode_us_p99}}},
            {"foot_lock_us", {{"median", report.foot_lock_us_median}, {"p99", report.foot_lock_us_p99}}}};
}

} // namespace

int run_retarget(int argc, char** argv) {
    Arguments arguments;
    if (std::optional<int> status = parse_command_line(retarget_spec(), argc, argv, arguments)) return *status;
    const std::optional<std::string> character_name = arguments.value("character");
    const std::optional<std::string> output = arguments.value("output");
    if (!character_name) return usage_error(retarget_spec(), "--character NAME is required");
    if (!output) return usage_error(retarget_spec(), "-o OUT.bvh (or OUT.glb) is required");
    if (std::optional<std::string> problem = recording_path_problem(*output)) return usage_error(retarget_spec(), "-o " + *problem);
    Result<CaptureOptions> options = capture_options_from(arguments);
    if (!options) return usage_error(retarget_spec(), options.error().message);

    Result<BvhFile> source = load_capture(arguments.positionals[0], *options);
    if (!source) return input_error(source.error().message);
    if (Result<void> timed = require_frame_rate(*source, arguments.positionals[0], "retarget (foot contacts)"); !timed) {
        return input_error(timed.error().message);
    }
    const std::filesystem::path characters = arguments.value("characters-dir").value_or(default_characters_dir().string());
    Result<BvhFile> character = load_character(characters, *character_name);
    if (!character) return usage_error(retarget_spec(), character.error().message);

    Result<RestAnatomy> source_anatomy = rest_anatomy_build(source->clip, source->body_map);
    if (!source_anatomy) return input_error(arguments.positionals[0] + ": " + source_anatomy.error().message);
    Result<RestAnatomy> target_anatomy = rest_anatomy_build(character->clip, character->body_map);
    if (!target_anatomy) return input_error("character " + *character_name + ": " + target_anatomy.error().message);

    RetargetReport report;
    const Clip retargeted = retarget_clip(report, source->clip, *source_anatomy, character->clip.skeleton, *target_anatomy);
    if (Result<void> written = write_recording(*output, retargeted, *character, characters, *character_name); !written) {
        return input_error(written.error().message);
    }
    const nlohmann::json document = report_json(report, *character_name, *output);
    if (const std::optional<std::string> report_path = arguments.value("report")) {
        if (Result<void> written = write_file_atomically(*report_path, document.dump(2) + "\n"); !written) {
            return input_error(written.error().message);
        }
    }
    if (arguments.has("json")) {
        print_json(document);
    } else {
        std::cout << "wrote " << *output << ": " << report.frames << " frames on " << *character_name
                  << "; bone length error " << report.bone_length_error_m << " m, foot drift " << report.foot_drift_m
                  << " m, floor penetration " << report.floor_penetration_m << " m, limb extension error "
                  << report.limb_extension_error << ", encode + decode " << report.encode_decode_us_median
                  << " us/frame (+ " << report.foot_lock_us_median << " us foot lock)\n";
    }
    return k_exit_ok;
}

} // namespace kumite::cli
