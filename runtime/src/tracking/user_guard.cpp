// The user's guard (user_guard.h): the elbow estimate, and the first part a moving sphere meets.

#include "kumite/runtime/user_guard.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace kumite {
namespace {

// A person's proportions from the tracked head (the skull's centre): the shoulder joint under and beside it, the
// upper arm, and the elbow to the fist's centre (forearm and half a fist).
constexpr double k_shoulder_below_head_m = 0.24;
constexpr double k_shoulder_beside_head_m = 0.18;
constexpr double k_upper_arm_m = 0.29;
constexpr double k_elbow_to_fist_m = 0.33;
constexpr double k_chest_below_head_m = 0.30;  // the trunk's capsule, from the chest down to the belly
constexpr double k_pelvis_below_head_m = 0.70;

// The first share of the path from `from` along `path` where a point comes within `reach` of `centre` (2 if never).
double first_within_sphere(const Eigen::Vector3d& from, const Eigen::Vector3d& path, const Eigen::Vector3d& centre, double reach) {
    const Eigen::Vector3d offset = from - centre;
    const double c = offset.squaredNorm() - reach * reach;
    if (c <= 0.0) return 0.0;
    const double a = path.squaredNorm();
    if (a < 1e-18) return 2.0;
    const double b = 2.0 * offset.dot(path);
    const double discriminant = b * b - 4.0 * a * c;
    if (discriminant < 0.0) return 2.0;
    const double share = (-b - std::sqrt(discriminant)) / (2.0 * a);
    return share >= 0.0 && share <= 1.0 ? share : 2.0;
}

double distance_to_segment(const Eigen::Vector3d& point, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return (point - nearest_on_segment(point, a, b)).norm();
}

// ... within `reach` of the segment a-b: sampled, then the first crossing bisected (to 1/4096 of the path).
double first_within_capsule(const Eigen::Vector3d& from, const Eigen::Vector3d& path, const Eigen::Vector3d& a, const Eigen::Vector3d& b, double reach) {
    constexpr int k_samples = 16;
    if (distance_to_segment(from, a, b) <= reach) return 0.0;
    double outside = 0.0;
    for (int i = 1; i <= k_samples; ++i) {
        const double share = double(i) / k_samples;
        if (distance_to_segment(from + share * path, a, b) > reach) {
            outside = share;
            continue;
        }
        double inside = share;
        for (int step = 0; step < 8; ++step) {
            const double middle = 0.5 * (outside + inside);
            (distance_to_segment(from + middle * path, a, b) <= reach ? inside : outside) = middle;
        }
        return inside;
    }
    return 2.0;
}

} // namespace

