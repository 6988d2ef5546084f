#pragma once
// A character's heading frame: its pelvis projected on the floor, turned about Y only so that the character
// faces +Z. Targets, trajectories and boxes handed between stages are expressed in it (`..._in_heading`).

#include <Eigen/Geometry>

namespace kumite {

struct HeadingFrame {
    Eigen::Vector3d origin = Eigen::Vector3d::Zero(); // on the floor (y = floor height), metres, world
    double yaw_rad = 0.0;                             // rotation about +Y from world to heading axes

    Eigen::Vector3d to_heading(const Eigen::Vector3d& world) const;
    Eigen::Vector3d to_world(const Eigen::Vector3d& in_heading) const;
    // An offset or a velocity (not a point): turned about Y only, the origin left out.
    Eigen::Vector3d direction_to_heading(const Eigen::Vector3d& world) const;
    Eigen::Vector3d direction_to_world(const Eigen::Vector3d& in_heading) const;
};

// From the pelvis position and the world direction the body faces (any vector with a horizontal part).
HeadingFrame heading_frame_from(const Eigen::Vector3d& pelvis_position, const Eigen::Vector3d& facing, double floor_y = 0.0);

} // namespace kumite
