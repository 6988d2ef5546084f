// kumite inspect: what a capture holds: joints, frames, rate, unit, height, rotation orders, body map.

#include "capture_loading.h"
#include "commands.h"

#include <iomanip>
#include <iostream>
#include <set>

namespace kumite::cli {
namespace {

nlohmann::json inspect_json(const BvhFile& file, const std::filesystem::path& path) {
    const Clip& clip = file.clip;
    nlohmann::json document;
    document["file"] = path.string();
    document["joints"] = clip.skeleton.joint_count();
    document["joint_names"] = clip.skeleton.names;
    document["end_sites"] = clip.skeleton.end_sites.size();
    document["channels"] = file.layout.channel_count();
    document["frames"] = clip.frame_count();
    // No rate (a file that says 'Frame Time: 0', read without --fps): null, with the reason in "warnings".
    document["frame_time_s"] = clip.has_frame_rate() ? nlohmann::json(clip.frame_time_s) : nlohmann::json();
    document["fps"] = clip.has_frame_rate() ? nlohmann::json(1.0 / clip.frame_time_s) : nlohmann::json();
    document["fps_source"] = file.frame_rate_in_file ? "file" : clip.has_frame_rate() ? "--fps" : "none";
    document["duration_s"] = clip.has_frame_rate() ? nlohmann::json(clip.duration_s()) : nlohmann::json();
    document["unit"] = file.unit.name;
    document["unit_scale_m"] = file.unit.metres;
    document["unit_detected"] = file.unit_detected;
    document["height_m"] = file.height_m;

    std::set<std::string> orders;
    for (const BvhJointChannels& joint : file.layout.joints) {
        if (joint.has_rotation()) orders.insert(joint.rotation_order.name());
    }
    document["rotation_orders"] = orders;

    nlohmann::json body_map = nlohmann::json::object(), sources = nlohmann::json::object();
    for (int part = 0; part < k_body_part_count; ++part) {
        const int joint = file.body_map.joints[part];
        if (joint < 0) continue;
        const std::string name(body_part_name(static_cast<BodyPart>(part)));
        body_map[name] = clip.skeleton.names[joint];
        sources[name] = std::string(body_map_source_name(file.body_map.sources[std::size_t(part)]));
    }
    document["body_map"] = body_map;
    // How each part was found: by name (a known naming scheme), by the skeleton's structure, or from a file.
    document["body_map_sources"] = sources;
    if (std::any_of(file.body_map.sources.begin(), file.body_map.sources.end(), [](BodyMapSource s) { return s == BodyMapSource::structure; })) {
        document["body_map_structure_confidence"] = file.body_map.structure_confidence;
    }
    nlohmann::json unmapped = nlohmann::json::array();
    for (int joint = 0; joint < clip.skeleton.joint_count(); ++joint) {
        if (!file.body_map.part_of(joint)) unmapped.push_back(clip.skeleton.names[joint]);
    }
    document["unmapped"] = unmapped;
    document["warnings"] = file.warnings;
    return document;
}

void print_inspect_text(const nlohmann::json& document) {
    std::cout << document["file"].get<std::string>() << "\n"
              << "  joints       " << document["joints"] << " (" << document["channels"] << " channels, "
              << document["end_sites"] << " End Sites)\n"
              << "  frames       " << document["frames"];
    if (document["fps"].is_null()) std::cout << " (no frame rate: give it with --fps N)\n";
    else std::cout << " at " << std::setprecision(6) << document["fps"].get<double>() << " fps, " << document["duration_s"].get<double>() << " s\n";
    std::cout
              << "  unit         " << document["unit"].get<std::string>() << " (" << document["unit_scale_m"].get<double>()
              << " m, " << (document["unit_detected"].get<bool>() ? "detected" : "given") << ")\n"
              << "  height       " << std::setprecision(4) << document["height_m"].get<double>() << " m\n"
              << "  rotations    ";
    for (const auto& order : document["rotation_orders"]) std::cout << order.get<std::string>() << " ";
    std::cout << "\n  body map     " << document["body_map"].size() << " of " << k_body_part_count << " parts\n";
    for (const auto& [part, joint] : document["body_map"].items()) {
        const std::string source = document["body_map_sources"].value(part, std::string("name"));
        std::cout << "    " << std::left << std::setw(12) << part << joint.get<std::string>() << (source == "name" ? "" : "  (by " + source + ")") << "\n";
    }
    if (document.contains("body_map_structure_confidence")) {
        std::cout << "  structure    confidence " << std::setprecision(2) << document["body_map_structure_confidence"].get<double>()
                  << " (how alike the left and right limbs are)\n";
    }
    std::cout << "  unmapped     " << document["unmapped"].size() << " joints\n";
}

} // namespace

const CommandSpec& inspect_spec() {
    static const CommandSpec spec{
        "inspect",
        "FILE.bvh [--unit auto|m|cm|mm|in|cmu] [--json]",
        "Reads a BVH capture and describes it: joints, frames, frame rate, length unit, standing height,\n"
        "rotation orders and the body map (which joint plays each body part).",
        1, 1,
        {unit_flag(), strict_flag(), fps_flag(), mocap_root_flag(), body_map_flag(), json_flag()}};
    return spec;
}

int run_inspect(int argc, char** argv) {
    Arguments arguments;
    if (std::optional<int> status = parse_command_line(inspect_spec(), argc, argv, arguments)) return *status;
    Result<CaptureOptions> options = capture_options_from(arguments);
    if (!options) return usage_error(inspect_spec(), options.error().message);
    const std::filesystem::path path = resolve_capture_path(arguments.positionals[0], options->mocap_root);
    Result<BvhFile> file = load_capture(path, *options);
    if (!file) return input_error(file.error().message);

    const nlohmann::json document = inspect_json(*file, path);
    if (arguments.has("json")) print_json(document);
    else print_inspect_text(document);
    return k_exit_ok;
}

} // namespace kumite::cli
