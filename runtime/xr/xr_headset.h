#pragma once
// The headset through OpenXR: the instance (the runtime the system names, XR_RUNTIME_JSON honoured), the HMD system,
// a session on the current OpenGL (GLX) context, the STAGE space (LOCAL 1.6 m above the floor when the runtime has
// no STAGE), and the controllers' actions: grip and aim poses, trigger, and the buttons the user can press (punch,
// kick, quit; docs/room.md, "The headset"). Every failed OpenXR call is counted and its first messages kept; nothing
// throws. One thread: the caller's, with the GL context current.

#include "xr_view_math.h"

#include "kumite/core/result.h"

#include <openxr/openxr.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace kumite::view {

// The user's poses located at one display time, in the STAGE space (= world).
struct XrTrackedUser {
    bool head_tracked = false;
    XrPoseWorld head; // the view pose: between the eyes
    std::array<bool, 2> grip_tracked{};
    std::array<XrPoseWorld, 2> grip, aim; // [left, right]
    std::array<float, 2> trigger{};
    bool punch_pressed = false, kick_pressed = false, quit_pressed = false; // pressed since the last sync
};

struct XrEyeViews {
    int count = 0;
    std::array<XrPoseWorld, 2> pose;
    std::array<XrFovRad, 2> fov;
};

class XrHeadset {
public:
    // Instance and system. No runtime, no HMD: an error that says what the loader looked for and how to get one.
    static Result<std::unique_ptr<XrHeadset>> open();
    ~XrHeadset();
    XrHeadset(const XrHeadset&) = delete;
    XrHeadset& operator=(const XrHeadset&) = delete;

    // The session on the current GLX context, its spaces and actions. Errors name the call that failed.
    Result<void> create_session();

    // Checks an OpenXR result: counts a failure and keeps its message (the first 20). Returns whether it succeeded.
    bool check(XrResult result, const char* what);

    // The next event, if any: a session state change is returned as its state; instance loss as LOSS_PENDING.
    bool poll_event(XrSessionState& state_changed, bool& instance_lost);

    void sync_and_locate(XrTime display_time, bool focused, XrTrackedUser& user);
    bool locate_views(XrTime display_time, XrEyeViews& views);

    XrInstance instance() const { return m_instance; }
    XrSession session() const { return m_session; }
    XrSpace world_space() const { return m_world; }
    bool stage_space() const { return m_stage; } // false: LOCAL with the floor offset
    const std::string& runtime_name() const { return m_runtime_name; }
    const std::string& system_name() const { return m_system_name; }
    std::array<int, 2> recommended_size() const { return m_recommended_size; }
    std::array<int, 2> max_size() const { return m_max_size; } // the largest swapchain image per eye
    long long errors() const { return m_errors; }
    const std::vector<std::string>& error_messages() const { return m_error_messages; }

private:
    XrHeadset() = default;
    Result<void> create_actions();
    bool locate(XrSpace space, XrTime time, XrPoseWorld& pose);

    XrInstance m_instance = XR_NULL_HANDLE;
    XrSystemId m_system = XR_NULL_SYSTEM_ID;
    XrSession m_session = XR_NULL_HANDLE;
    XrSpace m_world = XR_NULL_HANDLE, m_view = XR_NULL_HANDLE;
    bool m_stage = true;
    XrActionSet m_action_set = XR_NULL_HANDLE;
    XrAction m_grip = XR_NULL_HANDLE, m_aim = XR_NULL_HANDLE, m_trigger = XR_NULL_HANDLE;
    XrAction m_punch = XR_NULL_HANDLE, m_kick = XR_NULL_HANDLE, m_quit = XR_NULL_HANDLE;
    std::array<XrPath, 2> m_hand_paths{};
    std::array<XrSpace, 2> m_grip_spaces{}, m_aim_spaces{};
    std::string m_runtime_name, m_system_name;
    std::array<int, 2> m_recommended_size{}, m_max_size{};
    long long m_errors = 0;
    std::vector<std::string> m_error_messages;
};

// The name OpenXR gives a session state ("focused", "loss_pending", ...).
const char* xr_session_state_name(XrSessionState state);

} // namespace kumite::view
