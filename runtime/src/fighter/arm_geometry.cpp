#include "fighter/arm_geometry.h"

#include "kumite/core/contact_point.h"
#include "kumite/core/joint_limits.h"
#include "kumite/core/mir.h"
#include "kumite/core/two_bone_ik.h"

#include <Eigen/Geometry>

#include <algorithm>

namespace kumite {

double swivel_keeping_bend(const Eigen::Vector3d& root, const Eigen::Vector3d& wrist, const Eigen::Vector3d& bend, const Eigen::Vector3d& reference,
                           double fallback) {
    if ((wrist - root).norm() < 1e-6) return fallback;
    const Eigen::Vector3d axis = (wrist - root).normalized();
    const Eigen::Vector3d across = bend - bend.dot(axis) * axis;
    return across.norm() > 1e-3 ? limb_swivel(root, root + across, wrist, reference) : fallback;
}

Eigen::Vector3d contact_offset(const LimbChain& chain, const Eigen::Vector3d& root, const Eigen::Vector3d& wrist, const Eigen::Vector3d& bend,
                               const Eigen::Vector3d& reference, const Eigen::Vector3d& target) {
    Eigen::Vector3d offset = Eigen::Vector3d::Zero();
    for (int pass = 0; pass < 4; ++pass) {
        const Eigen::Vector3d asked = wrist + offset;
        const TwoBoneSolution solved = two_bone_ik(root, asked, chain.upper_length, chain.lower_length,
                                                   swivel_keeping_bend(root, asked, bend, reference, 0.0), reference);
        offset += target - (solved.extremity + k_block_contact_fraction * (solved.middle - solved.extremity));
    }
    return offset;
}

Eigen::Vector3d blend_about_root(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double weight) {
    const double from_length = from.norm(), to_length = to.norm();
    if (from_length < 1e-6 || to_length < 1e-6) return (1.0 - weight) * from + weight * to;
    const Eigen::Quaterniond turn = Eigen::Quaterniond::Identity().slerp(weight, Eigen::Quaterniond::FromTwoVectors(from, to));
    return (turn * from).normalized() * ((1.0 - weight) * from_length + weight * to_length);
}

bool limit_arm_step(const LimbChain& chain, const Eigen::Vector3d& reference, double swivel, const Eigen::Vector3d& last_wrist,
                    const Eigen::Vector3d& last_elbow, double max_step, Eigen::Vector3d& wrist, Eigen::Vector3d& bend) {
    const Eigen::Vector3d root = Eigen::Vector3d::Zero();
    auto solve = [&](const Eigen::Vector3d& at, const Eigen::Vector3d& bending) {
        return two_bone_ik(root, at, chain.upper_length, chain.lower_length, swivel_keeping_bend(root, at, bending, reference, swivel), reference);
    };
    const Eigen::Vector3d asked_elbow = solve(wrist, bend).middle;
    auto arm_at = [&](double share, Eigen::Vector3d& share_wrist, Eigen::Vector3d& share_bend) {
        share_wrist = blend_about_root(last_wrist, wrist, share);
        share_bend = limb_bend_direction(root, blend_about_root(last_elbow, asked_elbow, share), share_wrist, 0.0);
        if (share_bend.isZero()) share_bend = bend;
        const TwoBoneSolution solved = solve(share_wrist, share_bend);
        return std::max((solved.extremity - last_wrist).norm(), (solved.middle - last_elbow).norm());
    };
    Eigen::Vector3d share_wrist, share_bend;
    if (arm_at(1.0, share_wrist, share_bend) <= max_step) return false;
    double low = 0.0, high = 1.0;
    for (int pass = 0; pass < 10; ++pass) {
        const double middle = 0.5 * (low + high);
        (arm_at(middle, share_wrist, share_bend) <= max_step ? low : high) = middle;
    }
    arm_at(low, share_wrist, share_bend);
    wrist = share_wrist;
    bend = share_bend;
    return true;
}

} // namespace kumite
