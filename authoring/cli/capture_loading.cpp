#include "capture_loading.h"

#include "warning_groups.h"

#include "kumite/formats/capture_file.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <unistd.h>

namespace kumite::cli {

Result<CaptureOptions> capture_options_from(const Arguments& arguments) {
    CaptureOptions options;
    if (const std::optional<std::string> unit = arguments.value("unit"); unit && *unit != "auto") {
        Result<LengthUnit> parsed = length_unit_from_name(*unit);
        if (!parsed) return parsed.error();
        options.read.unit = *parsed;
    }
    const std::optional<std::string> root = arguments.value("mocap-root");
    options.mocap_root = root ? std::filesystem::path(*root) : default_mocap_root();
    if (const std::optional<std::string> body_map = arguments.value("body-map")) options.body_map_file = *body_map;
    options.read.strict = arguments.has("strict");
    if (const std::optional<std::string> fps = arguments.value("fps")) {
        Result<double> rate = frame_rate_from_text(*fps);
        if (!rate) return rate.error();
        options.read.frame_rate_hz = *rate;
    }
    return options;
}

Result<double> frame_rate_from_text(const std::string& text) {
    char* end = nullptr;
    const double rate = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(rate) || rate < 0.001 || rate > 100000.0) {
        return make_error(ErrorCode::invalid, "--fps: expected a frame rate from 0.001 to 100000 (frames per second), found '" + text + "'");
    }
    return rate;
}

Result<void> require_frame_rate(const BvhFile& file, const std::filesystem::path& path, std::string_view what_needs_it) {
    if (file.clip.has_frame_rate()) return {};
    return make_error(ErrorCode::invalid, path.string() + ": the capture does not say its frame rate (its 'Frame Time' is 0 or missing), and " +
                                              std::string(what_needs_it) + " needs it: give it with --fps N (e.g. --fps 100)");
}

Result<TimedCapture> load_timed_capture(const std::filesystem::path& path, const CaptureOptions& options, std::string_view what_needs_it) {
    Result<BvhFile> file = load_capture(path, options);
    if (!file) return file.error();
    if (Result<void> timed = require_frame_rate(*file, path, what_needs_it); !timed) return timed.error();
    Result<RestAnatomy> anatomy = rest_anatomy_build(file->clip, file->body_map);
    if (!anatomy) return make_error(anatomy.error().code, path.string() + ": " + anatomy.error().message);
    return TimedCapture{std::move(*file), std::move(*anatomy)};
}

std::filesystem::path resolve_capture_path(const std::filesystem::path& path, const std::filesystem::path& mocap_root) {
    std::error_code error;
    if (std::filesystem::exists(path, error) || path.is_absolute()) return path;
    const std::filesystem::path under_root = mocap_root / path;
    if (std::filesystem::exists(under_root, error)) return under_root;
    return path;
}

Result<BvhFile> load_capture(const std::filesystem::path& given_path, const CaptureOptions& options) {
    const std::filesystem::path path = resolve_capture_path(given_path, options.mocap_root);
    Result<BvhFile> file = capture_read_file(path, options.read, options.body_map_file);
    if (file) {
        for (const std::string& warning : file->warnings) {
            if (options.warnings) options.warnings->add_from_reader(path.string(), warning);
            else std::cerr << "warning: " << warning << "\n";
        }
    }
    return file;
}

std::filesystem::path default_mocap_root() { return locate_data_folder("KUMITE_MOCAP_ROOT", "data/mocap"); }

nlohmann::json json_vec3(const Eigen::Vector3d& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

void print_json(const nlohmann::json& document) {
    std::cout << document.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
}

} // namespace kumite::cli
