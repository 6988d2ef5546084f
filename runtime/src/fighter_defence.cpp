// The fighter's defence (fighter.h, defence.h): its body handed to the Defence each frame, and the move's edits
// (a blocking arm driven onto the hand's course, a slip's lean) decoded over the shown pose.

#include "kumite/runtime/fighter.h"

#include "fighter_body.h"

#include "kumite/core/joint_limits.h"
#include "kumite/core/mir_edit.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace kumite {

void Fighter::defend(double t_s) {
    const Body& body = *m_bodies[m_character];
    const RestAnatomy& anatomy = body.rig->anatomy();
    const auto positions = this->positions(); // the pose shown last frame (a strike's adapted one included)
    DefenderBody defender;
    defender.head = part_position(BodyPart::head);
    defender.chest = part_position(BodyPart::chest);
    for (int arm = 0; arm < 2; ++arm) {
        const LimbChain& limb = anatomy.limbs[arm == 0 ? int(Limb::arm_l) : int(Limb::arm_r)];
        defender.elbow[arm] = positions[limb.middle];
        defender.wrist[arm] = positions[limb.extremity];
        defender.shoulder[arm] = positions[limb.root];
        defender.arm_length[arm] = limb.length();
    }
    defender.heading = m_heading;
    // At rest, approaching or recovering any move; while striking, a block with an arm the strike leaves free (the
    // trunk is the strike's: no slip); nothing without a head to face.
    Defence::Allowed allowed;
    if (!m_tracking) {
        allowed = Defence::Allowed{{false, false}, false};
    } else if (m_state == FighterState::strike) {
        allowed.slip = false;
        const int segment = m_db.clips[m_plan.clip].segment;
        const int striking_limb = limb_of_segment(static_cast<BodyPart>(std::max(0, segment)));
        if (striking_limb == int(Limb::arm_l)) allowed.block_arms[0] = false;
        if (striking_limb == int(Limb::arm_r)) allowed.block_arms[1] = false;
    } else if (m_state == FighterState::hold) {
        allowed = Defence::Allowed{{false, false}, false};
    }
    m_defence.update(t_s, m_hands, defender, allowed);
    for (const UserStrikeEvent& seen : m_defence.events()) {
        FighterEvent event;
        event.type = seen.ended ? FighterEvent::Type::user_strike_end : FighterEvent::Type::user_strike;
        event.t_s = t_s;
        event.user_strike = seen;
        if (seen.ended) { // what the defence did to the body since the last strike ended
            event.joint_limit_violations = m_defence_violations;
            event.foot_shift_m = m_defence_foot_shift_m;
            m_defence_violations = 0;
            m_defence_foot_shift_m = 0.0;
        }
        push_event(event);
    }
    m_defence.clear_events();
}

void Fighter::apply_defence() {
    const double block = m_defence.block_weight(), slip = m_defence.slip_weight();
    if (block <= 0.0 && slip <= 0.0) return;
    Body& body = *m_bodies[m_character];
    const RestAnatomy& anatomy = body.rig->anatomy();
    // The undefended pose: the shown decode, or a strike's adapted frame (decoded again from its MIR frame, for the
    // arm's natural wrist below).
    const bool striking = m_state == FighterState::strike;
    if (striking) body.decoder.decode(m_pose, m_mir);
    const auto before = striking ? body.adapter.positions() : body.decoder.model_positions();
    // What the edits must not break, measured against the undefended pose: the arms' bends, the trunk, the feet.
    std::array<Eigen::Vector3d, 2> bends, ankles;
    for (int side = 0; side < 2; ++side) {
        const LimbChain& arm = anatomy.limbs[side == 0 ? int(Limb::arm_l) : int(Limb::arm_r)];
        bends[side] = limb_bend_direction(before[arm.root], before[arm.middle], before[arm.extremity]);
        ankles[side] = before[anatomy.limbs[side == 0 ? int(Limb::leg_l) : int(Limb::leg_r)].extremity];
    }
    m_defended_frame = m_mir;
    // The feet as the shown pose has them: lock_feet re-encoded the shown frame, so pinned feet stay pinned and a
    // released foot's fading offset is in the frame already (applying it again would move that foot twice). A
    // strike's frame holds its adapted limbs and planted feet already.
    LimbPins& pins = m_defence_pins;
    pins = m_state == FighterState::strike ? LimbPins{} : m_pins;
    for (Eigen::Vector3d& offset : pins.extremity_offset_world) offset.setZero();
    if (slip > 0.0) {
        // Lean above the spine's base so the head moves by the slip's offset: a turn about the horizontal axis
        // across it, by the angle that carries the head that far.
        const int base = anatomy.body_map.joint(BodyPart::spine) >= 0 ? anatomy.body_map.joint(BodyPart::spine) : anatomy.body_map.joint(BodyPart::pelvis);
        const double height = std::max(0.2, (before[anatomy.body_map.joint(BodyPart::head)] - before[base]).norm());
        const Eigen::Vector3d offset = m_defence.slip_offset();
        const Eigen::Vector3d axis = Eigen::Vector3d::UnitY().cross(offset).normalized();
        // At most 30 degrees: a short trunk leans that far and no further (the trunk's joint limit, with the guard's
        // own twist, is 75 degrees).
        const double angle = slip * std::min(0.5236, std::asin(std::min(1.0, offset.norm() / height)));
        mir_frame_turn(m_defended_frame, TrunkPivot::spine_base, Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis)), before[base],
                       anatomy.leg_length, anatomy.ankle_height);
    }
    if (block > 0.0) {
        // The wrist driven onto the hand's course, and the elbow keeping the guard's bend carried over to the new
        // shoulder->wrist line (as strikes keep their clip's bends), so it cannot flip.
        const int side = m_defence.block_arm();
        const int limb = side == 0 ? int(Limb::arm_l) : int(Limb::arm_r);
        const Eigen::Vector3d natural = body.decoder.limb_targets()[limb]; // the undefended decode's wrist
        pins.pinned[limb] = false;
        pins.extremity_offset_world[limb] = block * (m_defence.block_wrist_target() - natural);
        const Eigen::Vector3d root = before[anatomy.limbs[limb].root], asked = natural + pins.extremity_offset_world[limb];
        if ((asked - root).norm() > 1e-6) {
            const Eigen::Vector3d axis = (asked - root).normalized();
            Eigen::Vector3d bend = bends[side] - bends[side].dot(axis) * axis;
            if (bend.norm() > 1e-3) {
                m_defended_frame.swivel[limb] = limb_swivel(root, root + bend, asked, limb_swivel_reference(m_defended_frame, limb));
            }
        }
    }
    body.decoder.decode(m_pose, m_defended_frame, pins);
    m_shown_by_adapter = false;
    const auto after = body.decoder.model_positions();
    unsigned violations = trunk_turn(anatomy, body.decoder.model_rotations()) > JointLimits{}.trunk_turn_rad ? k_trunk_violation : 0u;
    for (int side = 0; side < 2; ++side) {
        const int limb = side == 0 ? int(Limb::arm_l) : int(Limb::arm_r);
        const LimbChain& arm = anatomy.limbs[limb];
        if (limb_bend_flipped(limb_bend_direction(after[arm.root], after[arm.middle], after[arm.extremity]), bends[side])) violations |= 1u << limb;
        const Eigen::Vector3d ankle = after[anatomy.limbs[side == 0 ? int(Limb::leg_l) : int(Limb::leg_r)].extremity];
        m_defence_foot_shift_m = std::max(m_defence_foot_shift_m, (ankle - ankles[side]).norm());
    }
    m_defence_violations += joint_violation_count(violations);
}

} // namespace kumite
