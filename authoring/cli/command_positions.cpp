// kumite positions: world positions of every joint after forward kinematics, in metres, in the file's axes.

#include "capture_loading.h"
#include "commands.h"
#include "kumite/core/forward_kinematics.h"

#include <charconv>
#include <iostream>

namespace kumite::cli {
namespace {

// "0,10,25" or ranges "10-20"; every index must be inside the clip.
Result<std::vector<int>> parse_frame_list(const std::string& text, int frame_count) {
    std::vector<int> frames;
    size_t start = 0;
    while (start <= text.size()) {
        const size_t comma = std::min(text.find(',', start), text.size());
        const std::string item = text.substr(start, comma - start);
        int first = 0, last = 0;
        const size_t dash = item.find('-', 1);
        const std::string first_text = item.substr(0, dash);
        const std::string last_text = dash == std::string::npos ? first_text : item.substr(dash + 1);
        const auto a = std::from_chars(first_text.data(), first_text.data() + first_text.size(), first);
        const auto b = std::from_chars(last_text.data(), last_text.data() + last_text.size(), last);
        if (item.empty() || a.ec != std::errc() || a.ptr != first_text.data() + first_text.size() || b.ec != std::errc() ||
            b.ptr != last_text.data() + last_text.size() || first < 0 || last < first) {
            return make_error(ErrorCode::invalid, "--frames expects indices like 0,10,25 or 10-20, got '" + item + "'");
        }
        if (last >= frame_count) {
            return make_error(ErrorCode::invalid, "frame " + std::to_string(last) + " is out of range: the file has " +
                                                      std::to_string(frame_count) + " frames (0-" +
                                                      std::to_string(frame_count - 1) + ")");
        }
        if (static_cast<long>(last) - first + static_cast<long>(frames.size()) > 10000000) {
            return make_error(ErrorCode::invalid, "--frames lists too many frames");
        }
        for (int frame = first; frame <= last; ++frame) frames.push_back(frame);
        start = comma + 1;
    }
    return frames;
}

} // namespace

const CommandSpec& positions_spec() {
    static const CommandSpec spec{
        "positions",
        "FILE.bvh [--frames 0,10,25 | --all] [--unit ...] [--json]",
        "World positions of every joint (End Sites excluded) after forward kinematics, in metres, in the\n"
        "file's own axes (Y up). Without --frames or --all, frame 0.",
        1, 1,
        {{"frames", "LIST", "frame indices, e.g. 0,10,25 or 10-20"},
         {"all", "", "every frame"},
         unit_flag(), strict_flag(), fps_flag(), mocap_root_flag(), json_flag()}};
    return spec;
}

int run_positions(int argc, char** argv) {
    Arguments arguments;
    if (std::optional<int> status = parse_command_line(positions_spec(), argc, argv, arguments)) return *status;
    if (arguments.has("frames") && arguments.has("all")) return usage_error(positions_spec(), "--frames and --all exclude each other");
    Result<CaptureOptions> options = capture_options_from(arguments);
    if (!options) return usage_error(positions_spec(), options.error().message);
    Result<BvhFile> file = load_capture(arguments.positionals[0], *options);
    if (!file) return input_error(file.error().message);
    const Clip& clip = file->clip;

    std::vector<int> frames;
    if (arguments.has("all")) {
        for (int frame = 0; frame < clip.frame_count(); ++frame) frames.push_back(frame);
    } else if (const std::optional<std::string> list = arguments.value("frames")) {
        Result<std::vector<int>> parsed = parse_frame_list(*list, clip.frame_count());
        if (!parsed) return usage_error(positions_spec(), parsed.error().message);
        frames = *parsed;
    } else if (clip.frame_count() > 0) {
        frames.push_back(0);
    }

    const int joints = clip.skeleton.joint_count();
    std::vector<Eigen::Vector3d> model_positions(joints);
    std::vector<Eigen::Quaterniond> model_rotations(joints);
    nlohmann::json frames_json = nlohmann::json::object();
    for (int frame : frames) {
        forward_kinematics(model_positions, model_rotations, clip.skeleton, clip.pose(frame));
        nlohmann::json positions = nlohmann::json::array();
        for (const Eigen::Vector3d& position : model_positions) positions.push_back(json_vec3(position));
        frames_json[std::to_string(frame)] = std::move(positions);
    }

    if (arguments.has("json")) {
        print_json({{"joint_names", clip.skeleton.names}, {"frames", frames_json}});
        return k_exit_ok;
    }
    for (int frame : frames) {
        std::cout << "frame " << frame << "\n";
        const nlohmann::json& positions = frames_json[std::to_string(frame)];
        for (int joint = 0; joint < joints; ++joint) {
            std::cout << "  " << clip.skeleton.names[joint] << " " << positions[joint][0].get<double>() << " "
                      << positions[joint][1].get<double>() << " " << positions[joint][2].get<double>() << "\n";
        }
    }
    return k_exit_ok;
}

} // namespace kumite::cli
