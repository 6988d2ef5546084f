#include "xr_play.h"

#include "player_scene.h"
#include "player_window.h"
#include "xr_eye_renderer.h"
#include "xr_headset.h"

#include <QApplication>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <thread>

#include <sched.h>

namespace kumite::view {
namespace {

using Clock = std::chrono::steady_clock;
double microseconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::micro>(b - a).count(); }

// In the headset the user sees the fighters, the floor and their own hands: not the supervisor's aids (the
// latched target, the hit path and its box) nor a sphere at their own head.
void headset_scene_build(const Bout& bout, Scene& scene) {
    player_scene_build(bout, scene);
    scene.spheres.clear(), scene.polylines.clear(), scene.boxes.clear();
    const UserHands& hands = bout.hands();
    for (std::size_t side = 0; side < 2; ++side) {
        if (!hands.present[side]) continue;
        Sphere fist;
        fist.center = hands.world[side].cast<float>();
        fist.radius_m = 0.045f;
        fist.color = side == 0 ? Color(0.95f, 0.6f, 0.35f) : Color(0.35f, 0.75f, 0.95f);
        scene.spheres.push_back(fist);
    }
}

void feed_tracker(Bout& bout, const XrTrackedUser& user, XrPlayOutcome& outcome) {
    UserHands hands;
    for (std::size_t side = 0; side < 2; ++side) {
        hands.present[side] = user.grip_tracked[side];
        if (hands.present[side]) hands.world[side] = user.grip[side].position.cast<double>();
    }
    if (!user.head_tracked) ++outcome.head_lost_frames;
    if (!user.grip_tracked[0] || !user.grip_tracked[1]) ++outcome.hand_lost_frames;
    const Eigen::Vector3d head = head_centre_from_view(user.head).cast<double>();
    bout.tracker().feed(user.head_tracked ? &head : nullptr, hands);
}

std::array<double, 3> array_of(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

struct Session {
    XrHeadset& headset;
    XrPlayOutcome& outcome;
    const std::function<void(double, const char*)>& on_state;
    XrSessionState state = XR_SESSION_STATE_UNKNOWN;
    bool running = false, exit_requested = false, done = false;
    Clock::time_point exit_requested_at{};

    void request_exit(const char* why) {
        if (exit_requested) return;
        exit_requested = true;
        exit_requested_at = Clock::now();
        if (outcome.ended_by.empty()) outcome.ended_by = why;
        if (!running || !headset.check(xrRequestExitSession(headset.session()), "xrRequestExitSession")) done = true;
    }
    // Handles the runtime's events; `t_s` the bout time for the log.
    void poll(double t_s) {
        XrSessionState changed = XR_SESSION_STATE_UNKNOWN;
        bool lost = false;
        while (!done && headset.poll_event(changed, lost)) {
            if (lost) {
                outcome.states.push_back("loss_pending");
                on_state(t_s, "loss_pending");
                if (outcome.ended_by.empty()) outcome.ended_by = "runtime_lost";
                done = true;
                return;
            }
            if (changed == XR_SESSION_STATE_UNKNOWN) continue;
            state = changed;
            outcome.states.push_back(xr_session_state_name(changed));
            on_state(t_s, xr_session_state_name(changed));
            if (changed == XR_SESSION_STATE_READY) {
                XrSessionBeginInfo begin{XR_TYPE_SESSION_BEGIN_INFO};
                begin.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
                running = headset.check(xrBeginSession(headset.session(), &begin), "xrBeginSession");
                if (!running) done = true;
            } else if (changed == XR_SESSION_STATE_STOPPING) {
                headset.check(xrEndSession(headset.session()), "xrEndSession");
                running = false;
                if (outcome.ended_by.empty()) outcome.ended_by = "runtime_stopped";
            } else if (changed == XR_SESSION_STATE_EXITING || changed == XR_SESSION_STATE_LOSS_PENDING) {
                if (outcome.ended_by.empty()) outcome.ended_by = changed == XR_SESSION_STATE_EXITING ? "runtime_exit" : "runtime_lost";
                done = true;
            }
        }
    }
};

// On one core, Mesa's software rasteriser (llvmpipe, and lavapipe in the runtime's compositor) would still start a
// worker thread per core it was built for and hand each triangle bin to them: the workers only take turns with the
// thread that waits for them, and each hand-off is a chance for the scheduler to run something else first (on the
// bench's one core, nine runs without them: frame work median 2.9-3.3 ms, p99 3.9-4.7 ms; with them, median
// 3.0-3.5 ms, p99 3.9-6.5 ms). So with one core allowed and no LP_NUM_THREADS of the user's, the drawing stays in
// the calling thread. Hardware drivers ignore the variable. Must run before the first OpenGL or Vulkan context.
void software_raster_threads_for_cores(XrPlayOutcome& outcome) {
    cpu_set_t allowed;
    CPU_ZERO(&allowed);
    outcome.cores_allowed = sched_getaffinity(0, sizeof(allowed), &allowed) == 0 ? CPU_COUNT(&allowed) : 0;
    if (const char* set = std::getenv("LP_NUM_THREADS")) {
        outcome.software_raster_threads = set;
        return;
    }
    if (outcome.cores_allowed == 1) {
        setenv("LP_NUM_THREADS", "0", 0);
        outcome.software_raster_threads = "0";
    }
}

} // namespace

int run_xr_bout(Bout& bout, const XrPlayOptions& options, const std::function<void()>& after_step,
                const std::function<void(double, const char*)>& on_state, XrPlayOutcome& outcome) {
    std::unique_ptr<QGuiApplication> application;
    static int argc = 1;
    static char name[] = "kumite";
    static char* argv[] = {name, nullptr};
    const char* display = std::getenv("DISPLAY");
    software_raster_threads_for_cores(outcome);
    Result<std::unique_ptr<XrHeadset>> opened = XrHeadset::open();
    if (!opened) {
        std::cerr << "kumite play --xr: " << opened.error().message << "\n";
        return 1;
    }
    XrHeadset& headset = **opened;
    outcome.runtime = headset.runtime_name(), outcome.system = headset.system_name();
    // Qt's window system for the OpenGL context: X11 (GLX) when there is a display, else none (the context fails
    // with a message rather than Qt aborting for want of a display).
    if (!QGuiApplication::instance()) {
        if (!display || !*display) qputenv("QT_QPA_PLATFORM", "offscreen");
        // Widgets for the supervisor's window; else the GUI alone.
        if (options.supervisor) application = std::make_unique<QApplication>(argc, argv);
        else application = std::make_unique<QGuiApplication>(argc, argv);
    }
    XrEyeRenderer renderer;
    Result<void> ready = renderer.create_context();
    if (ready) ready = headset.create_session();
    // A view size beyond the runtime's largest image is drawn at that size and scaled into the largest image.
    const std::array<int, 2> render_size = options.view_size[0] > 0 ? options.view_size : headset.recommended_size();
    const std::array<int, 2> swapchain_size = {std::min(render_size[0], headset.max_size()[0]), std::min(render_size[1], headset.max_size()[1])};
    if (ready) ready = renderer.create_swapchains(headset, swapchain_size, render_size);
    if (!ready) {
        std::cerr << "kumite play --xr: " << ready.error().message << "\n";
        return 1;
    }
    std::cerr << "kumite play --xr: " << outcome.runtime << ", " << outcome.system << ", " << renderer.size()[0] << "x" << renderer.size()[1] << " per eye\n";
    outcome.stage_space = headset.stage_space();
    outcome.view_width = renderer.size()[0], outcome.view_height = renderer.size()[1];
    outcome.swapchain_width = renderer.swapchain_size()[0], outcome.swapchain_height = renderer.swapchain_size()[1];

    // The supervisor's window, once the headset is ready: the bout seen from outside, the HUD, the keys.
    std::unique_ptr<SupervisorWindow> supervisor;
    if (options.supervisor && qobject_cast<QApplication*>(QCoreApplication::instance())) {
        supervisor = std::make_unique<SupervisorWindow>(bout, *options.supervisor);
        outcome.supervisor_window = true;
        outcome.supervisor_renderer = supervisor->renderer();
        renderer.make_current();
    }
    Session session{headset, outcome, on_state};
    Scene scene;
    XrTrackedUser user;
    XrEyeViews views;
    std::array<XrCompositionLayerProjectionView, 2> layer_views{};
    XrTime first_display_time = 0, paused_ns = 0, last_display_time = 0;
    long long next_step = 0;
    double bout_t = 0.0;
    QImage eye_image;
    const auto started = Clock::now();
    while (!session.done) {
        session.poll(bout_t);
        if (session.done) break;
        // A runtime that does not end the session within 5 s of the exit request (frames or not) is left.
        if (session.exit_requested && std::chrono::duration<double>(Clock::now() - session.exit_requested_at).count() > 5.0) {
            outcome.ended_by += "_exit_unanswered";
            break;
        }
        if (!session.running) {
            // Before READY (or after STOPPING): no frames. A runtime that never starts the session is given 20 s.
            if (std::chrono::duration<double>(Clock::now() - started).count() > 20.0 && outcome.frames_waited == 0) {
                outcome.ended_by = "session_never_ready";
                break;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
            continue;
        }
        XrFrameState frame{XR_TYPE_FRAME_STATE};
        const auto wait_start = Clock::now();
        if (!headset.check(xrWaitFrame(headset.session(), nullptr, &frame), "xrWaitFrame")) {
            outcome.ended_by = "runtime_lost";
            break;
        }
        const auto frame_start = Clock::now();
        outcome.wait_us.add(microseconds(wait_start, frame_start));
        ++outcome.frames_waited;
        if (!headset.check(xrBeginFrame(headset.session(), nullptr), "xrBeginFrame")) {
            outcome.ended_by = "runtime_lost";
            break;
        }
        if (first_display_time == 0) first_display_time = last_display_time = frame.predictedDisplayTime;
        // Paused by the supervisor: the bout's time stands still (the headset still gets its frames).
        if (supervisor && supervisor->paused()) paused_ns += frame.predictedDisplayTime - last_display_time;
        last_display_time = frame.predictedDisplayTime;
        bout_t = double(frame.predictedDisplayTime - first_display_time - paused_ns) * 1e-9;

        headset.sync_and_locate(frame.predictedDisplayTime, session.state == XR_SESSION_STATE_FOCUSED, user);
        feed_tracker(bout, user, outcome);
        for (const auto& [pressed, line] : {std::pair{user.punch_pressed, "punch"}, std::pair{user.kick_pressed, "kick"}}) {
            if (pressed && bout.command(line)) ++outcome.button_orders;
        }
        // The bout at its own rate up to the frame's display time (a 20 Hz runtime gets three steps a frame, 90 Hz
        // about two in three frames).
        // As headless: steps at 0, 1/rate, ... before the duration.
        const auto steps_start = Clock::now();
        while (double(next_step) / bout.rate_hz() <= bout_t && double(next_step) / bout.rate_hz() < options.duration_s - 1e-9 &&
               !bout.quit_requested() && !session.exit_requested) {
            bout.step(double(next_step) / bout.rate_hz());
            ++next_step;
            after_step();
            if (supervisor) supervisor->after_step();
        }
        const auto steps_end = Clock::now();

        std::uint32_t layer_count = 0;
        XrCompositionLayerProjection layer{XR_TYPE_COMPOSITION_LAYER_PROJECTION};
        if (frame.shouldRender && headset.locate_views(frame.predictedDisplayTime, views)) {
            const bool capture = !options.eye_image_path.empty() && outcome.eye_image.path.empty() && bout_t >= options.duration_s - 1.0;
            const auto scene_start = Clock::now();
            headset_scene_build(bout, scene);
            const auto render_start = Clock::now();
            if (renderer.render(headset, scene, views, layer_views, capture ? 0 : -1, &eye_image)) {
                if (outcome.frames_rendered > 0) {
                    outcome.render_us.add(microseconds(render_start, Clock::now()));
                    outcome.scene_us.add(microseconds(scene_start, render_start));
                }
                layer.space = headset.world_space();
                layer.viewCount = 2;
                layer.views = layer_views.data();
                layer_count = 1;
                ++outcome.frames_rendered;
                if (capture) {
                    XrEyeImage& e = outcome.eye_image;
                    e.path = options.eye_image_path, e.t_s = bout.now_s(), e.width = eye_image.width(), e.height = eye_image.height();
                    const XrPoseWorld& pose = views.pose[0];
                    e.eye_pose = {pose.orientation.x(), pose.orientation.y(), pose.orientation.z(), pose.orientation.w(), pose.position.x(), pose.position.y(), pose.position.z()};
                    e.fov_rad = {views.fov[0].left, views.fov[0].right, views.fov[0].up, views.fov[0].down};
                    const Fighter& fighter = bout.fighter(0);
                    e.fighter_head = array_of(fighter.part_position(BodyPart::head));
                    e.fighter_chest = array_of(fighter.part_position(BodyPart::chest));
                    e.fighter_pelvis = array_of(fighter.part_position(BodyPart::pelvis));
                }
            }
        }
        const XrCompositionLayerBaseHeader* layers[] = {reinterpret_cast<const XrCompositionLayerBaseHeader*>(&layer)};
        XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO};
        end.displayTime = frame.predictedDisplayTime;
        end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
        end.layerCount = layer_count;
        end.layers = layer_count ? layers : nullptr;
        const auto end_start = Clock::now();
        if (headset.check(xrEndFrame(headset.session(), &end), "xrEndFrame")) ++outcome.frames_submitted;
        const auto frame_end = Clock::now();
        // Up to the first frame drawn: meshes uploaded, shaders' first use.
        if (outcome.frames_rendered <= 1) {
            outcome.first_frame_work_us = std::max(outcome.first_frame_work_us, microseconds(frame_start, frame_end));
        } else {
            outcome.frame_work_us.add(microseconds(frame_start, frame_end));
            outcome.steps_us.add(microseconds(steps_start, steps_end));
            outcome.end_frame_us.add(microseconds(end_start, frame_end));
        }

        // The supervisor's window between frames (outside the frame work); then the eyes' context again.
        if (supervisor) {
            supervisor->show_frame();
            renderer.make_current();
        }

        if (bout_t >= options.duration_s) session.request_exit("duration");
        else if (bout.quit_requested()) session.request_exit("quit_command");
        else if (user.quit_pressed) session.request_exit("quit_button");
        else if (supervisor && supervisor->closed()) session.request_exit("supervisor_closed");
    }
    outcome.paused_s = double(paused_ns) * 1e-9;
    if (supervisor && !options.supervisor_screenshot_path.empty() && !supervisor->save(options.supervisor_screenshot_path)) {
        std::cerr << "kumite play --xr: could not write the supervisor's screenshot " << options.supervisor_screenshot_path << "\n";
        outcome.supervisor_screenshot_failed = true;
    }
    if (supervisor) renderer.make_current();
    renderer.release();
    outcome.errors = headset.errors();
    outcome.error_messages = headset.error_messages();
    if (!outcome.eye_image.path.empty() && !eye_image.save(QString::fromStdString(outcome.eye_image.path), "PNG")) {
        std::cerr << "kumite play --xr: could not write the eye image " << outcome.eye_image.path << "\n";
        outcome.eye_image.path.clear();
    }
    return 0;
}

} // namespace kumite::view
