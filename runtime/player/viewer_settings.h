#pragma once
// The viewer's settings file (JSON, every key optional; documented in runtime/player/README.md):
//   {"camera": "orbit" | "head_coupled", "stereo": "mono" | "side_by_side" | "quad_buffer",
//    "eye_separation_m": 0.064, "screen": {"lower_left": [x,y,z], "lower_right": [x,y,z], "upper_left": [x,y,z]},
//    "window": [width, height], "fullscreen": false, "bodies": true, "skeleton_overlay": false}
// The screen corners are measured in world metres (the room after the tracker's room-to-world transform).

#include "scene_view.h"

#include "kumite/core/result.h"

#include <filesystem>

namespace kumite::view {

struct ViewerSettings {
    Projection camera = Projection::orbit;
    StereoMode stereo = StereoMode::mono;
    HeadCoupling coupling;
    int width = 1280, height = 720;
    bool fullscreen = false;
    bool bodies = true;            // skinned bodies where characters have them (false: capsules only)
    bool skeleton_overlay = false; // the bones drawn over the bodies (the B key)
    // Where the orbit camera starts (the mouse moves it on): around the point it looks at, from the side by default.
    float orbit_yaw_deg = 68.75f;    // about +Y; 0 looks along -Z, from in front of the fighter's start
    float orbit_pitch_deg = 14.32f;  // positive looks down
    float orbit_distance_m = 4.5f;
    Eigen::Vector3f orbit_target{0.0f, 1.0f, 0.75f};
};

Result<ViewerSettings> viewer_settings_parse(std::string_view text, std::string_view source_name);
Result<ViewerSettings> viewer_settings_read(const std::filesystem::path& path);

// Checks that three corners make a screen: finite, edges longer than 1 cm and at right angles within 5 degrees.
Result<void> screen_corners_validate(const ScreenCorners& screen);

} // namespace kumite::view
