#include "kumite/core/strike_adaptation.h"

#include "kumite/core/smoothstep.h"

#include <algorithm>
#include <cmath>

namespace kumite {
namespace {

int limb_of_segment(BodyPart segment) {
    switch (segment) {
    case BodyPart::clavicle_l: case BodyPart::upper_arm_l: case BodyPart::forearm_l: case BodyPart::hand_l: return int(Limb::arm_l);
    case BodyPart::clavicle_r: case BodyPart::upper_arm_r: case BodyPart::forearm_r: case BodyPart::hand_r: return int(Limb::arm_r);
    case BodyPart::thigh_l: case BodyPart::shin_l: case BodyPart::foot_l: case BodyPart::toe_l: return int(Limb::leg_l);
    default: return int(Limb::leg_r);
    }
}

double rotation_angle(const Eigen::Quaterniond& q) { return 2.0 * std::acos(std::min(1.0, std::abs(q.w()))); }

} // namespace

double constraint_ramp(double t, double t0, double tc, double recovery) {
    if (t >= tc) return recovery > 0.0 ? 1.0 - smoothstep((t - tc) / recovery) : (t == tc ? 1.0 : 0.0);
    if (t <= t0) return 0.0;
    return smoothstep((t - t0) / (tc - t0));
}

StrikeAdapter::StrikeAdapter(const CharacterRig& rig, const MotionDatabaseView& database, AdaptationSettings settings)
    : m_rig(rig), m_db(database), m_settings(settings), m_decoder(rig.skeleton(), rig.anatomy(), {}) {
    m_pivot_turns.fill(Eigen::Quaterniond::Identity());
}

void StrikeAdapter::load_clip_frame(int index, MirFrame& out) const {
    const DbClip& clip = m_db.clips[m_plan.clip];
    const int frame = std::clamp(m_plan.start_frame + index, 0, static_cast<int>(clip.frame_count) - 1);
    db_mir_frame_load(out, m_db.mir_frames[clip.first_pose + frame]);
    mir_frame_move_on_floor(out, m_plan.clip_to_world, m_rig.anatomy().leg_length);
}

void StrikeAdapter::frame_mir(double index, MirFrame& out) {
    const int whole = static_cast<int>(std::floor(index));
    const double fraction = index - whole;
    load_clip_frame(whole, m_clip_frame);
    if (fraction > 1e-9) {
        load_clip_frame(whole + 1, m_next_frame);
        mir_frame_blend(out, m_clip_frame, m_next_frame, fraction);
        m_clip_frame = out;
    }
    const double s = m_settings.blend_frames > 0 ? std::min(1.0, index / m_settings.blend_frames) : 1.0;
    out = m_clip_frame;
    if (s >= 1.0) return;
    if (m_settings.blend == BlendMode::ramp) {
        mir_frame_blend(out, m_current, m_clip_frame, smoothstep(s));
    } else {
        const double decay = 1.0 - s * s * s * (10.0 - 15.0 * s + 6.0 * s * s); // quintic: zero slope and curvature at the end
        mir_frame_add_offset(out, m_initial_offset, decay);
    }
}

void StrikeAdapter::begin(const StrikePlan& plan, const MirFrame& current, const std::array<bool, 2>& planted,
                          const std::array<Eigen::Vector3d, 2>& ankles_world) {
    m_plan = plan;
    const DbClip& clip = m_db.clips[plan.clip];
    m_frame_count = static_cast<int>(clip.frame_count) - plan.start_frame;
    m_current = current;
    db_mir_frame_load(m_clip_frame, m_db.mir_frames[clip.first_pose + plan.start_frame]);
    mir_frame_move_on_floor(m_clip_frame, plan.clip_to_world, m_rig.anatomy().leg_length);
    mir_frame_offset(m_initial_offset, current, m_clip_frame);
    m_limb = limb_of_segment(static_cast<BodyPart>(std::max(0, clip.segment)));
    m_arm = m_limb < 2;
    m_effector_joint = m_rig.anatomy().limbs[m_limb].extremity;
    const std::uint32_t start_flags = m_db.poses[clip.first_pose + plan.start_frame].flags;
    for (int foot = 0; foot < 2; ++foot) {
        const bool clip_planted = start_flags & (foot == 0 ? db_pose_left_foot_planted : db_pose_right_foot_planted);
        const bool kicking = !m_arm && m_limb == int(Limb::leg_l) + foot;
        m_support[foot] = planted[foot] && clip_planted && !kicking;
        m_support_pins[foot] = ankles_world[foot];
    }
    if (!m_arm && !m_support[0] && !m_support[1]) { // a kick keeps its other foot down, whatever the flags say
        const int other = m_limb == int(Limb::leg_l) ? 1 : 0;
        m_support[other] = true;
    }
    m_pins = LimbPins{};
    for (int foot = 0; foot < 2; ++foot) {
        m_pins.pinned[2 + foot] = m_support[foot];
        m_pins.extremity_world[2 + foot] = m_support_pins[foot];
    }
    m_pivot_count = 0;
    if (m_arm) {
        const BodyPart clavicle = m_limb == int(Limb::arm_l) ? BodyPart::clavicle_l : BodyPart::clavicle_r;
        if (m_rig.anatomy().body_map.has(clavicle)) m_pivots[m_pivot_count++] = m_limb == int(Limb::arm_l) ? TrunkPivot::clavicle_l : TrunkPivot::clavicle_r;
        m_pivots[m_pivot_count++] = TrunkPivot::chest;
        m_pivots[m_pivot_count++] = TrunkPivot::spine_base;
    } else {
        m_pivots[m_pivot_count++] = TrunkPivot::pelvis;
    }
    // d(tc): where the hit point would be at the contact frame, against the target.
    frame_mir(contact_index(), m_frame);
    LimbPins pins = m_pins;
    decode(m_scratch_pose, m_frame, pins);
    m_offset_at_contact = plan.target_world - m_decoder.limb_targets()[m_limb];
}

int StrikeAdapter::decode(Pose& out, const MirFrame& frame, LimbPins& pins) {
    pins.hip_shift_world.setZero();
    m_decoder.decode(out, frame, pins);
    Eigen::Vector3d shift = Eigen::Vector3d::Zero();
    const auto positions = m_decoder.model_positions();
    for (int foot = 0; foot < 2; ++foot) {
        if (!m_support[foot]) continue;
        const LimbChain& leg = m_rig.anatomy().limbs[2 + foot];
        const Eigen::Vector3d to_pin = m_support_pins[foot] - positions[leg.root];
        const double excess = to_pin.norm() - leg.length() * (1.0 - 1e-4);
        if (excess > 0.0 && excess > shift.norm()) shift = to_pin.normalized() * excess;
    }
    if (shift.isZero()) return 1;
    pins.hip_shift_world = shift;
    m_decoder.decode(out, frame, pins);
    return 2;
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

AdaptedFrame StrikeAdapter::step(double index, Pose& out) {
    AdaptedFrame result;
    result.contact = index == static_cast<double>(contact_index());
    frame_mir(index, m_frame);
    result.ramp = constraint_ramp(index, 0.0, contact_index(), m_settings.recovery_frames);
    LimbPins pins = m_pins;
    pins.extremity_offset_world[m_limb] = result.ramp * m_offset_at_contact;
    decode(out, m_frame, pins);
    result.wanted = m_decoder.limb_targets()[m_limb];
    result.effector = m_decoder.model_positions()[m_effector_joint];
    if ((result.effector - result.wanted).norm() <= m_settings.reach_tolerance_m) return result;

    // Out of the limb's reach: turn the trunk towards the target, pivot by pivot, within the joint limits.
    result.reach = Reach::torso;
    pins.pinned[m_limb] = true;
    pins.extremity_world[m_limb] = result.wanted;
    m_pivot_turns.fill(Eigen::Quaterniond::Identity());
    const RestAnatomy& anatomy = m_rig.anatomy();
    for (int sweep = 0; sweep < m_settings.ccd_iterations; ++sweep) {
        for (int p = 0; p < m_pivot_count; ++p) {
            const TrunkPivot pivot = m_pivots[p];
            // Out of reach the limb points straight at the target from its root, so what the trunk must do is
            // bring the root closer: turn the pivot so that the root swings towards the target.
            const Eigen::Vector3d centre = pivot_point(pivot);
            const Eigen::Vector3d root = m_decoder.model_positions()[anatomy.limbs[m_limb].root];
            const Eigen::Vector3d from = root - centre, to = result.wanted - centre;
            if (from.norm() < 1e-6 || to.norm() < 1e-6) continue;
            Eigen::Quaterniond total = Eigen::Quaterniond::FromTwoVectors(from, to) * m_pivot_turns[p];
            const double angle = rotation_angle(total), limit = pivot_limit(pivot);
            if (angle > limit) total = Eigen::Quaterniond::Identity().slerp(limit / angle, total);
            const Eigen::Quaterniond turn = total * m_pivot_turns[p].conjugate();
            m_pivot_turns[p] = total;
            result.pivot_turn_rad[p] = rotation_angle(total);
            mir_frame_turn(m_frame, pivot, turn, centre, anatomy.leg_length, anatomy.ankle_height);
            result.ccd_decodes += decode(out, m_frame, pins);
            result.effector = m_decoder.model_positions()[m_effector_joint];
            if ((result.effector - result.wanted).norm() <= m_settings.reach_tolerance_m) return result;
        }
    }
    result.reach = Reach::unreachable;
    return result;
}

} // namespace kumite
