#pragma once
// The player's window (Qt6): the bout stepped at its rate on the wall clock, drawn in a SceneView with a HUD
// (state, character, fps, frame time, last strike's contact error, hits and misses) and the keys listed on
// screen. Camera: orbit (mouse), or head-coupled for the wall screen (Kooima's off-axis projection from the
// tracked head), mono or stereo side by side.

#include "viewer_settings.h"

#include "kumite/runtime/bout.h"

#include <functional>
#include <memory>
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

// The same window beside a headset (`kumite play --xr`): the orbit view, the HUD and the keys, while the headset's
// frame loop steps the bout. Needs a QApplication. The loop calls after_step() after each bout step and
// show_frame() once a frame (the scene shown, Qt's events handled: keys become orders, Space pauses, Esc closes);
// the loop leaves the bout's time still while paused() and ends the bout once closed(). Whatever OpenGL context was
// current before show_frame() may not be after it.
class SupervisorWindow {
public:
    SupervisorWindow(Bout& bout, const ViewerSettings& settings);
    ~SupervisorWindow();
    void after_step();
    void show_frame();
    bool paused() const;
    bool closed() const;
    bool save(const std::string& path); // the window as PNG; false when it cannot be written
    std::string renderer() const;

private:
    struct Window;
    std::unique_ptr<Window> m_window;
};

} // namespace kumite::view
