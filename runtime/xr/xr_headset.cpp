#include "xr_headset.h"

#include "xr_glx_session.h"

#include <cstdlib>
#include <cstring>
#include <string_view>

namespace kumite::view {
namespace {

std::string result_name(XrInstance instance, XrResult result) {
    char name[XR_MAX_RESULT_STRING_SIZE] = {};
    if (instance != XR_NULL_HANDLE && XR_SUCCEEDED(xrResultToString(instance, result, name))) return name;
    // Without an instance the loader cannot name it: the codes a missing or broken runtime gives.
    switch (result) {
    case XR_ERROR_RUNTIME_UNAVAILABLE: return "XR_ERROR_RUNTIME_UNAVAILABLE";
    case XR_ERROR_RUNTIME_FAILURE: return "XR_ERROR_RUNTIME_FAILURE";
    case XR_ERROR_INSTANCE_LOST: return "XR_ERROR_INSTANCE_LOST";
    case XR_ERROR_INITIALIZATION_FAILED: return "XR_ERROR_INITIALIZATION_FAILED";
    case XR_ERROR_EXTENSION_NOT_PRESENT: return "XR_ERROR_EXTENSION_NOT_PRESENT";
    default: break;
    }
    return "XrResult " + std::to_string(int(result));
}

std::string no_runtime_message(XrResult result) {
    const char* json = std::getenv("XR_RUNTIME_JSON");
    std::string looked = json && *json ? std::string("XR_RUNTIME_JSON=") + json + " (the manifest it names)"
                                       : "XR_RUNTIME_JSON (unset), then openxr/1/active_runtime.json in $XDG_CONFIG_HOME (~/.config), "
                                         "$XDG_CONFIG_DIRS (/etc/xdg) and /etc";
    return "no OpenXR runtime could be opened (xrCreateInstance: " + result_name(XR_NULL_HANDLE, result) + "). The OpenXR loader looked at " +
           looked + ". Install and start a runtime (SteamVR, Monado, or your headset's own) so that it is the active runtime, or set "
           "XR_RUNTIME_JSON to its manifest; to try without a headset, scripts/build_monado.sh builds Monado and "
           "scripts/with_monado.sh runs a command against it (null compositor, remote driver).";
}

bool extension_offered(std::string_view name) {
    std::uint32_t count = 0;
    if (XR_FAILED(xrEnumerateInstanceExtensionProperties(nullptr, 0, &count, nullptr))) return false;
    std::vector<XrExtensionProperties> properties(count, {XR_TYPE_EXTENSION_PROPERTIES, nullptr, {}, 0});
    if (XR_FAILED(xrEnumerateInstanceExtensionProperties(nullptr, count, &count, properties.data()))) return false;
    for (const XrExtensionProperties& p : properties) {
        if (name == p.extensionName) return true;
    }
    return false;
}

XrPoseWorld pose_from(const XrPosef& pose) {
    XrPoseWorld out;
    out.orientation = Eigen::Quaternionf(pose.orientation.w, pose.orientation.x, pose.orientation.y, pose.orientation.z);
    out.position = Eigen::Vector3f(pose.position.x, pose.position.y, pose.position.z);
    return out;
}

} // namespace

const char* xr_session_state_name(XrSessionState state) {
    switch (state) {
    case XR_SESSION_STATE_IDLE: return "idle";
    case XR_SESSION_STATE_READY: return "ready";
    case XR_SESSION_STATE_SYNCHRONIZED: return "synchronized";
    case XR_SESSION_STATE_VISIBLE: return "visible";
    case XR_SESSION_STATE_FOCUSED: return "focused";
    case XR_SESSION_STATE_STOPPING: return "stopping";
    case XR_SESSION_STATE_LOSS_PENDING: return "loss_pending";
    case XR_SESSION_STATE_EXITING: return "exiting";
    default: return "unknown";
    }
}

Result<std::unique_ptr<XrHeadset>> XrHeadset::open() {
    std::unique_ptr<XrHeadset> headset(new XrHeadset());
    if (!extension_offered("XR_KHR_opengl_enable")) {
        // The loader lists a runtime's extensions only when it finds a runtime: none found reads the same as none offered.
        std::uint32_t count = 0;
        const XrResult listed = xrEnumerateInstanceExtensionProperties(nullptr, 0, &count, nullptr);
        if (XR_FAILED(listed) || count == 0) return Error{ErrorCode::io, no_runtime_message(listed)};
        return Error{ErrorCode::unsupported, "the OpenXR runtime offers no XR_KHR_opengl_enable (kumite renders with OpenGL)"};
    }
    XrInstanceCreateInfo info{XR_TYPE_INSTANCE_CREATE_INFO};
    std::strncpy(info.applicationInfo.applicationName, "kumite play", XR_MAX_APPLICATION_NAME_SIZE - 1);
    std::strncpy(info.applicationInfo.engineName, "kumite", XR_MAX_ENGINE_NAME_SIZE - 1);
    info.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
    const char* extensions[] = {"XR_KHR_opengl_enable"};
    info.enabledExtensionCount = 1;
    info.enabledExtensionNames = extensions;
    if (const XrResult created = xrCreateInstance(&info, &headset->m_instance); XR_FAILED(created)) {
        headset->m_instance = XR_NULL_HANDLE;
        return Error{ErrorCode::io, no_runtime_message(created)};
    }
    XrInstanceProperties properties{XR_TYPE_INSTANCE_PROPERTIES};
    if (XR_SUCCEEDED(xrGetInstanceProperties(headset->m_instance, &properties))) {
        headset->m_runtime_name = std::string(properties.runtimeName) + " " + std::to_string(XR_VERSION_MAJOR(properties.runtimeVersion)) + "." +
                                  std::to_string(XR_VERSION_MINOR(properties.runtimeVersion)) + "." + std::to_string(XR_VERSION_PATCH(properties.runtimeVersion));
    }
    XrSystemGetInfo system_info{XR_TYPE_SYSTEM_GET_INFO};
    system_info.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
    if (const XrResult got = xrGetSystem(headset->m_instance, &system_info, &headset->m_system); XR_FAILED(got)) {
        return Error{ErrorCode::io, "the OpenXR runtime '" + headset->m_runtime_name + "' has no headset (xrGetSystem: " +
                                        result_name(headset->m_instance, got) + "): is it connected and switched on?"};
    }
    XrSystemProperties system{XR_TYPE_SYSTEM_PROPERTIES};
    if (XR_SUCCEEDED(xrGetSystemProperties(headset->m_instance, headset->m_system, &system))) headset->m_system_name = system.systemName;
    std::uint32_t views = 0;
    std::array<XrViewConfigurationView, 2> view_sizes{};
    for (XrViewConfigurationView& v : view_sizes) v.type = XR_TYPE_VIEW_CONFIGURATION_VIEW;
    if (XR_FAILED(xrEnumerateViewConfigurationViews(headset->m_instance, headset->m_system, XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO, 2, &views,
                                                    view_sizes.data())) || views != 2) {
        return Error{ErrorCode::unsupported, "the OpenXR system '" + headset->m_system_name + "' has no stereo view configuration"};
    }
    headset->m_recommended_size = {int(view_sizes[0].recommendedImageRectWidth), int(view_sizes[0].recommendedImageRectHeight)};
    headset->m_max_size = {int(view_sizes[0].maxImageRectWidth), int(view_sizes[0].maxImageRectHeight)};
    return headset;
}

XrHeadset::~XrHeadset() {
    for (XrSpace space : {m_grip_spaces[0], m_grip_spaces[1], m_aim_spaces[0], m_aim_spaces[1], m_view, m_world}) {
        if (space != XR_NULL_HANDLE) xrDestroySpace(space);
    }
    if (m_action_set != XR_NULL_HANDLE) xrDestroyActionSet(m_action_set);
    if (m_session != XR_NULL_HANDLE) xrDestroySession(m_session);
    if (m_instance != XR_NULL_HANDLE) xrDestroyInstance(m_instance);
}

bool XrHeadset::check(XrResult result, const char* what) {
    if (XR_SUCCEEDED(result)) return true;
    ++m_errors;
    if (m_error_messages.size() < 20) m_error_messages.push_back(std::string(what) + ": " + result_name(m_instance, result));
    return false;
}

Result<void> XrHeadset::create_session() {
    std::string error;
    if (!xr_glx_create_session(m_instance, m_system, m_session, error)) return Error{ErrorCode::io, error};
    // The world: STAGE (floor at y = 0) when the runtime has one, else LOCAL lifted to a standing user's eye height.
    std::uint32_t count = 0;
    std::vector<XrReferenceSpaceType> spaces(8);
    m_stage = false;
    if (XR_SUCCEEDED(xrEnumerateReferenceSpaces(m_session, std::uint32_t(spaces.size()), &count, spaces.data()))) {
        for (std::uint32_t i = 0; i < count; ++i) m_stage = m_stage || spaces[i] == XR_REFERENCE_SPACE_TYPE_STAGE;
    }
    XrReferenceSpaceCreateInfo world{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
    world.referenceSpaceType = m_stage ? XR_REFERENCE_SPACE_TYPE_STAGE : XR_REFERENCE_SPACE_TYPE_LOCAL;
    world.poseInReferenceSpace.orientation.w = 1.0f;
    if (!m_stage) world.poseInReferenceSpace.position.y = -1.6f; // the floor 1.6 m below LOCAL's origin (the head at start)
    if (!check(xrCreateReferenceSpace(m_session, &world, &m_world), "xrCreateReferenceSpace(world)")) return Error{ErrorCode::io, m_error_messages.back()};
    XrReferenceSpaceCreateInfo view{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
    view.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_VIEW;
    view.poseInReferenceSpace.orientation.w = 1.0f;
    if (!check(xrCreateReferenceSpace(m_session, &view, &m_view), "xrCreateReferenceSpace(view)")) return Error{ErrorCode::io, m_error_messages.back()};
    return create_actions();
}

bool XrHeadset::locate(XrSpace space, XrTime time, XrPoseWorld& pose) {
    XrSpaceLocation location{XR_TYPE_SPACE_LOCATION};
    if (!check(xrLocateSpace(space, m_world, time, &location), "xrLocateSpace")) return false;
    const XrSpaceLocationFlags needed = XR_SPACE_LOCATION_POSITION_VALID_BIT | XR_SPACE_LOCATION_ORIENTATION_VALID_BIT;
    if ((location.locationFlags & needed) != needed) return false;
    pose = pose_from(location.pose);
    return true;
}

void XrHeadset::sync_and_locate(XrTime display_time, bool focused, XrTrackedUser& user) {
    user.punch_pressed = user.kick_pressed = user.quit_pressed = false;
    if (focused) {
        XrActiveActionSet active{m_action_set, XR_NULL_PATH};
        XrActionsSyncInfo sync{XR_TYPE_ACTIONS_SYNC_INFO};
        sync.countActiveActionSets = 1;
        sync.activeActionSets = &active;
        check(xrSyncActions(m_session, &sync), "xrSyncActions");
        auto pressed = [&](XrAction action) {
            XrActionStateGetInfo info{XR_TYPE_ACTION_STATE_GET_INFO};
            info.action = action;
            XrActionStateBoolean state{XR_TYPE_ACTION_STATE_BOOLEAN};
            return check(xrGetActionStateBoolean(m_session, &info, &state), "xrGetActionStateBoolean") && state.isActive && state.changedSinceLastSync &&
                   state.currentState;
        };
        user.punch_pressed = pressed(m_punch), user.kick_pressed = pressed(m_kick), user.quit_pressed = pressed(m_quit);
        for (int side = 0; side < 2; ++side) {
            XrActionStateGetInfo info{XR_TYPE_ACTION_STATE_GET_INFO};
            info.action = m_trigger;
            info.subactionPath = m_hand_paths[std::size_t(side)];
            XrActionStateFloat state{XR_TYPE_ACTION_STATE_FLOAT};
            user.trigger[std::size_t(side)] = check(xrGetActionStateFloat(m_session, &info, &state), "xrGetActionStateFloat") && state.isActive ? state.currentState : 0.0f;
        }
    }
    user.head_tracked = locate(m_view, display_time, user.head);
    for (std::size_t side = 0; side < 2; ++side) {
        // Grip poses are located only while the actions are synced (focused); otherwise the hands count as lost.
        user.grip_tracked[side] = focused && locate(m_grip_spaces[side], display_time, user.grip[side]);
        if (focused) locate(m_aim_spaces[side], display_time, user.aim[side]);
    }
}

bool XrHeadset::locate_views(XrTime display_time, XrEyeViews& views) {
    XrViewLocateInfo info{XR_TYPE_VIEW_LOCATE_INFO};
    info.viewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
    info.displayTime = display_time;
    info.space = m_world;
    XrViewState state{XR_TYPE_VIEW_STATE};
    std::array<XrView, 2> located{};
    for (XrView& v : located) v.type = XR_TYPE_VIEW;
    std::uint32_t count = 0;
    if (!check(xrLocateViews(m_session, &info, &state, 2, &count, located.data()), "xrLocateViews")) return false;
    const XrViewStateFlags needed = XR_VIEW_STATE_POSITION_VALID_BIT | XR_VIEW_STATE_ORIENTATION_VALID_BIT;
    if ((state.viewStateFlags & needed) != needed || count != 2) return false;
    views.count = 2;
    for (std::size_t eye = 0; eye < 2; ++eye) {
        views.pose[eye] = pose_from(located[eye].pose);
        views.fov[eye] = {located[eye].fov.angleLeft, located[eye].fov.angleRight, located[eye].fov.angleUp, located[eye].fov.angleDown};
    }
    return true;
}

bool XrHeadset::poll_event(XrSessionState& state_changed, bool& instance_lost) {
    XrEventDataBuffer event{XR_TYPE_EVENT_DATA_BUFFER};
    const XrResult polled = xrPollEvent(m_instance, &event);
    if (polled == XR_EVENT_UNAVAILABLE) return false;
    if (!check(polled, "xrPollEvent")) {
        instance_lost = true; // the runtime is gone: nothing more will come
        return true;
    }
    state_changed = XR_SESSION_STATE_UNKNOWN;
    if (event.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) {
        state_changed = reinterpret_cast<const XrEventDataSessionStateChanged&>(event).state;
    } else if (event.type == XR_TYPE_EVENT_DATA_INSTANCE_LOSS_PENDING) {
        instance_lost = true;
    }
    return true;
}

} // namespace kumite::view
