#include "kumite/core/euler.h"

#include <algorithm>
#include <cmath>

namespace kumite {

std::string EulerOrder::name() const {
    std::string result;
    for (int axis : axes) result += static_cast<char>('X' + axis);
    return result;
}

Eigen::Quaterniond quaternion_from_euler(const Eigen::Vector3d& angles_rad, EulerOrder order) {
    Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
    for (int i = 0; i < 3; ++i) {
        rotation = rotation * Eigen::Quaterniond(Eigen::AngleAxisd(angles_rad[i], Eigen::Vector3d::Unit(order.axes[i])));
    }
    return rotation;
}

Eigen::Vector3d euler_from_quaternion(const Eigen::Quaterniond& rotation, EulerOrder order) {
    // For R = Ri(a) Rj(b) Rk(c) with (i, j, k) distinct and s = +1 for an even permutation of XYZ, -1 for odd:
    //   R(i,k) = s sin b,  R(j,k) = -s sin a cos b,  R(k,k) = cos a cos b,  R(i,j) = -s cos b sin c,  R(i,i) = cos b cos c.
    const Eigen::Matrix3d m = rotation.normalized().toRotationMatrix();
    const int i = order.axes[0], j = order.axes[1], k = order.axes[2];
    const double s = ((j - i + 3) % 3 == 1) ? 1.0 : -1.0;
    const double sin_b = std::clamp(s * m(i, k), -1.0, 1.0);
    Eigen::Vector3d angles;
    angles[1] = std::asin(sin_b);
    if (std::abs(sin_b) < 1.0 - 1e-12) {
        angles[0] = std::atan2(-s * m(j, k), m(k, k));
        angles[2] = std::atan2(-s * m(i, j), m(i, i));
    } else {
        // Gimbal lock: only a +- c is defined. Put it all in c (a = 0), as exporters such as iClone do:
        // then R = Rj(b) Rk(c), and Rk(c) = Rj(b)^T R gives c from its block around axis k.
        angles[0] = 0.0;
        const Eigen::Matrix3d about_k = Eigen::AngleAxisd(angles[1], Eigen::Vector3d::Unit(j)).toRotationMatrix().transpose() * m;
        const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
        angles[2] = std::atan2(about_k(k2, k1), about_k(k1, k1));
    }
    return angles;
}

} // namespace kumite
