#include "view_camera.h"

#include <algorithm>
#include <cmath>

namespace kumite::view {

Eigen::Matrix4f frustum_matrix(float l, float r, float b, float t, float n, float f) {
    Eigen::Matrix4f m = Eigen::Matrix4f::Zero();
    m(0, 0) = 2 * n / (r - l);
    m(0, 2) = (r + l) / (r - l);
    m(1, 1) = 2 * n / (t - b);
    m(1, 2) = (t + b) / (t - b);
    m(2, 2) = -(f + n) / (f - n);
    m(2, 3) = -2 * f * n / (f - n);
    m(3, 2) = -1;
    return m;
}

Eigen::Matrix4f look_at_matrix(const Eigen::Vector3f& eye, const Eigen::Vector3f& target, const Eigen::Vector3f& up) {
    const Eigen::Vector3f back = (eye - target).normalized();
    const Eigen::Vector3f right = up.cross(back).normalized();
    const Eigen::Vector3f true_up = back.cross(right);
    Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
    m.block<1, 3>(0, 0) = right.transpose();
    m.block<1, 3>(1, 0) = true_up.transpose();
    m.block<1, 3>(2, 0) = back.transpose();
    m(0, 3) = -right.dot(eye);
    m(1, 3) = -true_up.dot(eye);
    m(2, 3) = -back.dot(eye);
    return m;
}

ViewProjection OrbitCamera::view_projection(float aspect) const {
    const Eigen::Vector3f offset(std::sin(yaw_rad) * std::cos(pitch_rad), std::sin(pitch_rad), std::cos(yaw_rad) * std::cos(pitch_rad));
    ViewProjection result;
    result.eye = target + distance_m * offset;
    result.view = look_at_matrix(result.eye, target, Eigen::Vector3f::UnitY());
    const float near_m = std::max(0.01f, distance_m * 0.01f), far_m = distance_m * 20.0f + 20.0f;
    const float top = near_m * std::tan(0.5f * fov_y_deg * float(M_PI) / 180.0f);
    const float right = top * std::max(aspect, 1e-3f);
    result.projection = frustum_matrix(-right, right, -top, top, near_m, far_m);
    return result;
}

void OrbitCamera::orbit(float dx_px, float dy_px) {
    yaw_rad -= dx_px * 0.008f;
    pitch_rad = std::clamp(pitch_rad + dy_px * 0.008f, -1.5f, 1.5f);
}

void OrbitCamera::pan(float dx_px, float dy_px, float viewport_height_px) {
    const float metres_per_px = 2.0f * distance_m * std::tan(0.5f * fov_y_deg * float(M_PI) / 180.0f) / std::max(viewport_height_px, 1.0f);
    const ViewProjection vp = view_projection(1.0f);
    const Eigen::Vector3f right = vp.view.block<1, 3>(0, 0).transpose();
    const Eigen::Vector3f up = vp.view.block<1, 3>(1, 0).transpose();
    target += (-dx_px * right + dy_px * up) * metres_per_px;
}

void OrbitCamera::zoom(float steps) { distance_m = std::clamp(distance_m * std::pow(0.88f, steps), 0.2f, 100.0f); }

void OrbitCamera::frame(const Eigen::AlignedBox3f& box) {
    if (box.isEmpty()) return;
    target = box.center();
    const float radius = std::max(0.5f * box.diagonal().norm(), 0.1f);
    distance_m = radius / std::sin(0.5f * fov_y_deg * float(M_PI) / 180.0f) * 1.05f;
}

ViewProjection off_axis_view_projection(const ScreenCorners& screen, Eigen::Vector3f eye, float near_m, float far_m) {
    const Eigen::Vector3f& pa = screen.lower_left;
    const Eigen::Vector3f& pb = screen.lower_right;
    const Eigen::Vector3f& pc = screen.upper_left;
    const Eigen::Vector3f vr = (pb - pa).normalized();
    const Eigen::Vector3f vu = (pc - pa).normalized();
    const Eigen::Vector3f vn = vr.cross(vu).normalized(); // towards the viewer
    // An eye on or behind the screen plane would flip the frustum: keep it a millimetre in front.
    const float in_front = (eye - pa).dot(vn);
    if (in_front < 1e-3f) eye += (1e-3f - in_front) * vn;
    const Eigen::Vector3f va = pa - eye, vb = pb - eye, vc = pc - eye;
    const float d = -va.dot(vn); // eye to screen plane
    const float scale = near_m / d;
    ViewProjection result;
    result.eye = eye;
    result.projection = frustum_matrix(vr.dot(va) * scale, vr.dot(vb) * scale, vu.dot(va) * scale, vu.dot(vc) * scale, near_m, far_m);
    Eigen::Matrix4f rotation = Eigen::Matrix4f::Identity();
    rotation.block<1, 3>(0, 0) = vr.transpose();
    rotation.block<1, 3>(1, 0) = vu.transpose();
    rotation.block<1, 3>(2, 0) = vn.transpose();
    Eigen::Matrix4f translation = Eigen::Matrix4f::Identity();
    translation.block<3, 1>(0, 3) = -eye;
    result.view = rotation * translation;
    return result;
}

} // namespace kumite::view
