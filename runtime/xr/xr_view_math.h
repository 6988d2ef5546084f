#pragma once
// The headset's geometry as the viewer's matrices (no OpenXR types: plain numbers, so it is tested without a
// runtime). OpenXR poses are right-handed, Y up, metres, a view looking along its -Z; field-of-view angles are
// radians, left and down negative (asymmetric frusta: each eye's own four angles, not a symmetric FOV).

#include "view_camera.h"

#include <Eigen/Geometry>

namespace kumite::view {

// A pose: orientation (unit quaternion) and position, in the space it was located in (here the STAGE = world).
struct XrPoseWorld {
    Eigen::Quaternionf orientation = Eigen::Quaternionf::Identity();
    Eigen::Vector3f position = Eigen::Vector3f::Zero();
};

struct XrFovRad {
    float left = -0.8f, right = 0.8f, up = 0.8f, down = -0.8f;
};

// The centre of the head (where kumite's trackers put the user's head: the skull's centre) from the headset's view
// pose (the eyes' midpoint): 9 cm behind the eyes along the view's +Z, at eye height. A fixed offset for an adult
// head (eye plane to skull centre); the same whichever way the head turns.
inline constexpr float k_head_centre_behind_eyes_m = 0.09f;
Eigen::Vector3f head_centre_from_view(const XrPoseWorld& view_pose);
// The inverse, for a test that feeds a head centre: the view pose's position for a head centre and orientation.
Eigen::Vector3f view_position_for_head_centre(const Eigen::Vector3f& head_centre, const Eigen::Quaternionf& orientation);

// The eye's view (world -> eye) and its off-axis projection from the four angles (OpenGL clip conventions).
ViewProjection xr_eye_view_projection(const XrPoseWorld& eye_pose, const XrFovRad& fov, float near_m, float far_m);

} // namespace kumite::view
