#include "fighter/fighter_defence.h"

#include "fighter/arm_geometry.h"

#include "kumite/core/joint_limits.h"
#include "kumite/core/mir_edit.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace kumite {
namespace {

constexpr double k_cover_hold_s = 0.2; // a strike's free arm kept in the guard this long after it (the recovery's blend)
constexpr double k_cover_mps = 3.0;    // how fast the guard's pull moves a wrist on top of its own motion
constexpr int k_fist_off_rounds = 3;              // rounds out of both gloves, for a fist caught between the two
constexpr double k_fist_in_tolerance_m = 0.005; // a fist this far into a glove is at it (the push out leaves a few mm)

} // namespace

void FighterDefence::reset() {
    m_defence.reset();
    m_guard_known = false; // another body, or one the tracker lost: its guard is seen again first
    m_cover_weight = {0.0, 0.0};
    m_block_arm.forget_lag(); // the last arm shown was another body's, or held still
}

void FighterDefence::defend(double t_s, double shown_s, const UserHands& hands, bool tracking, FighterState state, int striking_segment,
                            const CharacterBody& body, EventLog& log) {
    const RestAnatomy& anatomy = body.anatomy();
    const auto positions = body.positions(); // the pose shown last frame (a strike's adapted one included)
    DefenderBody defender;
    defender.head = body.part_position(BodyPart::head);
    defender.chest = body.part_position(BodyPart::chest);
    for (int arm = 0; arm < 2; ++arm) {
        const LimbChain& limb = anatomy.limbs[arm == 0 ? int(Limb::arm_l) : int(Limb::arm_r)];
        defender.elbow[arm] = positions[limb.middle];
        defender.wrist[arm] = positions[limb.extremity];
        defender.shoulder[arm] = positions[limb.root];
        defender.arm_length[arm] = limb.length();
    }
    defender.heading = body.heading();
    // At rest, approaching or recovering any move; while striking, a block with an arm the strike leaves free (the
    // trunk is the strike's: no slip); nothing without a head to face.
    Defence::Allowed allowed;
    if (!tracking) {
        allowed = Defence::Allowed{{false, false}, false};
    } else if (state == FighterState::strike) {
        allowed.slip = false;
        const int striking_limb = limb_of_segment(static_cast<BodyPart>(std::max(0, striking_segment)));
        if (striking_limb == int(Limb::arm_l)) allowed.block_arms[0] = false;
        if (striking_limb == int(Limb::arm_r)) allowed.block_arms[1] = false;
    } else if (state == FighterState::hit_reaction) { // rocked by a blow: the arms may still cover, the head lean on top
        allowed.slip = m_defence.settings().slip_in_hit_reaction;
    } else if (state == FighterState::hold) {
        allowed = Defence::Allowed{{false, false}, false};
    }
    // The guard's arms as last shown (resting or stepping, no move on): where a strike keeps its free arm.
    if ((state == FighterState::rest || state == FighterState::approach) && !m_defence.active() && m_cover_weight[0] <= 0.0 &&
        m_cover_weight[1] <= 0.0) {
        for (int arm = 0; arm < 2; ++arm) m_guard_wrist_from_head[arm] = defender.heading.direction_to_heading(defender.wrist[arm] - defender.head);
        m_guard_known = true;
    }
    m_block_arm.measure_from_shown(m_defence, defender, shown_s);
    m_landed = false;
    m_defence.update(t_s, hands, defender, allowed);
    if (m_defence.block_started()) m_block_arm.start(m_defence, anatomy, defender, body.mir(), body.heading().yaw_rad, t_s);
    for (const UserStrikeEvent& seen : m_defence.events()) {
        FighterEvent event;
        event.type = seen.course_followed ? FighterEvent::Type::user_strike_course
                     : seen.ended           ? FighterEvent::Type::user_strike_end
                                            : FighterEvent::Type::user_strike;
        event.t_s = t_s;
        event.user_strike = seen;
        if (seen.ended && seen.outcome == UserStrikeOutcome::hit_by_user) {
            m_landed = true;
            m_landed_strike = seen;
        }
        if (seen.ended) { // what the defence did to the body since the last strike ended
            event.joint_limit_violations = m_violations;
            event.foot_shift_m = m_foot_shift_m;
            m_violations = 0;
            m_foot_shift_m = 0.0;
        }
        log.push(event);
    }
    m_defence.clear_events();
}