Eigen::Vector3d nearest_on_segment(const Eigen::Vector3d& point, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    const Eigen::Vector3d ab = b - a;
    const double length2 = ab.squaredNorm();
    const double u = length2 > 1e-18 ? std::clamp((point - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
    return a + u * ab;
}

const char* guard_part_name(GuardPart part) {
    switch (part) {
    case GuardPart::none: return "none";
    case GuardPart::head: return "head";
    case GuardPart::trunk: return "trunk";
    case GuardPart::glove_l: return "glove_left";
    case GuardPart::glove_r: return "glove_right";
    case GuardPart::forearm_l: return "forearm_left";
    case GuardPart::forearm_r: return "forearm_right";
    }
    return "none";
}

Eigen::Vector3d user_right(const Eigen::Vector3d& facing, const UserHands& hands) {
    const Eigen::Vector3d from_facing = facing.cross(Eigen::Vector3d::UnitY()).normalized(); // facing +Z: -X
    if (!hands.present[0] || !hands.present[1]) return from_facing;
    Eigen::Vector3d across = hands.world[1] - hands.world[0];
    across.y() = 0.0;
    if (across.norm() < 0.05 || !across.allFinite()) return from_facing;
    across.normalize();
    return across.dot(from_facing) >= 0.5 ? across : from_facing;
}

Eigen::Vector3d estimate_elbow(const Eigen::Vector3d& head, const Eigen::Vector3d& hand, const Eigen::Vector3d& right, int side) {
    const Eigen::Vector3d up = Eigen::Vector3d::UnitY();
    const double outwards = side == 1 ? 1.0 : -1.0;
    const Eigen::Vector3d shoulder = head - k_shoulder_below_head_m * up + outwards * k_shoulder_beside_head_m * right;
    Eigen::Vector3d reach = hand - shoulder;
    const double length = reach.norm();
    if (length < 1e-6) return shoulder - k_upper_arm_m * up;
    const Eigen::Vector3d along = reach / length;
    // The elbow's bulge: down and out, across the shoulder-to-hand line.
    Eigen::Vector3d bulge = -up + 0.5 * outwards * right;
    bulge -= bulge.dot(along) * along;
    if (bulge.norm() < 1e-6) bulge = outwards * right - (outwards * right).dot(along) * along;
    bulge.normalize();
    const double d = std::min(length, k_upper_arm_m + k_elbow_to_fist_m - 1e-6);
    // Law of cosines: how far along the line the elbow is, and how far off it.
    const double a = (k_upper_arm_m * k_upper_arm_m - k_elbow_to_fist_m * k_elbow_to_fist_m + d * d) / (2.0 * d);
    const double h = std::sqrt(std::max(0.0, k_upper_arm_m * k_upper_arm_m - a * a));
    return shoulder + a * along + h * bulge;
}

void UserGuard::update(const Eigen::Vector3d& head, const UserHands& hands, const Eigen::Vector3d& facing, const std::array<Eigen::Vector3d, 2>* elbows) {
    const Eigen::Vector3d up = Eigen::Vector3d::UnitY();
    const Eigen::Vector3d right = user_right(facing, hands);
    m_head = head;
    m_chest = head - k_chest_below_head_m * up;
    m_pelvis = head - k_pelvis_below_head_m * up;
    for (int side = 0; side < 2; ++side) {
        m_hand[side] = hands.present[side] && hands.world[side].allFinite();
        if (!m_hand[side]) continue;
        m_glove[side] = hands.world[side];
        m_elbow[side] = elbows ? (*elbows)[side] : estimate_elbow(head, m_glove[side], right, side);
        const Eigen::Vector3d back = m_elbow[side] - m_glove[side];
        m_wrist[side] = back.norm() > k_fist_centre_past_wrist_m ? Eigen::Vector3d(m_glove[side] + k_fist_centre_past_wrist_m * back.normalized()) : m_glove[side];
    }
}

Eigen::Vector3d UserGuard::part_centre(GuardPart part) const {
    switch (part) {
    case GuardPart::head: return m_head;
    case GuardPart::trunk: return m_chest;
    case GuardPart::glove_l: return m_glove[0];
    case GuardPart::glove_r: return m_glove[1];
    case GuardPart::forearm_l: return 0.5 * (m_wrist[0] + m_elbow[0]);
    case GuardPart::forearm_r: return 0.5 * (m_wrist[1] + m_elbow[1]);
    case GuardPart::none: break;
    }
    return m_head;
}

Eigen::Vector3d UserGuard::nearest_core(GuardPart part, const Eigen::Vector3d& point) const {
    switch (part) {
    case GuardPart::trunk: return nearest_on_segment(point, m_chest, m_pelvis);
    case GuardPart::forearm_l: return nearest_on_segment(point, m_wrist[0], m_elbow[0]);
    case GuardPart::forearm_r: return nearest_on_segment(point, m_wrist[1], m_elbow[1]);
    default: return part_centre(part);
    }
}

double UserGuard::radius(GuardPart part) const {
    switch (part) {
    case GuardPart::head: return m_settings.head_radius_m;
    case GuardPart::trunk: return m_settings.trunk_radius_m;
    case GuardPart::glove_l:
    case GuardPart::glove_r: return m_settings.glove_radius_m;
    case GuardPart::forearm_l:
    case GuardPart::forearm_r: return m_settings.forearm_radius_m;
    case GuardPart::none: break;
    }
    return 0.0;
}

GuardContact UserGuard::first_contact(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double radius) const {
    const Eigen::Vector3d path = to - from;
    GuardContact first;
    double best = 2.0;
    const auto consider = [&](GuardPart part, double share) {
        if (share < best) {
            best = share;
            first.part = part;
        }
    };
    consider(GuardPart::head, first_within_sphere(from, path, m_head, m_settings.head_radius_m + radius));
    consider(GuardPart::trunk, first_within_capsule(from, path, m_chest, m_pelvis, m_settings.trunk_radius_m + radius));
    for (int side = 0; side < 2; ++side) {
        if (!m_hand[side]) continue;
        const GuardPart glove = side == 0 ? GuardPart::glove_l : GuardPart::glove_r;
        const GuardPart forearm = side == 0 ? GuardPart::forearm_l : GuardPart::forearm_r;
        consider(glove, first_within_sphere(from, path, m_glove[side], m_settings.glove_radius_m + radius));
        consider(forearm, first_within_capsule(from, path, m_wrist[side], m_elbow[side], m_settings.forearm_radius_m + radius));
    }
    if (first.part == GuardPart::none) return first;
    first.share = best;
    first.sphere_at_touch = from + best * path;
    return first;
}

} // namespace kumite
