#pragma once
// Euler angles in an explicit axis order, as BVH rotation channels use them: the order lists the axes as the
// channels appear, and the rotation is R = R(axis0, a0) * R(axis1, a1) * R(axis2, a2) (intrinsic, applied in the
// listed order). Angles are radians. Only Tait-Bryan orders (three distinct axes) exist here.

#include <Eigen/Geometry>

#include <array>
#include <string>

namespace kumite {

struct EulerOrder {
    std::array<int, 3> axes{2, 0, 1}; // 0 = X, 1 = Y, 2 = Z; distinct; default ZXY

    std::string name() const; // e.g. "ZXY"
    bool operator==(const EulerOrder&) const = default;
};

Eigen::Quaterniond quaternion_from_euler(const Eigen::Vector3d& angles_rad, EulerOrder order);

// The canonical angles that give this rotation in this order, as exporters write them: the middle angle in
// [-pi/2, pi/2], the others in [-pi, pi]. At gimbal lock (middle angle +-pi/2) the first angle is zero.
Eigen::Vector3d euler_from_quaternion(const Eigen::Quaterniond& rotation, EulerOrder order);

} // namespace kumite
