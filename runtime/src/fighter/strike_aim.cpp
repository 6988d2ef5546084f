#include "fighter/strike_aim.h"

#include <algorithm>
#include <cmath>

namespace kumite {
namespace {

constexpr double k_target_drops_m[k_target_part_count] = {0.0, 0.10, 0.30, 0.45}; // under a 1.65 m head

} // namespace

double drop_under_head_m(int part, const Eigen::Vector3d& head) { return k_target_drops_m[part] * std::clamp(head.y() / 1.65, 0.5, 1.4); }

Eigen::Vector3d aim_offset(int part, const Eigen::Vector3d& head, const Eigen::Vector3d& fighter, double surface_depth_m) {
    Eigen::Vector3d towards = fighter - head;
    towards.y() = 0.0;
    const Eigen::Vector3d surface = towards.norm() > 1e-6 ? Eigen::Vector3d(surface_depth_m * towards.normalized()) : Eigen::Vector3d::Zero();
    return surface - Eigen::Vector3d(0.0, drop_under_head_m(part, head), 0.0);
}

double strike_reach_m(const CharacterBody& body, const Eigen::Vector3d& head, bool fallback) {
    const RestAnatomy& anatomy = body.anatomy();
    const auto positions = body.current().decoder.model_positions();
    // At the head's height, else (reach fallback) at the highest body point under it the arms get to.
    for (int part = 0; part < (fallback ? k_target_part_count : 1); ++part) {
        const double height = head.y() - drop_under_head_m(part, head);
        double reach = 0.0;
        for (const Limb arm : {Limb::arm_l, Limb::arm_r}) {
            const LimbChain& limb = anatomy.limbs[int(arm)];
            const Eigen::Vector3d shoulder = body.heading().to_heading(positions[limb.root]);
            const double span = 0.9 * limb.length(), rise = height - positions[limb.root].y();
            if (std::abs(rise) < span) reach = std::max(reach, shoulder.z() + std::sqrt(span * span - rise * rise));
        }
        if (reach > 0.0) return reach + 0.1 * anatomy.leg_length;
    }
    return 0.0;
}

} // namespace kumite
