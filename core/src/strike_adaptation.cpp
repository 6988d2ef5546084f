// The strike adapted frame by frame (strike_adaptation.h): the plan begun (support feet, pivots, the clip's
// progress to its hit, the approach), the clip's frame blended in (step 1), the offset ramp (step 2), the limb
// solved (step 3), and knee and elbow strikes placed by their middle joint. The trunk's reach (step 4) is in
// strike_trunk_reach.cpp, the impact (step 6) in strike_impact.cpp, the clip's bends kept (step 7) in
// strike_clip_bends.cpp.
#include "kumite/core/strike_adaptation.h"

#include "kumite/core/smoothstep.h"
#include "kumite/core/two_bone_ik.h"

#include <algorithm>
#include <cmath>

namespace kumite {

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
    m_early_stop_index = k_no_early_stop;
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
    m_plane_offsets.fill(0.0);
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
    if (result.contact && !stopped_early()) m_stop_point = result.reach == Reach::unreachable ? result.effector : m_plan.target_world;
    return result;
}

void StrikeAdapter::measure_contact_offset() {
    frame_mir(contact_index(), m_frame);
    LimbPins pins = m_pins;
    decode(m_scratch_pose, m_frame, pins);
    lean(1.0, m_scratch_pose, pins);
    m_offset_at_contact = m_plan.target_world - (m_middle ? m_decoder.model_positions()[m_effector_joint] : m_decoder.limb_targets()[m_limb]);
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

} // namespace kumite
