#include "kumite/core/heading_frame.h"

#include <cmath>

namespace kumite {

Eigen::Vector3d HeadingFrame::to_heading(const Eigen::Vector3d& world) const { return direction_to_heading(world - origin); }

Eigen::Vector3d HeadingFrame::to_world(const Eigen::Vector3d& h) const { return origin + direction_to_world(h); }

Eigen::Vector3d HeadingFrame::direction_to_heading(const Eigen::Vector3d& d) const {
    // Undo the yaw: rotate by -yaw about Y.
    const double c = std::cos(yaw_rad), s = std::sin(yaw_rad);
    return {c * d.x() - s * d.z(), d.y(), s * d.x() + c * d.z()};
}

Eigen::Vector3d HeadingFrame::direction_to_world(const Eigen::Vector3d& h) const {
    const double c = std::cos(yaw_rad), s = std::sin(yaw_rad);
    return {c * h.x() + s * h.z(), h.y(), -s * h.x() + c * h.z()};
}

HeadingFrame heading_frame_from(const Eigen::Vector3d& pelvis_position, const Eigen::Vector3d& facing, double floor_y) {
    HeadingFrame frame;
    frame.origin = Eigen::Vector3d(pelvis_position.x(), floor_y, pelvis_position.z());
    // Yaw such that the heading's +Z maps to the facing direction: to_world(0,0,1) = (sin yaw, 0, cos yaw).
    frame.yaw_rad = std::atan2(facing.x(), facing.z());
    return frame;
}

} // namespace kumite
