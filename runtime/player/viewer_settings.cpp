#include "viewer_settings.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <tuple>

namespace kumite::view {
namespace {

Result<Eigen::Vector3f> read_point(const nlohmann::json& value, const std::string& where) {
    if (!value.is_array() || value.size() != 3) return make_error(ErrorCode::invalid, where + ": expected [x, y, z] in metres");
    Eigen::Vector3f point;
    for (int i = 0; i < 3; ++i) {
        if (!value[i].is_number() || !std::isfinite(value[i].get<double>())) return make_error(ErrorCode::invalid, where + ": expected finite numbers");
        point[i] = value[i].get<float>();
    }
    return point;
}

} // namespace

Result<void> screen_corners_validate(const ScreenCorners& s) {
    const Eigen::Vector3f right = s.lower_right - s.lower_left, up = s.upper_left - s.lower_left;
    if (!right.allFinite() || !up.allFinite()) return make_error(ErrorCode::invalid, "screen corners must be finite");
    if (right.norm() < 0.01f || up.norm() < 0.01f) return make_error(ErrorCode::invalid, "screen corners are less than 1 cm apart");
    if (std::abs(right.normalized().dot(up.normalized())) > std::sin(5.0f * float(M_PI) / 180.0f)) {
        return make_error(ErrorCode::invalid, "screen edges lower_left->lower_right and lower_left->upper_left are not at right angles");
    }
    return {};
}

Result<ViewerSettings> viewer_settings_parse(std::string_view text, std::string_view source_name) {
    const std::string source(source_name);
    nlohmann::json json;
    try {
        json = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& error) {
        return make_error(ErrorCode::parse, source + ": not JSON (byte " + std::to_string(error.byte) + ")");
    }
    if (!json.is_object()) return make_error(ErrorCode::invalid, source + ": expected a JSON object");
    ViewerSettings settings;
    auto text_of = [&](const char* key, std::string& out) -> Result<void> {
        if (!json.contains(key)) return {};
        if (!json[key].is_string()) return make_error(ErrorCode::invalid, source + ": \"" + key + "\" must be a string");
        out = json[key].get<std::string>();
        return {};
    };
    std::string camera = "orbit", stereo = "mono";
    if (Result<void> ok = text_of("camera", camera); !ok) return ok.error();
    if (Result<void> ok = text_of("stereo", stereo); !ok) return ok.error();
    if (camera == "orbit") settings.camera = Projection::orbit;
    else if (camera == "head_coupled") settings.camera = Projection::head_coupled;
    else return make_error(ErrorCode::invalid, source + ": \"camera\" is orbit or head_coupled, not '" + camera + "'");
    if (stereo == "mono") settings.stereo = StereoMode::mono;
    else if (stereo == "side_by_side") settings.stereo = StereoMode::side_by_side;
    else if (stereo == "quad_buffer") settings.stereo = StereoMode::quad_buffer;
    else return make_error(ErrorCode::invalid, source + ": \"stereo\" is mono, side_by_side or quad_buffer, not '" + stereo + "'");
    if (json.contains("eye_separation_m")) {
        const nlohmann::json& value = json["eye_separation_m"];
        if (!value.is_number() || !(value.get<double>() >= 0.0 && value.get<double>() <= 0.2)) {
            return make_error(ErrorCode::invalid, source + ": \"eye_separation_m\" must be 0 to 0.2 m");
        }
        settings.coupling.eye_separation_m = value.get<float>();
    }
    if (json.contains("screen")) {
        const nlohmann::json& screen = json["screen"];
        if (!screen.is_object()) return make_error(ErrorCode::invalid, source + ": \"screen\" must be an object of three corners");
        const std::pair<const char*, Eigen::Vector3f*> corners[] = {{"lower_left", &settings.coupling.screen.lower_left},
                                                                    {"lower_right", &settings.coupling.screen.lower_right},
                                                                    {"upper_left", &settings.coupling.screen.upper_left}};
        for (const auto& [key, out] : corners) {
            if (!screen.contains(key)) return make_error(ErrorCode::invalid, source + ": screen." + key + " is missing");
            Result<Eigen::Vector3f> point = read_point(screen[key], source + ": screen." + key);
            if (!point) return point.error();
            *out = *point;
        }
        if (Result<void> valid = screen_corners_validate(settings.coupling.screen); !valid) {
            return make_error(ErrorCode::invalid, source + ": " + valid.error().message);
        }
        settings.coupling.right_world = (settings.coupling.screen.lower_right - settings.coupling.screen.lower_left).normalized();
    }
    if (json.contains("window")) {
        const nlohmann::json& window = json["window"];
        if (!window.is_array() || window.size() != 2 || !window[0].is_number_integer() || !window[1].is_number_integer() ||
            window[0].get<int>() < 160 || window[1].get<int>() < 120 || window[0].get<int>() > 16384 || window[1].get<int>() > 16384) {
            return make_error(ErrorCode::invalid, source + ": \"window\" must be [width, height] in pixels, 160x120 to 16384x16384");
        }
        settings.width = window[0].get<int>();
        settings.height = window[1].get<int>();
    }
    for (auto [key, flag] : {std::pair<const char*, bool*>{"bodies", &settings.bodies}, {"skeleton_overlay", &settings.skeleton_overlay}}) {
        if (!json.contains(key)) continue;
        if (!json[key].is_boolean()) return make_error(ErrorCode::invalid, source + ": \"" + key + "\" must be true or false");
        *flag = json[key].get<bool>();
    }
    if (json.contains("orbit")) {
        // {"yaw_deg": 30, "pitch_deg": 10, "distance_m": 3, "target": [0, 1.2, 0.6]}, every key optional.
        const nlohmann::json& orbit = json["orbit"];
        if (!orbit.is_object()) return make_error(ErrorCode::invalid, source + ": \"orbit\" must be an object (yaw_deg, pitch_deg, distance_m, target)");
        const std::tuple<const char*, float*, double, double> numbers[] = {{"yaw_deg", &settings.orbit_yaw_deg, -360.0, 360.0},
                                                                           {"pitch_deg", &settings.orbit_pitch_deg, -89.0, 89.0},
                                                                           {"distance_m", &settings.orbit_distance_m, 0.1, 100.0}};
        for (const auto& [key, out, lowest, highest] : numbers) {
            if (!orbit.contains(key)) continue;
            const nlohmann::json& value = orbit[key];
            if (!value.is_number() || !(value.get<double>() >= lowest && value.get<double>() <= highest)) {
                return make_error(ErrorCode::invalid, source + ": orbit." + key + " must be a number from " + std::to_string(int(lowest)) + " to " +
                                                           std::to_string(int(highest)));
            }
            *out = value.get<float>();
        }
        if (orbit.contains("target")) {
            Result<Eigen::Vector3f> target = read_point(orbit["target"], source + ": orbit.target");
            if (!target) return target.error();
            settings.orbit_target = *target;
        }
    }
    if (json.contains("fullscreen")) {
        if (!json["fullscreen"].is_boolean()) return make_error(ErrorCode::invalid, source + ": \"fullscreen\" must be true or false");
        settings.fullscreen = json["fullscreen"].get<bool>();
    }
    return settings;
}

Result<ViewerSettings> viewer_settings_read(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return make_error(ErrorCode::io, path.string() + ": cannot read the viewer settings");
    std::ostringstream text;
    text << in.rdbuf();
    if (text.str().size() > (1u << 20)) return make_error(ErrorCode::limit, path.string() + ": larger than 1 MB, not viewer settings");
    return viewer_settings_parse(text.str(), path.string());
}

} // namespace kumite::view
