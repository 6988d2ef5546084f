#include "play_xr.h"

#ifdef KUMITE_HAVE_OPENXR
#include "xr_play.h"
#include "xr_view_math.h"
#endif

#include <cstdio>
#include <iostream>

namespace kumite::cli {

#ifdef KUMITE_HAVE_OPENXR
namespace {

nlohmann::json times_json(const ValueHistogram& h) {
    return {{"median", h.quantile(0.5)}, {"p99", h.quantile(0.99)}, {"max", h.max()}, {"mean", h.mean()}, {"count", h.count()}};
}

} // namespace

int play_xr(Bout& bout, const Arguments& arguments, double duration_s, const std::function<void()>& after_step,
            const std::function<void(nlohmann::json)>& write_event, const view::ViewerSettings* supervisor, nlohmann::json& xr_report) {
    view::XrPlayOptions options;
    options.duration_s = duration_s;
    options.supervisor = supervisor;
    options.supervisor_screenshot_path = arguments.value("screenshot").value_or("");
    options.eye_image_path = arguments.value("xr-eye-image").value_or("");
    if (const std::optional<std::string> size = arguments.value("xr-view-size")) {
        int width = 0, height = 0;
        char x = 0, rest = 0;
        if (std::sscanf(size->c_str(), "%d%c%d%c", &width, &x, &height, &rest) != 3 || x != 'x' || width < 16 || height < 16 || width > 8192 || height > 8192) {
            std::cerr << "kumite play: --xr-view-size must be WIDTHxHEIGHT in pixels (16 to 8192), not '" << *size << "'\n";
            return 2;
        }
        options.view_size = {width, height};
    }
    view::XrPlayOutcome outcome;
    auto on_state = [&](double t_s, const char* state) { write_event({{"t", t_s}, {"type", "xr_session"}, {"state", state}}); };
    if (const int status = view::run_xr_bout(bout, options, after_step, on_state, outcome); status != 0) return status;
    xr_report = {{"runtime", outcome.runtime},
                 {"system", outcome.system},
                 {"graphics", "OpenGL (XR_KHR_opengl_enable, GLX)"},
                 {"space", outcome.stage_space ? "stage" : "local_floor_offset"},
                 {"view_size_px", {outcome.view_width, outcome.view_height}},
                 {"swapchain_size_px", {outcome.swapchain_width, outcome.swapchain_height}},
                 {"head_centre_behind_eyes_m", view::k_head_centre_behind_eyes_m},
                 {"frames_waited", outcome.frames_waited},
                 {"frames_submitted", outcome.frames_submitted},
                 {"frames_rendered", outcome.frames_rendered},
                 {"errors", outcome.errors},
                 {"error_messages", outcome.error_messages},
                 {"states", outcome.states},
                 {"ended_by", outcome.ended_by},
                 {"head_lost_frames", outcome.head_lost_frames},
                 {"hand_lost_frames", outcome.hand_lost_frames},
                 {"button_orders", outcome.button_orders},
                 {"frame_work_us", times_json(outcome.frame_work_us)},
                 {"first_frame_work_us", outcome.first_frame_work_us},
                 {"render_us", times_json(outcome.render_us)},
                 {"steps_us", times_json(outcome.steps_us)},
                 {"scene_us", times_json(outcome.scene_us)},
                 {"end_frame_us", times_json(outcome.end_frame_us)},
                 {"wait_us", times_json(outcome.wait_us)},
                 {"supervisor_window", outcome.supervisor_window},
                 {"supervisor_renderer", outcome.supervisor_renderer},
                 {"paused_s", outcome.paused_s},
                 {"cores_allowed", outcome.cores_allowed},
                 {"software_raster_threads", outcome.software_raster_threads.empty() ? nlohmann::json("mesa default") : nlohmann::json(outcome.software_raster_threads)}};
    if (!outcome.eye_image.path.empty()) {
        const view::XrEyeImage& e = outcome.eye_image;
        xr_report["eye_image"] = {{"path", e.path}, {"t", e.t_s}, {"width", e.width}, {"height", e.height}, {"eye", "left"},
                                  {"eye_pose", e.eye_pose}, {"fov_rad", e.fov_rad}, {"fighter_head", e.fighter_head},
                                  {"fighter_chest", e.fighter_chest}, {"fighter_pelvis", e.fighter_pelvis}};
    }
    if (outcome.ended_by == "runtime_lost") {
        std::cerr << "kumite play --xr: the OpenXR runtime was lost after " << outcome.frames_waited << " frames (" << bout.now_s()
                  << " s): the bout ends here, its events and report are written\n";
    }
    if (outcome.errors > 0) std::cerr << "kumite play --xr: " << outcome.errors << " OpenXR call(s) failed, first: " << outcome.error_messages.front() << "\n";
    return outcome.supervisor_screenshot_failed ? 1 : 0;
}

#else

int play_xr(Bout&, const Arguments&, double, const std::function<void()>&, const std::function<void(nlohmann::json)>&, const view::ViewerSettings*,
            nlohmann::json&) {
    std::cerr << "kumite play --xr: this kumite was built without OpenXR (install libopenxr-dev, or run scripts/setup.sh, and build again)\n";
    return 1;
}

#endif

} // namespace kumite::cli
