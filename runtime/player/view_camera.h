#pragma once
// Cameras of the viewports (no Qt): an orbit camera for the desk, and Kooima's generalized perspective for a wall
// screen seen from a tracked eye ("Generalized Perspective Projection", R. Kooima, 2009): the screen is given by
// three measured corners in world metres, the projection is off-axis so the picture on the wall lines up with the
// room from where the eye is.

#include <Eigen/Geometry>

namespace kumite::view {

struct ViewProjection {
    Eigen::Matrix4f view = Eigen::Matrix4f::Identity();       // world -> eye
    Eigen::Matrix4f projection = Eigen::Matrix4f::Identity(); // eye -> clip (OpenGL conventions, z in -1..1)
    Eigen::Vector3f eye = Eigen::Vector3f::Zero();           // world
};

struct OrbitCamera {
    Eigen::Vector3f target{0.0f, 1.0f, 0.0f};
    float yaw_rad = 0.6f;    // about +Y, 0 looks along -Z (from +Z towards the origin)
    float pitch_rad = 0.25f; // positive looks down
    float distance_m = 4.0f;
    float fov_y_deg = 45.0f;

    ViewProjection view_projection(float aspect) const;
    void orbit(float dx_px, float dy_px);                         // a mouse drag
    void pan(float dx_px, float dy_px, float viewport_height_px); // moves the target in the view plane
    void zoom(float steps);                                       // wheel steps, positive comes closer
    void frame(const Eigen::AlignedBox3f& box);                   // the box fills the view
};

struct ScreenCorners {
    Eigen::Vector3f lower_left{-1.5f, 0.0f, -0.5f}; // default: a 3 m x 2.25 m wall half a metre behind the fighter's start
    Eigen::Vector3f lower_right{1.5f, 0.0f, -0.5f};
    Eigen::Vector3f upper_left{-1.5f, 2.25f, -0.5f};
};

// The off-axis view and projection for `eye` looking at the screen. Eyes on the back side of the screen are
// moved just in front of it so the matrices stay finite.
ViewProjection off_axis_view_projection(const ScreenCorners& screen, Eigen::Vector3f eye, float near_m, float far_m);

Eigen::Matrix4f frustum_matrix(float left, float right, float bottom, float top, float near_m, float far_m);
Eigen::Matrix4f look_at_matrix(const Eigen::Vector3f& eye, const Eigen::Vector3f& target, const Eigen::Vector3f& up);

} // namespace kumite::view
