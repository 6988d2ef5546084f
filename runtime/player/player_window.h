#pragma once
// The player's window (Qt6): the bout stepped at its rate on the wall clock, drawn in a SceneView with a HUD
// (state, character, fps, frame time, last strike's contact error, hits and misses) and the keys listed on
// screen. Camera: orbit (mouse), or head-coupled for the wall screen (Kooima's off-axis projection from the
// tracked head), mono or stereo side by side.

#include "viewer_settings.h"

#include "kumite/runtime/bout.h"

#include <functional>
#include <string>

namespace kumite::view {

struct PlayerRunOptions {
    double duration_s = 30.0;
    bool stop_after_duration = false; // otherwise runs until closed or `quit`
    std::string screenshot_path;       // when set: after duration_s, save the window as PNG and close
};

// What the window saw, for the report.
struct PlayerRunOutcome {
    std::string renderer;       // "OpenGL 4.5 (llvmpipe ...)" or the QPainter fallback
    int body_mesh_uploads = 0;  // skinned meshes uploaded to the GPU (one per character with a body drawn)
};

// Opens the window and runs until it closes (needs a display). `after_step` is called after every bout step
// (event logging). Returns 0, or 1 when the screenshot could not be written.
int run_player_window(Bout& bout, const ViewerSettings& settings, const PlayerRunOptions& options,
                      const std::function<void()>& after_step, PlayerRunOutcome* outcome = nullptr);

} // namespace kumite::view