void FighterDefence::apply(double now_s, int striking_segment, const LimbPins& pins_shown, CharacterBody& body) {
    const bool striking = striking_segment >= 0;
    const int striking_limb = striking ? limb_of_segment(static_cast<BodyPart>(striking_segment)) : -1;
    const int striking_arm = striking_limb == int(Limb::arm_l) ? 0 : striking_limb == int(Limb::arm_r) ? 1 : -1;
    m_shown = false;
    m_arm_to_note = -1;
    const double block = m_defence.block_weight(), slip = m_defence.slip_weight();
    // A captured block's arm held back to its clip's speed may still be on its way to the guard when the move ends:
    // it goes on there at that speed (not in one frame), unless the fighter strikes or moves again.
    const bool lagging = m_block_arm.lagging() && m_defence.move() == DefenceMove::none && !striking;
    m_block_arm.forget_lag();
    // The guard kept: each free arm goes to (or stays at) the guard while striking and a little after.
    const double dt_s = std::clamp(now_s - m_last_apply_s, 0.0, 0.1);
    m_last_apply_s = now_s;
    std::array<bool, 2> cover_goal{};
    for (int arm = 0; arm < 2; ++arm) {
        const bool covering = m_defence.settings().keep_guard && striking && m_guard_known && arm != striking_arm;
        if (covering) m_cover_end_s[arm] = now_s;
        cover_goal[arm] = covering || (m_cover_weight[arm] > 0.0 && now_s - m_cover_end_s[arm] < k_cover_hold_s);
    }
    const bool cover = cover_goal[0] || cover_goal[1] || m_cover_weight[0] > 0.0 || m_cover_weight[1] > 0.0;
    // The fists a glove is in, on the pose as it stands: a strike's own arm is left to the strike, a captured block's
    // arm to its clip (pushed, it would outrun the clip's speed).
    const FistOff fist_off = m_fist_off;
    m_fist_off.guard = nullptr;
    m_fists_kept = fist_off;
    std::array<bool, 2> kept_out{}, fist_in{};
    if (fist_off.guard != nullptr) {
        const RestAnatomy& anatomy = body.anatomy();
        const auto shown = body.positions();
        for (int arm = 0; arm < 2; ++arm) {
            kept_out[arm] = arm != striking_arm && !(arm == m_defence.block_arm() && (lagging || (block > 0.0 && m_defence.move() == DefenceMove::block_clip)));
            if (!kept_out[arm]) continue;
            const LimbChain& chain = anatomy.limbs[arm == 0 ? int(Limb::arm_l) : int(Limb::arm_r)];
            fist_in[arm] = fist_off_offset(fist_off, shown[chain.middle], shown[chain.extremity]).squaredNorm() > 0.0;
        }
    }
    // Held back only off the block's course: a blocking arm held short of the glove it goes to meet would miss it.
    m_fists_kept_arms = kept_out;
    if (block > 0.0 && m_defence.block_arm() >= 0) m_fists_kept_arms[std::size_t(m_defence.block_arm())] = false;
    if (block <= 0.0 && slip <= 0.0 && !lagging && !cover && !fist_in[0] && !fist_in[1]) return;
    CharacterBody::Rig& rig = body.current();
    const RestAnatomy& anatomy = rig.rig->anatomy();
    // The undefended pose: the shown decode, or a strike's adapted frame (decoded again from its MIR frame, for the
    // arm's natural wrist below).
    if (striking) rig.decoder.decode(body.pose(), body.mir());
    const auto before = striking ? rig.adapter.positions() : rig.decoder.model_positions();
    const double trunk_before = trunk_turn(anatomy, rig.decoder.model_rotations()); // the undefended trunk's turn
    // What the edits must not break, measured against the undefended pose: the arms' bends, the trunk, the feet.
    std::array<Eigen::Vector3d, 2> bends, ankles;
    for (int side = 0; side < 2; ++side) {
        const LimbChain& arm = anatomy.limbs[side == 0 ? int(Limb::arm_l) : int(Limb::arm_r)];
        bends[side] = limb_bend_direction(before[arm.root], before[arm.middle], before[arm.extremity]);
        ankles[side] = before[anatomy.limbs[side == 0 ? int(Limb::leg_l) : int(Limb::leg_r)].extremity];
    }
    m_defended_frame = body.mir();
    // The feet as the shown pose has them: lock_feet re-encoded the shown frame, so pinned feet stay pinned and a
    // released foot's fading offset is in the frame already (applying it again would move that foot twice). A
    // strike's frame holds its adapted limbs and planted feet already.
    LimbPins& pins = m_pins;
    pins = striking ? LimbPins{} : pins_shown;
    for (Eigen::Vector3d& offset : pins.extremity_offset_world) offset.setZero();
    if (slip > 0.0) {
        // Lean above the spine's base so the head moves by the slip's offset: a turn about the horizontal axis
        // across it, by the angle that carries the head that far.
        const int base = anatomy.body_map.joint(BodyPart::spine) >= 0 ? anatomy.body_map.joint(BodyPart::spine) : anatomy.body_map.joint(BodyPart::pelvis);
        const double height = std::max(0.2, (before[anatomy.body_map.joint(BodyPart::head)] - before[base]).norm());
        const Eigen::Vector3d offset = m_defence.slip_offset();
        const Eigen::Vector3d axis = Eigen::Vector3d::UnitY().cross(offset).normalized();
        // At most 30 degrees: a short trunk leans that far and no further (the trunk's joint limit, with the guard's
        // own twist, is 75 degrees); and no further than the trunk may still turn from where the pose has it (a hit
        // reaction's fold): two turns together turn at most by the sum of their angles.
        const double room = std::max(0.0, JointLimits{}.trunk_turn_rad - trunk_before - 1e-6);
        const double angle = std::min(room, slip * std::min(0.5236, std::asin(std::min(1.0, offset.norm() / height))));
        mir_frame_turn(m_defended_frame, TrunkPivot::spine_base, Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis)), before[base],
                       anatomy.leg_length, anatomy.ankle_height);
    }
    const int block_side = m_defence.block_arm();
    const int block_limb = block_side == 0 ? int(Limb::arm_l) : int(Limb::arm_r);
    const LimbChain& block_chain = anatomy.limbs[block_limb];
    Eigen::Vector3d asked = Eigen::Vector3d::Zero(); // where the blocking wrist is asked to go
    // A captured block's arm (or one still on its way back to the guard): its wrist (relative to the shoulder, world
    // axes) and elbow bend asked this frame, then held to the clip's speed.
    const bool captured_arm = lagging || (block > 0.0 && m_defence.move() == DefenceMove::block_clip);
    Eigen::Vector3d clip_wrist = Eigen::Vector3d::Zero();
    if (lagging) {
        // On to the guard's wrist and bend (this frame's undefended arm).
        clip_wrist = m_defended_frame.part_frames[block_chain.parent_part] * m_defended_frame.extremity[block_limb] * block_chain.length();
    } else if (captured_arm) {
        clip_wrist = m_block_arm.clip_wrist(m_defence, anatomy, before, block, body.heading().yaw_rad, now_s, m_defended_frame, bends[block_side]);
    } else if (block > 0.0) {
        // The wrist driven onto the hand's course.
        const Eigen::Vector3d natural = rig.decoder.limb_targets()[block_limb]; // the undefended decode's wrist
        pins.pinned[block_limb] = false;
        pins.extremity_offset_world[block_limb] = block * (m_defence.block_wrist_target() - natural);
        asked = natural + pins.extremity_offset_world[block_limb];
    }
    if (captured_arm) {
        m_block_arm.limit_speed(m_defence, block_chain, limb_swivel_reference(m_defended_frame, block_limb), m_defended_frame.swivel[block_limb], lagging,
                                now_s, clip_wrist, bends[block_side]);
        m_defended_frame.extremity[block_limb] = m_defended_frame.part_frames[block_chain.parent_part].conjugate() * clip_wrist / block_chain.length();
        pins.pinned[block_limb] = false;
        pins.extremity_offset_world[block_limb].setZero();
        asked = before[block_chain.root] + clip_wrist;
    }
    if (block > 0.0 || lagging) {
        // The elbow keeps its bend (the guard's, or the captured clip's) carried over to the new shoulder->wrist line,
        // as strikes keep their clip's bends, so it cannot flip.
        m_defended_frame.swivel[block_limb] = swivel_keeping_bend(before[block_chain.root], asked, bends[block_side],
                                                                  limb_swivel_reference(m_defended_frame, block_limb), m_defended_frame.swivel[block_limb]);
    }
    // The guard kept: a free arm's wrist where the guard had it from the head (the head as the strike moves it).
    for (int arm = 0; arm < 2; ++arm) {
        if ((block > 0.0 || lagging) && arm == block_side) { // the block has the arm: the cover starts again after it
            m_cover_weight[arm] = 0.0;
            continue;
        }
        if (!cover_goal[arm] && m_cover_weight[arm] <= 0.0) continue;
        const int limb = arm == 0 ? int(Limb::arm_l) : int(Limb::arm_r);
        const LimbChain& chain = anatomy.limbs[limb];
        const Eigen::Vector3d head = before[anatomy.body_map.joint(BodyPart::head)];
        const Eigen::Vector3d guard_wrist = head + body.heading().direction_to_world(m_guard_wrist_from_head[arm]);
        const Eigen::Vector3d natural = rig.decoder.limb_targets()[limb];
        // The weight moves towards its goal no faster than carries the wrist k_cover_mps off the arm's own way: an
        // arm already in the guard (a strike's start) is kept there at once, one a block left elsewhere comes back.
        const double step = dt_s * k_cover_mps / std::max((guard_wrist - natural).norm(), 1e-6);
        m_cover_weight[arm] = std::clamp(m_cover_weight[arm] + std::clamp((cover_goal[arm] ? 1.0 : 0.0) - m_cover_weight[arm], -step, step), 0.0, 1.0);
        if (m_cover_weight[arm] <= 0.0) continue;
        pins.pinned[limb] = false;
        pins.extremity_offset_world[limb] = m_cover_weight[arm] * (guard_wrist - natural);
        // The elbow keeps the strike's own bend, as a block's does.
        m_defended_frame.swivel[limb] = swivel_keeping_bend(before[chain.root], natural + pins.extremity_offset_world[limb], bends[arm],
                                                            limb_swivel_reference(m_defended_frame, limb), m_defended_frame.swivel[limb]);
    }
    body.decode(m_defended_frame, pins);
    // The fists kept out of the user's gloves, as the edits placed them: the wrist moved off by as much as the fist
    // is in, the elbow's bend kept, and the pose decoded again.
    if (fist_off.guard != nullptr && push_fists_out(fist_off, kept_out, bends, pins, body)) body.decode(m_defended_frame, pins);
    // What is shown, for a recording (shown_mir()): the body's MIR frame stays the undefended one the next blend starts from.
    body.encode(m_shown_mir);
    m_shown = true;
    const auto after = rig.decoder.model_positions();
    // The trunk over its limit, when the edits turned it further (a reaction's fold near the limit, leaned on more).
    const double trunk_after = trunk_turn(anatomy, rig.decoder.model_rotations());
    unsigned violations = trunk_after > JointLimits{}.trunk_turn_rad && trunk_after > trunk_before + 1e-9 ? k_trunk_violation : 0u;
    for (int side = 0; side < 2; ++side) {
        const int limb = side == 0 ? int(Limb::arm_l) : int(Limb::arm_r);
        const LimbChain& arm = anatomy.limbs[limb];
        if (limb_bend_flipped(limb_bend_direction(after[arm.root], after[arm.middle], after[arm.extremity]), bends[side])) violations |= 1u << limb;
        const Eigen::Vector3d ankle = after[anatomy.limbs[side == 0 ? int(Limb::leg_l) : int(Limb::leg_r)].extremity];
        m_foot_shift_m = std::max(m_foot_shift_m, (ankle - ankles[side]).norm());
    }
    m_violations += joint_violation_count(violations);
    m_arm_to_note = block > 0.0 || lagging ? block_limb : -1; // measured as shown (note_shown_arm)
}

