#include "kumite/core/strike_adaptation.h"

#include "kumite/core/halfspace_projection.h"
#include "kumite/core/smoothstep.h"
#include "kumite/core/two_bone_ik.h"

#include <algorithm>
#include <cmath>

namespace kumite {
namespace {

double rotation_angle(const Eigen::Quaterniond& q) { return 2.0 * std::acos(std::min(1.0, std::abs(q.w()))); }

} // namespace

int limb_of_segment(BodyPart segment) {
    switch (segment) {
    case BodyPart::clavicle_l: case BodyPart::upper_arm_l: case BodyPart::forearm_l: case BodyPart::hand_l: return int(Limb::arm_l);
    case BodyPart::clavicle_r: case BodyPart::upper_arm_r: case BodyPart::forearm_r: case BodyPart::hand_r: return int(Limb::arm_r);
    case BodyPart::thigh_l: case BodyPart::shin_l: case BodyPart::foot_l: case BodyPart::toe_l: return int(Limb::leg_l);
    default: return int(Limb::leg_r);
    }
}

bool segment_strikes_with_middle(BodyPart segment) {
    return segment == BodyPart::forearm_l || segment == BodyPart::forearm_r || segment == BodyPart::shin_l || segment == BodyPart::shin_r;
}

double constraint_ramp(double t, double t0, double tc, double recovery) {
    if (t >= tc) return recovery > 0.0 ? 1.0 - smoothstep((t - tc) / recovery) : (t == tc ? 1.0 : 0.0);
    if (t <= t0) return 0.0;
    return smoothstep((t - t0) / (tc - t0));
}

StrikeAdapter::StrikeAdapter(const CharacterRig& rig, const MotionDatabaseView& database, AdaptationSettings settings)
    : m_rig(rig), m_db(database), m_settings(settings), m_decoder(rig.skeleton(), rig.anatomy(), {}) {
    m_pivot_turns.fill(Eigen::Quaterniond::Identity());
    m_contact_lean.fill(Eigen::Quaterniond::Identity());
    m_lean_now.fill(Eigen::Quaterniond::Identity());
    std::size_t longest = 1;
    for (const DbClip& clip : database.clips) longest = std::max<std::size_t>(longest, clip.frame_count);
    m_progress.assign(longest, 0.0);
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
    m_middle = clip.segment >= 0 && segment_strikes_with_middle(static_cast<BodyPart>(clip.segment));
    m_effector_joint = m_middle ? m_rig.anatomy().limbs[m_limb].middle : m_rig.anatomy().limbs[m_limb].extremity;
    // The clip's progress towards its hit, from its hit points (clip space: only ratios of distances are used).
    {
        auto hit_point = [&](int index) {
            const float* p = m_db.poses[clip.first_pose + std::clamp(plan.start_frame + index, 0, int(clip.frame_count) - 1)].hit_point;
            return Eigen::Vector3d(p[0], p[1], p[2]);
        };
        // The share of the hit point's path from the start to the contact covered by each frame: 0 at the start, 1
        // at the contact, rising as fast as the clip's own hit point moves. (Its distance to the contact point, as a
        // share of the farthest it was, is not 0 at a start after which the fist first draws back: the ramp jumped
        // there, the offset added in one frame.) A hit point that never moves: the share of the time.
        const int contact = std::clamp(contact_index(), 0, int(m_progress.size()) - 1);
        double path = 0.0;
        m_progress[0] = 0.0;
        for (int i = 1; i <= contact; ++i) {
            path += (hit_point(i) - hit_point(i - 1)).norm();
            m_progress[i] = path;
        }
        for (int i = 1; i <= contact; ++i) m_progress[i] = path > 1e-9 ? m_progress[i] / path : double(i) / contact;
    }
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
    m_impact = true;
    const AdaptedFrame at_contact = plan_contact();
    // The approach: the ways the effector itself travels into the stop point over the last 1 to 4 frames before
    // the contact (chords of its path that move at least a centimetre; when it arrives at rest, the outward
    // direction alone). A sweeping kick or a hook turns in its last frames: stopped along its final direction
    // alone, it would carry on along the way it came from, across and into the target.
    const Eigen::Vector3d from_root = m_stop_point - m_decoder.model_positions()[m_rig.anatomy().limbs[m_limb].root];
    m_approach_count = 0;
    for (int back = 1; back <= k_approach_chords && contact_index() - back >= 0; ++back) {
        const Eigen::Vector3d arriving = at_contact.effector - step(contact_index() - back, m_scratch_pose).effector;
        if (arriving.norm() > 0.01) m_approaches[m_approach_count++] = arriving.normalized();
    }
    // And outwards from the limb's root: after the contact the fist or foot does not reach further out than the
    // target either (a clip whose hit comes before its full extension would otherwise punch on into the air).
    if (from_root.norm() > 1e-6) m_approaches[m_approach_count++] = from_root.normalized();
    m_approach = m_approaches[0];
}

AdaptedFrame StrikeAdapter::plan_contact() {
    // d(tc): where the hit point would be at the contact frame, against the target; and the trunk's lean there
    // (the CCD's, when the limb alone falls short), with d(tc) then measured from the leaned hit point. Where the
    // strike stops: the target, or out of reach the closest point the effector gets to at the contact.
    const bool impact = m_impact;
    m_impact = true;
    m_leans = false;
    m_contact_lean.fill(Eigen::Quaterniond::Identity());
    measure_contact_offset();
    AdaptedFrame at_contact = step(contact_index(), m_scratch_pose);
    if (at_contact.reach != Reach::limb && !m_middle) { // a knee or elbow: its CCD turns whole, no lean ahead
        m_contact_lean = m_pivot_turns;
        m_leans = true;
        measure_contact_offset();
        at_contact = step(contact_index(), m_scratch_pose);
    }
    m_stop_point = at_contact.reach == Reach::unreachable ? at_contact.effector : m_plan.target_world;
    m_impact = impact;
    return at_contact;
}

void StrikeAdapter::retarget(const Eigen::Vector3d& target_world) {
    m_plan.target_world = target_world;
    plan_contact();
}

double StrikeAdapter::past_stop(const Eigen::Vector3d& point) const {
    // Through the target only: within target_radius_m of the approach line. A kick whose last chords turn back
    // towards the kicker (a roundhouse's sweep) drops its foot to the floor beyond the stop point along them, but a
    // metre under the head, not through it.
    double past = 0.0;
    const Eigen::Vector3d displacement = point - m_stop_point;
    for (int k = 0; k < m_approach_count; ++k) {
        const double along = displacement.dot(m_approaches[k]);
        if ((displacement - along * m_approaches[k]).norm() <= m_settings.target_radius_m) past = std::max(past, along);
    }
    return past;
}

double StrikeAdapter::offset_ramp(double index) const {
    const int contact = contact_index();
    if (m_settings.offset_ramp == OffsetRamp::time || index >= contact || contact >= int(m_progress.size())) {
        return constraint_ramp(index, 0.0, contact, m_settings.recovery_frames);
    }
    if (index <= 0.0) return 0.0;
    const int whole = static_cast<int>(std::floor(index));
    const double fraction = index - whole;
    const double progress = m_progress[whole] + fraction * (m_progress[std::min(whole + 1, contact)] - m_progress[whole]);
    return smoothstep(progress);
}

Eigen::Vector3d StrikeAdapter::impact_correction(const Eigen::Vector3d& point, double index) const {
    if (!m_impact || index <= contact_index()) return Eigen::Vector3d::Zero();
    // Past the stop point along approach direction k by g_k: the least move of the hit point that brings each g_k
    // down to softness * (1 - exp(-g_k / softness)) (C1 at g_k = 0, below the softness), and keeps the others
    // within the softness. What goes back or aside from every approach direction (the retraction) is kept.
    const double softness = m_settings.overshoot_softness_m;
    if (softness <= 0.0) return Eigen::Vector3d::Zero();
    const Eigen::Vector3d displacement = point - m_stop_point;
    std::array<double, k_approach_chords + 1> bounds{};
    bool past = false;
    for (int k = 0; k < m_approach_count; ++k) {
        const double along = displacement.dot(m_approaches[k]);
        bounds[k] = along > 0.0 ? softness * (1.0 - std::exp(-along / softness)) : softness;
        past = past || along > 0.0;
    }
    if (!past) return Eigen::Vector3d::Zero();
    const Eigen::Vector3d held = nearest_within_halfspaces(displacement, {m_approaches.data(), std::size_t(m_approach_count)},
                                                           {bounds.data(), std::size_t(m_approach_count)}, Eigen::Vector3d::Zero());
    return held - displacement;
}

bool StrikeAdapter::stop_at_target(LimbPins& pins, double index) const {
    const Eigen::Vector3d correction = impact_correction(m_decoder.limb_targets()[m_limb], index);
    if (correction.isZero()) return false;
    pins.extremity_offset_world[m_limb] += correction;
    return true;
}

int StrikeAdapter::place_middle(Pose& out, LimbPins& pins, const Eigen::Vector3d& wanted) {
    // The clip's own limb at the current root: extremity from the frame, middle from the clip's swivel.
    const LimbChain& chain = m_rig.anatomy().limbs[m_limb];
    const Eigen::Vector3d root = m_decoder.model_positions()[chain.root];
    const Eigen::Vector3d own_extremity = root + clip_reach(m_limb);
    const Eigen::Vector3d reference = limb_swivel_reference(m_frame, m_limb);
    const TwoBoneSolution own = two_bone_ik(root, own_extremity, chain.upper_length, chain.lower_length, m_clip_swivels[m_limb], reference);
    // The middle joint as near `wanted` as the upper bone allows; the limb turned rigidly about its root to put it
    // there, and the swivel that puts the middle joint on that point for the turned extremity.
    const Eigen::Vector3d to_wanted = wanted - root, to_own = own.middle - root;
    if (to_wanted.norm() < 1e-9 || to_own.norm() < 1e-9) return decode(out, m_frame, pins);
    const Eigen::Vector3d middle = root + chain.upper_length * to_wanted.normalized();
    const Eigen::Quaterniond turn = Eigen::Quaterniond::FromTwoVectors(to_own, middle - root);
    const Eigen::Vector3d extremity = root + turn * (own.extremity - root);
    pins.pinned[m_limb] = true;
    pins.extremity_world[m_limb] = extremity;
    m_frame.swivel[m_limb] = limb_swivel(root, middle, extremity, reference);
    return decode(out, m_frame, pins);
}

int StrikeAdapter::decode_striking(Pose& out, LimbPins& pins, const Eigen::Vector3d& wanted) {
    const int decodes = decode(out, m_frame, pins);
    return m_middle ? decodes + place_middle(out, pins, wanted) : decodes;
}

AdaptedFrame StrikeAdapter::step_middle(double index, Pose& out, AdaptedFrame result, LimbPins& pins) {
    // Where the clip's own middle joint is (the limb as the clip holds it), plus the ramped offset, held at the
    // target after the contact.
    const int middle_joint = m_effector_joint;
    result.ccd_decodes = decode(out, m_frame, pins);
    result.ccd_decodes += lean(result.ramp, out, pins);
    Eigen::Vector3d wanted = m_decoder.model_positions()[middle_joint] + result.ramp * m_offset_at_contact;
    wanted += impact_correction(wanted, index);
    result.wanted = wanted;
    result.ccd_decodes += place_middle(out, pins, wanted);
    result.effector = m_decoder.model_positions()[middle_joint];
    if ((result.effector - result.wanted).norm() > m_settings.reach_tolerance_m) reach_with_trunk(result, pins, out);
    if (index > contact_index()) result.past_target_m = past_stop(result.effector);
    result.joint_violations = violations();
    return result;
}

bool StrikeAdapter::keep_clip_bends(const LimbPins& pins) {
    if (!m_settings.keep_clip_bends) return false;
    bool changed = false;
    const RestAnatomy& anatomy = m_rig.anatomy();
    const auto positions = m_decoder.model_positions();
    for (int limb = 0; limb < k_limb_count; ++limb) {
        if (m_middle && limb == m_limb) continue; // place_middle gives it the clip's bend, turned
        const LimbChain& chain = anatomy.limbs[limb];
        const Eigen::Vector3d& root = positions[chain.root];
        const Eigen::Vector3d own = root + clip_reach(limb);
        Eigen::Vector3d asked = pins.pinned[limb] ? pins.extremity_world[limb] : Eigen::Vector3d(own + pins.extremity_offset_world[limb]);
        if ((asked - own).norm() < 1e-3 || (asked - root).norm() < 1e-6) continue;
        // The clip's bend carried to the new line: its component across that line, when it keeps one.
        Eigen::Vector3d bend = clip_bend(limb);
        const Eigen::Vector3d axis = (asked - root).normalized();
        bend -= bend.dot(axis) * axis;
        if (bend.norm() < 1e-3) continue; // the new line runs along the old bend: any swivel is as far from it
        const double swivel = limb_swivel(root, root + bend, asked, limb_swivel_reference(m_frame, limb));
        if (std::abs(std::remainder(swivel - m_frame.swivel[limb], 2.0 * 3.14159265358979)) > 1e-4) {
            m_frame.swivel[limb] = swivel;
            changed = true;
        }
    }
    return changed;
}

Eigen::Vector3d StrikeAdapter::clip_reach(int limb) const {
    const LimbChain& chain = m_rig.anatomy().limbs[limb];
    return m_frame.part_frames[chain.parent_part] * m_frame.extremity[limb] * chain.length();
}

Eigen::Vector3d StrikeAdapter::clip_bend(int limb) const {
    const LimbChain& chain = m_rig.anatomy().limbs[limb];
    const Eigen::Vector3d& root = m_decoder.model_positions()[chain.root];
    const Eigen::Vector3d own = root + clip_reach(limb);
    const TwoBoneSolution clip = two_bone_ik(root, own, chain.upper_length, chain.lower_length, m_clip_swivels[limb],
                                             limb_swivel_reference(m_frame, limb));
    return limb_bend_direction(root, clip.middle, clip.extremity, m_settings.limits.bent_rad);
}

unsigned StrikeAdapter::violations() const {
    const RestAnatomy& anatomy = m_rig.anatomy();
    const auto positions = m_decoder.model_positions();
    unsigned mask = 0;
    for (int limb = 0; limb < k_limb_count; ++limb) {
        const LimbChain& chain = anatomy.limbs[limb];
        const Eigen::Vector3d bend =
            limb_bend_direction(positions[chain.root], positions[chain.middle], positions[chain.extremity], m_settings.limits.bent_rad);
        if (limb_bend_flipped(bend, clip_bend(limb), m_settings.limits)) mask |= 1u << limb;
    }
    if (trunk_turn(anatomy, m_decoder.model_rotations()) > m_settings.limits.trunk_turn_rad) mask |= k_trunk_violation;
    return mask;
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

AdaptedFrame StrikeAdapter::step(double index, Pose& out) {
    AdaptedFrame result;
    result.contact = index == static_cast<double>(contact_index());
    frame_mir(index, m_frame);
    m_clip_swivels = m_frame.swivel;
    result.ramp = offset_ramp(index);
    LimbPins pins = m_pins;
    if (m_middle) return at_stop(step_middle(index, out, result, pins));
    pins.extremity_offset_world[m_limb] = result.ramp * m_offset_at_contact;
    decode(out, m_frame, pins);
    lean(result.ramp, out, pins);
    const bool stopped = stop_at_target(pins, index);
    if (keep_clip_bends(pins) || stopped) decode(out, m_frame, pins);
    result.wanted = m_decoder.limb_targets()[m_limb];
    result.effector = m_decoder.model_positions()[m_effector_joint];
    if ((result.effector - result.wanted).norm() > m_settings.reach_tolerance_m || beyond_limb_reach(result.wanted)) {
        reach_with_trunk(result, pins, out);
        // The trunk moved the limb's root: carry the bends over to the new line again.
        if (keep_clip_bends(pins)) {
            result.ccd_decodes += decode(out, m_frame, pins);
            result.effector = m_decoder.model_positions()[m_effector_joint];
        }
    }
    if (index > contact_index()) result.past_target_m = past_stop(result.effector);
    result.joint_violations = violations();
    return at_stop(result);
}

AdaptedFrame StrikeAdapter::at_stop(const AdaptedFrame& result) {
    // The contact as played: the strike stops where it got to, the target or (out of reach) the closest point to
    // it. The target may have moved since begin() (retarget): a point out of reach does not move with it, and the
    // stop point guessed then would pull the fist or foot back across the gap in one frame.
    if (result.contact) m_stop_point = result.reach == Reach::unreachable ? result.effector : m_plan.target_world;
    return result;
}

void StrikeAdapter::measure_contact_offset() {
    frame_mir(contact_index(), m_frame);
    LimbPins pins = m_pins;
    decode(m_scratch_pose, m_frame, pins);
    lean(1.0, m_scratch_pose, pins);
    m_offset_at_contact = m_plan.target_world - (m_middle ? m_decoder.model_positions()[m_effector_joint] : m_decoder.limb_targets()[m_limb]);
}

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

namespace {

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
