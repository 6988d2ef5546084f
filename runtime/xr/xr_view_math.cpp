#include "xr_view_math.h"

#include <cmath>

namespace kumite::view {

Eigen::Vector3f head_centre_from_view(const XrPoseWorld& view_pose) {
    return view_pose.position + view_pose.orientation * Eigen::Vector3f(0.0f, 0.0f, k_head_centre_behind_eyes_m);
}

Eigen::Vector3f view_position_for_head_centre(const Eigen::Vector3f& head_centre, const Eigen::Quaternionf& orientation) {
    return head_centre - orientation * Eigen::Vector3f(0.0f, 0.0f, k_head_centre_behind_eyes_m);
}

ViewProjection xr_eye_view_projection(const XrPoseWorld& eye_pose, const XrFovRad& fov, float near_m, float far_m) {
    ViewProjection result;
    const Eigen::Matrix3f to_world = eye_pose.orientation.normalized().toRotationMatrix();
    result.view.setIdentity();
    result.view.topLeftCorner<3, 3>() = to_world.transpose();
    result.view.topRightCorner<3, 1>() = -(to_world.transpose() * eye_pose.position);
    result.projection = frustum_matrix(near_m * std::tan(fov.left), near_m * std::tan(fov.right), near_m * std::tan(fov.down),
                                       near_m * std::tan(fov.up), near_m, far_m);
    result.eye = eye_pose.position;
    return result;
}

} // namespace kumite::view
