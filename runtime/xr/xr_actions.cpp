// The controllers' actions and their suggested bindings (part of XrHeadset: xr_headset.h). The mapping the user
// reads in docs/room.md ("The headset"): right A punches, right B kicks, left menu (Touch, simple) or left B
// (Index) ends the bout; the simple controller's select asks for a punch (right) or a kick (left).
#include "xr_headset.h"

#include <cstring>
#include <initializer_list>
#include <utility>
#include <vector>

namespace kumite::view {
namespace {

XrAction create_action(XrHeadset& headset, XrActionSet set, const char* name, const char* localized, XrActionType type, const std::array<XrPath, 2>& hands) {
    XrActionCreateInfo info{XR_TYPE_ACTION_CREATE_INFO};
    std::strncpy(info.actionName, name, XR_MAX_ACTION_NAME_SIZE - 1);
    std::strncpy(info.localizedActionName, localized, XR_MAX_LOCALIZED_ACTION_NAME_SIZE - 1);
    info.actionType = type;
    const bool per_hand = type == XR_ACTION_TYPE_POSE_INPUT || type == XR_ACTION_TYPE_FLOAT_INPUT;
    info.countSubactionPaths = per_hand ? 2 : 0;
    info.subactionPaths = per_hand ? hands.data() : nullptr;
    XrAction action = XR_NULL_HANDLE;
    headset.check(xrCreateAction(set, &info, &action), name);
    return action;
}

} // namespace

Result<void> XrHeadset::create_actions() {
    XrActionSetCreateInfo set_info{XR_TYPE_ACTION_SET_CREATE_INFO};
    std::strncpy(set_info.actionSetName, "sparring", XR_MAX_ACTION_SET_NAME_SIZE - 1);
    std::strncpy(set_info.localizedActionSetName, "Sparring", XR_MAX_LOCALIZED_ACTION_SET_NAME_SIZE - 1);
    if (!check(xrCreateActionSet(m_instance, &set_info, &m_action_set), "xrCreateActionSet")) return Error{ErrorCode::io, m_error_messages.back()};
    check(xrStringToPath(m_instance, "/user/hand/left", &m_hand_paths[0]), "xrStringToPath");
    check(xrStringToPath(m_instance, "/user/hand/right", &m_hand_paths[1]), "xrStringToPath");
    m_grip = create_action(*this, m_action_set, "grip", "Hand (grip)", XR_ACTION_TYPE_POSE_INPUT, m_hand_paths);
    m_aim = create_action(*this, m_action_set, "aim", "Pointing (aim)", XR_ACTION_TYPE_POSE_INPUT, m_hand_paths);
    m_trigger = create_action(*this, m_action_set, "trigger", "Trigger", XR_ACTION_TYPE_FLOAT_INPUT, m_hand_paths);
    m_punch = create_action(*this, m_action_set, "punch", "Ask for a punch", XR_ACTION_TYPE_BOOLEAN_INPUT, m_hand_paths);
    m_kick = create_action(*this, m_action_set, "kick", "Ask for a kick", XR_ACTION_TYPE_BOOLEAN_INPUT, m_hand_paths);
    m_quit = create_action(*this, m_action_set, "quit", "End the bout", XR_ACTION_TYPE_BOOLEAN_INPUT, m_hand_paths);
    if (m_errors > 0) return Error{ErrorCode::io, "the controllers' actions could not be created: " + m_error_messages.back()};

    using Binding = std::pair<XrAction, const char*>;
    auto suggest = [&](const char* profile, std::initializer_list<Binding> bindings) {
        std::vector<XrActionSuggestedBinding> suggested;
        for (const Binding& b : bindings) {
            XrPath path = XR_NULL_PATH;
            if (check(xrStringToPath(m_instance, b.second, &path), b.second)) suggested.push_back({b.first, path});
        }
        XrPath profile_path = XR_NULL_PATH;
        if (!check(xrStringToPath(m_instance, profile, &profile_path), profile)) return;
        XrInteractionProfileSuggestedBinding info{XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
        info.interactionProfile = profile_path;
        info.countSuggestedBindings = std::uint32_t(suggested.size());
        info.suggestedBindings = suggested.data();
        check(xrSuggestInteractionProfileBindings(m_instance, &info), profile);
    };
    suggest("/interaction_profiles/valve/index_controller",
            {{m_grip, "/user/hand/left/input/grip/pose"}, {m_grip, "/user/hand/right/input/grip/pose"},
             {m_aim, "/user/hand/left/input/aim/pose"}, {m_aim, "/user/hand/right/input/aim/pose"},
             {m_trigger, "/user/hand/left/input/trigger/value"}, {m_trigger, "/user/hand/right/input/trigger/value"},
             {m_punch, "/user/hand/right/input/a/click"}, {m_kick, "/user/hand/right/input/b/click"}, {m_quit, "/user/hand/left/input/b/click"}});
    suggest("/interaction_profiles/oculus/touch_controller",
            {{m_grip, "/user/hand/left/input/grip/pose"}, {m_grip, "/user/hand/right/input/grip/pose"},
             {m_aim, "/user/hand/left/input/aim/pose"}, {m_aim, "/user/hand/right/input/aim/pose"},
             {m_trigger, "/user/hand/left/input/trigger/value"}, {m_trigger, "/user/hand/right/input/trigger/value"},
             {m_punch, "/user/hand/right/input/a/click"}, {m_kick, "/user/hand/right/input/b/click"}, {m_quit, "/user/hand/left/input/menu/click"}});
    suggest("/interaction_profiles/khr/simple_controller",
            {{m_grip, "/user/hand/left/input/grip/pose"}, {m_grip, "/user/hand/right/input/grip/pose"},
             {m_aim, "/user/hand/left/input/aim/pose"}, {m_aim, "/user/hand/right/input/aim/pose"},
             {m_punch, "/user/hand/right/input/select/click"}, {m_kick, "/user/hand/left/input/select/click"}, {m_quit, "/user/hand/left/input/menu/click"}});

    for (std::size_t side = 0; side < 2; ++side) {
        XrActionSpaceCreateInfo info{XR_TYPE_ACTION_SPACE_CREATE_INFO};
        info.subactionPath = m_hand_paths[side];
        info.poseInActionSpace.orientation.w = 1.0f;
        info.action = m_grip;
        check(xrCreateActionSpace(m_session, &info, &m_grip_spaces[side]), "xrCreateActionSpace(grip)");
        info.action = m_aim;
        check(xrCreateActionSpace(m_session, &info, &m_aim_spaces[side]), "xrCreateActionSpace(aim)");
    }
    XrSessionActionSetsAttachInfo attach{XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO};
    attach.countActionSets = 1;
    attach.actionSets = &m_action_set;
    if (!check(xrAttachSessionActionSets(m_session, &attach), "xrAttachSessionActionSets")) return Error{ErrorCode::io, m_error_messages.back()};
    return {};
}

} // namespace kumite::view