bool FighterDefence::push_fists_out(const FistOff& fists, const std::array<bool, 2>& arms, const std::array<Eigen::Vector3d, 2>& bends, LimbPins& pins, CharacterBody& body) {
    const RestAnatomy& anatomy = body.anatomy();
    const auto decoded = body.current().decoder.model_positions();
    bool pushed = false;
    for (int arm = 0; arm < 2; ++arm) {
        if (!arms[arm]) continue;
        const int limb = arm == 0 ? int(Limb::arm_l) : int(Limb::arm_r);
        const LimbChain& chain = anatomy.limbs[limb];
        const Eigen::Vector3d wrist = decoded[chain.extremity];
        const Eigen::Vector3d offset = fist_off_offset(fists, decoded[chain.middle], wrist);
        if (offset.squaredNorm() <= 0.0) continue;
        pins.pinned[limb] = false;
        pins.extremity_offset_world[limb] += offset;
        m_defended_frame.swivel[limb] = swivel_keeping_bend(decoded[chain.root], wrist + offset, bends[arm], limb_swivel_reference(m_defended_frame, limb),
                                                            m_defended_frame.swivel[limb]);
        pushed = true;
    }
    return pushed;
}

Eigen::Vector3d FighterDefence::fist_off_offset(const FistOff& fists, const Eigen::Vector3d& elbow, const Eigen::Vector3d& wrist) {
    const Eigen::Vector3d fist_start = fist_centre(elbow, wrist, fists.knuckles_past_wrist_m);
    Eigen::Vector3d fist = fist_start;
    // Out of one glove, then the other, the nearest way; a few rounds, for a fist caught between the two.
    for (int round = 0; round < 2 * k_fist_off_rounds; ++round) {
        const int side = round % 2;
        if (!fists.guard->hand(side)) continue;
        const Eigen::Vector3d core = fists.guard->glove(side);
        const double reach = fists.guard->radius(side == 0 ? GuardPart::glove_l : GuardPart::glove_r) + fists.fist_radius_m;
        Eigen::Vector3d out = fist - core;
        if (out.norm() >= reach) continue;
        // At the glove's very centre, back along the forearm.
        out = out.norm() > 1e-6 ? Eigen::Vector3d(out.normalized()) : Eigen::Vector3d((elbow - wrist).normalized());
        fist = core + reach * out;
    }
    return fist - fist_start;
}

