#pragma once
// `kumite play --xr`: the bout in the headset. Each runtime frame: xrWaitFrame, the headset's head (its view pose
// moved to the head's centre, xr_view_math.h) and grips (the hands) fed to the bout's tracker, the bout stepped at
// its own rate up to the frame's predicted display time, both eyes drawn (the fighters, the floor, the user's
// hands), xrEndFrame. Session states are reported as they come; the bout ends when its duration is reached, on
// the user's quit button, a supervisor's quit, or when the runtime stops or is lost (the caller still writes its
// report). Needs a bout made with a fed tracker (HeadTracker::fed).

#include "viewer_settings.h"

#include "kumite/runtime/bout.h"
#include "kumite/runtime/value_histogram.h"

#include <functional>
#include <string>
#include <vector>

namespace kumite::view {

struct XrPlayOptions {
    double duration_s = 30.0;
    std::string eye_image_path; // non-empty: the left eye of the last frame drawn, as PNG (and its geometry in the outcome)
    std::array<int, 2> view_size{}; // per eye, pixels; 0: the runtime's recommended size (benchmarks ask for a headset's)
    // The supervisor's desktop window beside the headset (player_window.h), when set; its PNG at the end when a
    // path is given.
    const ViewerSettings* supervisor = nullptr;
    std::string supervisor_screenshot_path;
};

struct XrEyeImage {
    std::string path;
    double t_s = 0.0;
    int width = 0, height = 0;
    std::array<float, 7> eye_pose{};   // qx qy qz qw x y z (world)
    std::array<float, 4> fov_rad{};    // left right up down
    std::array<double, 3> fighter_head{}, fighter_chest{}, fighter_pelvis{}; // world, that frame
};

struct XrPlayOutcome {
    std::string runtime, system, ended_by;
    bool stage_space = true;
    int view_width = 0, view_height = 0, swapchain_width = 0, swapchain_height = 0;
    long long frames_waited = 0, frames_submitted = 0, frames_rendered = 0, errors = 0;
    long long head_lost_frames = 0, hand_lost_frames = 0, button_orders = 0;
    std::vector<std::string> states, error_messages;
    // From xrWaitFrame's return to xrEndFrame's, the eyes' drawing within it, the wait itself; the first frame
    // (shaders compiled, meshes uploaded) apart. Within the frame work besides the drawing: the bout's steps, the
    // scene built for the eyes, xrEndFrame (where the runtime takes the layers and the drawing is finished).
    ValueHistogram frame_work_us{1.0, 1e7}, render_us{1.0, 1e7}, wait_us{1.0, 1e7};
    ValueHistogram steps_us{0.1, 1e7}, scene_us{0.1, 1e7}, end_frame_us{1.0, 1e7};
    double first_frame_work_us = 0.0;
    XrEyeImage eye_image;
    bool supervisor_window = false;  // opened beside the headset
    std::string supervisor_renderer; // what drew it
    double paused_s = 0.0;           // bout time held still by the supervisor (Space)
    bool supervisor_screenshot_failed = false;
    // Mesa's software rasteriser's worker threads (LP_NUM_THREADS) as the run had them: "0" set by kumite when the
    // process may use one core only, the user's own value, or "" (Mesa's default: one per core).
    std::string software_raster_threads;
    int cores_allowed = 0;
};

// Runs the session. Returns 0, or 1 when no session could be started (the message already on stderr).
// `after_step` runs after each bout step; `on_state` gets each session state as it comes (bout time, name).
int run_xr_bout(Bout& bout, const XrPlayOptions& options, const std::function<void()>& after_step,
                const std::function<void(double, const char*)>& on_state, XrPlayOutcome& outcome);

} // namespace kumite::view
