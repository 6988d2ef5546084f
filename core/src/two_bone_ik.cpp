#include "kumite/core/two_bone_ik.h"

#include <algorithm>
#include <cmath>

namespace kumite {

Eigen::Quaterniond rotation_between(const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
    // q = normalize(1 + a.b, a x b) for unit a, b: no trigonometry. Opposite directions need an explicit axis.
    const Eigen::Vector3d a = from.normalized(), b = to.normalized();
    const double dot = a.dot(b);
    if (dot < -1.0 + 1e-12) {
        const Eigen::Vector3d axis = orthogonal_reference(a, Eigen::Vector3d::UnitY());
        return Eigen::Quaterniond(0.0, axis.x(), axis.y(), axis.z());
    }
    const Eigen::Vector3d cross = a.cross(b);
    return Eigen::Quaterniond(1.0 + dot, cross.x(), cross.y(), cross.z()).normalized();
}

Eigen::Vector3d orthogonal_reference(const Eigen::Vector3d& axis, const Eigen::Vector3d& reference) {
    Eigen::Vector3d projected = reference - reference.dot(axis) * axis;
    if (projected.norm() < 1e-3 * std::max(1.0, reference.norm())) {
        // The reference runs along the axis: any perpendicular is as good; take the most stable one.
        const Eigen::Vector3d other = std::abs(axis.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
        projected = other - other.dot(axis) * axis;
    }
    return projected.normalized();
}

TwoBoneSolution two_bone_ik(const Eigen::Vector3d& root, const Eigen::Vector3d& target, double upper_length,
                            double lower_length, double swivel, const Eigen::Vector3d& reference) {
    TwoBoneSolution solution;
    Eigen::Vector3d to_target = target - root;
    double distance = to_target.norm();
    const Eigen::Vector3d axis = distance > 1e-12 ? Eigen::Vector3d(to_target / distance) : orthogonal_reference(reference, reference);
    // Keep a hair inside the reachable shell so the elbow angle stays defined.
    const double longest = (upper_length + lower_length) * (1.0 - 1e-9);
    const double shortest = std::abs(upper_length - lower_length) * (1.0 + 1e-9) + 1e-12;
    const double clamped = std::clamp(distance, shortest, longest);
    solution.reachable = std::abs(clamped - distance) <= 1e-9 * (upper_length + lower_length) + 1e-12;
    distance = clamped;

    const double cos_root = std::clamp((upper_length * upper_length + distance * distance - lower_length * lower_length) /
                                           (2.0 * upper_length * distance), -1.0, 1.0);
    const double sin_root = std::sqrt(std::max(0.0, 1.0 - cos_root * cos_root));
    const Eigen::Vector3d zero_swivel = orthogonal_reference(axis, reference);
    const Eigen::Vector3d bend = std::cos(swivel) * zero_swivel + std::sin(swivel) * axis.cross(zero_swivel);
    solution.middle = root + upper_length * (cos_root * axis + sin_root * bend);
    solution.extremity = root + distance * axis;
    return solution;
}

} // namespace kumite