bool FighterDefence::blocked(const CharacterBody& body, int limb) const {
    if (m_fists_kept.guard == nullptr || limb > 1 || !m_fists_kept_arms[std::size_t(limb)]) return false;
    const LimbChain& chain = body.anatomy().limbs[limb == 0 ? int(Limb::arm_l) : int(Limb::arm_r)];
    const auto shown = body.positions();
    const Eigen::Vector3d fist = fist_centre(shown[chain.middle], shown[chain.extremity], m_fists_kept.knuckles_past_wrist_m);
    for (int side = 0; side < 2; ++side) {
        if (!m_fists_kept.guard->hand(side)) continue;
        const double reach = m_fists_kept.guard->radius(side == 0 ? GuardPart::glove_l : GuardPart::glove_r) + m_fists_kept.fist_radius_m;
        if ((fist - m_fists_kept.guard->glove(side)).norm() < reach - k_fist_in_tolerance_m) return true;
    }
    return false;
}

void FighterDefence::note_shown_arm(double now_s, const CharacterBody& body) {
    if (m_arm_to_note < 0) return;
    // The blocking arm's fastest moves, for the block's event: on the pose shown, after the speed limit (what the user
    // saw, not what the edits asked for).
    const LimbChain& chain = body.anatomy().limbs[m_arm_to_note];
    const auto shown = body.positions();
    m_block_arm.note_shown(m_defence, {shown[chain.root], shown[chain.middle], shown[chain.extremity]}, now_s);
    m_arm_to_note = -1;
}

} // namespace kumite
