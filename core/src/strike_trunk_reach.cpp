// Step 4 of the strike's adaptation (strike_adaptation.h): when the limb alone falls short, the trunk's pivots
// turn towards the target by Cyclic Coordinate Descent, each within its joint limit and the trunk's; and the
// trunk's lean into the strike, found at the contact and shared out along the offset ramp.
#include "kumite/core/strike_adaptation.h"

#include <algorithm>
#include <cmath>

namespace kumite {

int StrikeAdapter::lean(double share, Pose& out, LimbPins& pins) {
    m_lean_now.fill(Eigen::Quaterniond::Identity());
    if (!m_leans || share <= 0.0) return 0;
    const RestAnatomy& anatomy = m_rig.anatomy();
    for (int p = 0; p < m_pivot_count; ++p) { // about the pivots as decoded (the pelvis's: the support hip)
        m_lean_now[p] = Eigen::Quaterniond::Identity().slerp(std::min(share, 1.0), m_contact_lean[p]);
        // The clip's own trunk turns on (a hook's follow-through): the lean keeps it within the trunk's limit.
        if (m_pivots[p] == TrunkPivot::chest || m_pivots[p] == TrunkPivot::spine_base) m_lean_now[p] = within_trunk_limit(m_lean_now[p]);
        mir_frame_turn(m_frame, m_pivots[p], m_lean_now[p], pivot_point(m_pivots[p]), anatomy.leg_length, anatomy.ankle_height);
    }
    return decode(out, m_frame, pins);
}

double StrikeAdapter::limb_reach() const {
    const double length = m_rig.anatomy().limbs[m_limb].length();
    return std::min(length, std::max(m_settings.limb_reach_share * length, clip_reach(m_limb).norm()));
}

bool StrikeAdapter::beyond_limb_reach(const Eigen::Vector3d& wanted) const {
    if (m_middle) return false;
    const Eigen::Vector3d& root = m_decoder.model_positions()[m_rig.anatomy().limbs[m_limb].root];
    return (wanted - root).norm() > limb_reach() + m_settings.reach_tolerance_m;
}

Eigen::Quaterniond StrikeAdapter::within_trunk_limit(const Eigen::Quaterniond& turn) const {
    // The chest turns with `turn`, the pelvis stays: keep the largest part of the turn that leaves the chest within
    // the trunk's limit from the pelvis (bisection; none of it when the clip's own trunk is already beyond).
    const Eigen::Quaterniond& pelvis = m_frame.part_frames[int(BodyPart::pelvis)];
    const Eigen::Quaterniond& chest = m_frame.part_frames[int(BodyPart::chest)];
    const double limit = m_settings.limits.trunk_turn_rad;
    if (pelvis.angularDistance(turn * chest) <= limit) return turn;
    double inside = 0.0, outside = 1.0;
    for (int iteration = 0; iteration < 10; ++iteration) {
        const double middle = 0.5 * (inside + outside);
        (pelvis.angularDistance(Eigen::Quaterniond::Identity().slerp(middle, turn) * chest) <= limit ? inside : outside) = middle;
    }
    return Eigen::Quaterniond::Identity().slerp(inside, turn);
}

Eigen::Vector3d StrikeAdapter::pivot_point(TrunkPivot pivot) const {
    const RestAnatomy& anatomy = m_rig.anatomy();
    const auto positions = m_decoder.model_positions();
    switch (pivot) {
    case TrunkPivot::clavicle_l: return positions[anatomy.body_map.joint(BodyPart::clavicle_l)];
    case TrunkPivot::clavicle_r: return positions[anatomy.body_map.joint(BodyPart::clavicle_r)];
    case TrunkPivot::chest: return positions[anatomy.body_map.joint(BodyPart::chest)];
    case TrunkPivot::spine_base: return positions[anatomy.spine.count > 1 ? anatomy.spine.joints[1] : anatomy.body_map.joint(BodyPart::chest)];
    case TrunkPivot::pelvis: {
        const int support_leg = m_support[0] ? int(Limb::leg_l) : int(Limb::leg_r);
        return positions[anatomy.limbs[support_leg].root];
    }
    }
    return Eigen::Vector3d::Zero();
}

double StrikeAdapter::pivot_limit(TrunkPivot pivot) const {
    switch (pivot) {
    case TrunkPivot::clavicle_l:
    case TrunkPivot::clavicle_r: return m_settings.clavicle_limit_rad;
    case TrunkPivot::chest: return m_settings.chest_limit_rad;
    case TrunkPivot::spine_base: return m_settings.spine_base_limit_rad;
    case TrunkPivot::pelvis: return m_settings.pelvis_limit_rad;
    }
    return 0.0;
}

namespace {

double rotation_angle(const Eigen::Quaterniond& q) { return 2.0 * std::acos(std::min(1.0, std::abs(q.w()))); }

// The turn about the pivot, in the plane of `from` and `to` (the limb's root and the target, from the pivot), that
// brings the root just within `reach` of the target: the least of FromTwoVectors(from, to) that does (none when it
// already is). It stops sooner where the turn stops paying: where the root, swinging about the pivot, comes
// nearer the target at less than half the speed it swings at (a pelvis turned about the support hip towards a
// target along the hips' line would swing the whole body for a centimetre; full alignment there turned it to its
// limit in a frame). The turn is a continuous function of the target either way.
Eigen::Quaterniond turn_within_reach(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double reach) {
    const double f = from.norm(), t = to.norm();
    if ((from - to).norm() <= reach) return Eigen::Quaterniond::Identity();
    const double angle = std::acos(std::clamp(from.dot(to) / (f * t), -1.0, 1.0));
    if (angle < 1e-9) return Eigen::Quaterniond::Identity();
    // With `left` of the angle still to turn: the root's distance to the target, and how fast it falls per radian.
    auto distance = [&](double left) { return std::sqrt(std::max(0.0, f * f + t * t - 2.0 * f * t * std::cos(left))); };
    auto pays = [&](double left) { return t * std::sin(left) >= 0.5 * distance(left); };
    // Least turn into reach (all of it when even that does not reach).
    const double c = (f * f + t * t - reach * reach) / (2.0 * f * t);
    double left = c >= 1.0 ? 0.0 : std::acos(c);
    if (!pays(left)) { // past the point where it stops paying: turn as far as that point (bisection)
        double paying = angle, idle = left;
        if (!pays(paying)) return Eigen::Quaterniond::Identity();
        for (int iteration = 0; iteration < 30; ++iteration) {
            const double middle = 0.5 * (paying + idle);
            (pays(middle) ? paying : idle) = middle;
        }
        left = paying;
    }
    const double phi = std::clamp(angle - left, 0.0, angle);
    return Eigen::Quaterniond::Identity().slerp(phi / angle, Eigen::Quaterniond::FromTwoVectors(from, to));
}

} // namespace

void StrikeAdapter::reach_with_trunk(AdaptedFrame& result, LimbPins& pins, Pose& out) {
    // Out of the limb's reach (or of what it carries, limb_reach): turn the trunk towards the target, pivot by
    // pivot, each no further than brings the limb's root within that reach, within the joint limits.
    result.reach = Reach::torso;
    if (!m_middle) {
        pins.pinned[m_limb] = true;
        pins.extremity_world[m_limb] = result.wanted;
    }
    const RestAnatomy& anatomy = m_rig.anatomy();
    const double middle_reach = anatomy.limbs[m_limb].upper_length;
    const double tolerance = m_settings.reach_tolerance_m;
    auto root_position = [&]() -> Eigen::Vector3d { return m_decoder.model_positions()[anatomy.limbs[m_limb].root]; };
    // Done: the hit point on the target, and (an extremity strike) the root within the limb's carried reach.
    auto reached = [&]() {
        return (result.effector - result.wanted).norm() <= tolerance && (m_middle || (root_position() - result.wanted).norm() <= limb_reach() + tolerance);
    };
    m_pivot_turns = m_lean_now; // from the lean already made: the limits hold for the whole turn
    auto gap_now = [&]() { return m_middle ? (result.effector - result.wanted).norm() : (root_position() - result.wanted).norm(); };
    double gap = gap_now();
    for (int sweep = 0; sweep < m_settings.ccd_iterations; ++sweep) {
        bool turned = false;
        for (int p = 0; p < m_pivot_count; ++p) {
            const TrunkPivot pivot = m_pivots[p];
            const Eigen::Vector3d centre = pivot_point(pivot);
            const Eigen::Vector3d root = root_position();
            Eigen::Quaterniond step;
            if (m_middle) {
                // A knee or elbow is always the upper bone's length from the root: the root goes to that distance
                // from the target, nearer or farther.
                const Eigen::Vector3d aim = (root - result.wanted).norm() > 1e-9
                                                ? Eigen::Vector3d(result.wanted + middle_reach * (root - result.wanted).normalized())
                                                : result.wanted;
                const Eigen::Vector3d from = root - centre, to = aim - centre;
                if (from.norm() < 1e-6 || to.norm() < 1e-6) continue;
                step = Eigen::Quaterniond::FromTwoVectors(from, to);
            } else {
                const Eigen::Vector3d from = root - centre, to = result.wanted - centre;
                if (from.norm() < 1e-6 || to.norm() < 1e-6) continue;
                step = turn_within_reach(from, to, limb_reach());
            }
            Eigen::Quaterniond total = step * m_pivot_turns[p];
            const double angle = rotation_angle(total), limit = pivot_limit(pivot);
            if (angle > limit) total = Eigen::Quaterniond::Identity().slerp(limit / angle, total);
            Eigen::Quaterniond turn = total * m_pivot_turns[p].conjugate();
            if (pivot == TrunkPivot::chest || pivot == TrunkPivot::spine_base) {
                turn = within_trunk_limit(turn);
                total = turn * m_pivot_turns[p];
            }
            m_pivot_turns[p] = total;
            result.pivot_turn_rad[p] = rotation_angle(total);
            if (rotation_angle(turn) < 1e-5) continue; // held at its limit: the pose is unchanged, no decode
            turned = true;
            mir_frame_turn(m_frame, pivot, turn, centre, anatomy.leg_length, anatomy.ankle_height);
            result.ccd_decodes += decode_striking(out, pins, result.wanted);
            result.effector = m_decoder.model_positions()[m_effector_joint];
            if (reached()) return;
        }
        // Every pivot at its limit, or a sweep that gained less than a millimetre (the limits bind): further
        // sweeps would change next to nothing.
        const double now = gap_now();
        if (!turned || gap - now < 1e-3) break;
        gap = now;
    }
    if ((result.effector - result.wanted).norm() > tolerance) result.reach = Reach::unreachable;
}

} // namespace kumite
