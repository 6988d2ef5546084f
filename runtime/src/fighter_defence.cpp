// The fighter's defence (fighter.h, defence.h): its body handed to the Defence each frame, and the move's edits
// (a blocking arm driven onto the hand's course, a slip's lean) decoded over the shown pose.

#include "kumite/runtime/fighter.h"

#include "fighter_body.h"

#include "kumite/core/joint_limits.h"
#include "kumite/core/mir_edit.h"
#include "kumite/core/contact_point.h"
#include "kumite/core/smoothstep.h"
#include "kumite/core/two_bone_ik.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace kumite {
namespace {

// The elbow's swivel that keeps its bend `bend` (carried over to the shoulder->wrist line `root` -> `wrist`), or
// `fallback` when the limb has no bend there.
double swivel_keeping_bend(const Eigen::Vector3d& root, const Eigen::Vector3d& wrist, const Eigen::Vector3d& bend, const Eigen::Vector3d& reference,
                           double fallback) {
    if ((wrist - root).norm() < 1e-6) return fallback;
    const Eigen::Vector3d axis = (wrist - root).normalized();
    const Eigen::Vector3d across = bend - bend.dot(axis) * axis;
    return across.norm() > 1e-3 ? limb_swivel(root, root + across, wrist, reference) : fallback;
}

// The wrist offset that puts a block's contact point (a third of the way from the wrist to the elbow) on `target`,
// for an arm from `root` to `wrist` whose elbow keeps the bend `bend`: the elbow follows the wrist, so a few passes.
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

// `from` turned towards `to` (both from a limb's root) by `weight` of the angle between them, its length blended
// alike: the extremity keeps its distance from the root all the way, as a straight blend does not.
Eigen::Vector3d blend_about_root(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double weight) {
    const double from_length = from.norm(), to_length = to.norm();
    if (from_length < 1e-6 || to_length < 1e-6) return (1.0 - weight) * from + weight * to;
    const Eigen::Quaterniond turn = Eigen::Quaterniond::Identity().slerp(weight, Eigen::Quaterniond::FromTwoVectors(from, to));
    return (turn * from).normalized() * ((1.0 - weight) * from_length + weight * to_length);
}

// The arm's move this frame cut to at most `max_step` (wrist and elbow, relative to the shoulder): the largest share
// of the way from the arm shown last frame (`last_wrist`, `last_elbow`) to the asked one (`wrist`, its elbow bending
// towards `bend`; `swivel` where it has no bend), wrist and elbow turned about the shoulder as the block's blend
// turns them, the elbow's bend then as the decoder will place it.
// Whether it had to.
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

// A punch arriving this far below the chest joint or more is a low one (issue 26: the solar plexus, the belly): the
// recorded boxers' body punches arrive 27 cm below it to 7 cm above, simulate:punch's at it.
constexpr double k_low_punch_below_chest_m = 0.1;

} // namespace

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
    if (m_block_measure_from_shown && m_defence.active()) {
        // A block started last frame, shown then at weight 0: its first step is measured from that pose.
        const int side = m_defence.block_arm();
        m_block_last_wrist = defender.wrist[side] - defender.shoulder[side];
        m_block_last_elbow = defender.elbow[side] - defender.shoulder[side];
        m_block_last_s = m_previous_step_s;
    }
    m_block_measure_from_shown = false;
    m_defence.update(t_s, m_hands, defender, allowed);
    if (m_defence.block_started()) {
        m_block_last_s = -1.0;
        m_block_measure_from_shown = true;
        start_block_clip(anatomy, defender);
    }
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

void Fighter::start_block_clip(const RestAnatomy& anatomy, const DefenderBody& defender) {
    if (m_block_clips.empty() || !m_defence.settings().captured_blocks) return;
    const int side = m_defence.block_arm();
    const int limb = side == 0 ? int(Limb::arm_l) : int(Limb::arm_r);
    const LimbChain& chain = anatomy.limbs[limb];
    BlockClipQuery query;
    query.limb = limb;
    // Against the head the forearm rises over it (age-uke). A low punch (arriving a hand's breadth or more below the
    // chest joint: the solar plexus, the belly) is swept down (gedan-barai). Between, at the chest, whichever sweep
    // passes the course nearest: a gedan-barai's on its way down, an age-uke's on its way up (downward ones only:
    // 54-100% of the blocks against simulate:punch were captured, the kid's 54%; either kind: 93-100%, more punches
    // defended; README).
    Eigen::Vector3d arrival = Eigen::Vector3d::Zero();
    double arrival_s = 0.0;
    m_defence.course_point(0.0, arrival, arrival_s);
    const bool low = !m_defence.move_strike().at_head && arrival.y() < defender.chest.y() - k_low_punch_below_chest_m;
    query.kind = m_defence.move_strike().at_head ? StrikeKind::rising : low ? StrikeKind::downward : StrikeKind::none;
    // Where on the course: from just outside the hit radius of the part it is aimed at (a fist blocked there has
    // not touched it yet) to `block_clip_span_m` further out, wherever the clip's forearm passes nearest.
    const DefenceSettings& settings = m_defence.settings();
    const double nearest_m = (m_defence.move_strike().at_head ? settings.head_radius_m : settings.chest_radius_m) + settings.block_contact_m;
    query.course_count = 0;
    for (int k = 0; k < int(query.course.size()); ++k) {
        const double before_m = nearest_m + settings.block_clip_span_m * k / double(query.course.size() - 1);
        CoursePoint& point = query.course[query.course_count];
        point.before_m = before_m;
        if (m_defence.course_point(before_m, point.point, point.time_s)) ++query.course_count;
    }
    if (query.course_count == 0) return;
    query.heading_yaw_rad = m_heading.yaw_rad;
    query.shoulder = defender.shoulder[side];
    query.wrist = defender.wrist[side];
    query.upper_length = chain.upper_length;
    query.lower_length = chain.lower_length;
    // A clip whose forearm would have to be carried more than half an arm away is another movement: synthesized.
    query.max_contact_error = settings.block_clip_reach;
    if (!m_block_clips.choose(query, anatomy, m_block_choice)) return; // no captured block gets there in time
    // And one whose elbow, bent as the clip bends it, cannot put the forearm there (the course too close to the
    // body for that arm's shape) is not played either.
    const auto at_meet = m_block_clips.arm_points(anatomy, limb, m_block_choice.clip, m_block_choice.meet_frame, query.shoulder, m_heading.yaw_rad,
                                                 Eigen::Vector3d::Zero());
    const Eigen::Vector3d bend = limb_bend_direction(query.shoulder, at_meet.elbow, at_meet.wrist), reference = limb_swivel_reference(m_mir, limb);
    const CoursePoint& meeting = query.course[m_block_choice.course_point];
    const Eigen::Vector3d offset = contact_offset(chain, query.shoulder, at_meet.wrist, bend, reference, meeting.point);
    const Eigen::Vector3d asked = at_meet.wrist + offset;
    const TwoBoneSolution placed = two_bone_ik(query.shoulder, asked, chain.upper_length, chain.lower_length,
                                               swivel_keeping_bend(query.shoulder, asked, bend, reference, 0.0), reference);
    const Eigen::Vector3d contact = placed.extremity + k_block_contact_fraction * (placed.middle - placed.extremity);
    if ((contact - meeting.point).norm() > settings.block_contact_m) return;
    m_defence.use_block_clip(m_block_choice.clip, m_block_choice.clip_arm_speed_mps, std::max(0.03, 0.6 * meeting.time_s), meeting.before_m);
    m_block_played = 0.0;
    m_block_played_s = m_now_s;
}

void Fighter::apply_defence() {
    m_defence_shown = false;
    const double block = m_defence.block_weight(), slip = m_defence.slip_weight();
    // A captured block's arm held back to its clip's speed may still be on its way to the guard when the move ends:
    // it goes on there at that speed (not in one frame), unless the fighter strikes or moves again.
    const bool lagging = m_block_lagging && m_defence.move() == DefenceMove::none && m_state != FighterState::strike;
    m_block_lagging = false;
    if (block <= 0.0 && slip <= 0.0 && !lagging) return;
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
    const int block_side = m_defence.block_arm();
    const int block_limb = block_side == 0 ? int(Limb::arm_l) : int(Limb::arm_r);
    Eigen::Vector3d asked = Eigen::Vector3d::Zero(); // where the blocking wrist is asked to go
    // A captured block's arm (or one still on its way back to the guard): its wrist (relative to the shoulder, world
    // axes) and elbow bend asked this frame, then held to the clip's speed.
    const bool captured_arm = lagging || (block > 0.0 && m_defence.move() == DefenceMove::block_clip);
    Eigen::Vector3d clip_wrist = Eigen::Vector3d::Zero();
    if (lagging) {
        // On to the guard's wrist and bend (this frame's undefended arm).
        const LimbChain& chain = anatomy.limbs[block_limb];
        clip_wrist = m_defended_frame.part_frames[chain.parent_part] * m_defended_frame.extremity[block_limb] * chain.length();
    } else if (captured_arm) {
        // The captured block's arm at the played frame over the shown pose, its wrist offset so that the forearm's
        // contact meets the course at the clip's meeting frame (the offset grows with the clip's progress).
        const int side = m_defence.block_arm();
        const int limb = side == 0 ? int(Limb::arm_l) : int(Limb::arm_r);
        const BlockClipChoice& choice = m_block_choice;
        const double lead = std::max(1, choice.meet_frame - choice.start_frame);
        // Timed by the fist: the clip's rest up to the meeting should end a little before the fist reaches the meeting
        // point (its course is known better every frame), at 0.4 to 3 times the captured speed.
        const double ft = m_block_clips.frame_time_s();
        const double remaining_clip_s = (lead - m_block_played) * ft, fist_s = m_defence.time_to_block_point();
        const double rate = std::clamp(remaining_clip_s / std::max(0.8 * fist_s, 1e-3), 0.4, 3.0);
        m_block_played = std::min(lead, m_block_played + (m_now_s - m_block_played_s) * rate / ft);
        m_block_played_s = m_now_s;
        const double played = m_block_played;
        const LimbChain& chain = anatomy.limbs[limb];
        const Eigen::Vector3d shoulder = before[chain.root];
        const Eigen::Vector3d guard_extremity = m_defended_frame.extremity[limb]; // the undefended wrist, in its parent part
        m_block_clips.apply(m_defended_frame, anatomy, limb, choice.clip, choice.start_frame + played, block, shoulder, m_heading.yaw_rad);
        // The offset at the meeting frame, with the elbow bending as the clip's does there (as it will be decoded).
        const auto at_meet = m_block_clips.arm_points(anatomy, limb, choice.clip, choice.meet_frame, shoulder, m_heading.yaw_rad, Eigen::Vector3d::Zero());
        const Eigen::Vector3d offset = contact_offset(chain, shoulder, at_meet.wrist, limb_bend_direction(shoulder, at_meet.elbow, at_meet.wrist),
                                                      limb_swivel_reference(m_defended_frame, limb), m_defence.block_wrist_target());
        const auto clip_arm =
            m_block_clips.arm_points(anatomy, limb, choice.clip, choice.start_frame + played, shoulder, m_heading.yaw_rad, Eigen::Vector3d::Zero());
        // The wrist from the guard's to the clip's (offset), turned about the shoulder and its reach blended: a
        // straight blend between them can pass by the shoulder, folding the arm shut and swinging the elbow round
        // in a frame (the elbow moved 20-48 cm a frame in releases).
        const Eigen::Quaterniond& parent = m_defended_frame.part_frames[chain.parent_part];
        const Eigen::Vector3d wrist_in_block = clip_arm.wrist - shoulder + smoothstep(played / lead) * offset;
        clip_wrist = blend_about_root(parent * guard_extremity * chain.length(), wrist_in_block, block);
        // The elbow bends as the clip's does (from the guard's, as the block blends in).
        const Eigen::Vector3d blended = (1.0 - block) * bends[side] + block * limb_bend_direction(shoulder, clip_arm.elbow, clip_arm.wrist);
        if (blended.norm() > 1e-6) bends[side] = blended.normalized();
    } else if (block > 0.0) {
        // The wrist driven onto the hand's course.
        const Eigen::Vector3d natural = body.decoder.limb_targets()[block_limb]; // the undefended decode's wrist
        pins.pinned[block_limb] = false;
        pins.extremity_offset_world[block_limb] = block * (m_defence.block_wrist_target() - natural);
        asked = natural + pins.extremity_offset_world[block_limb];
    }
    if (captured_arm) {
        // No faster than the clip allows (block_clip_max_speed_ratio): the arm lags where the fist leaves too little
        // time. Once the fist has reached the meeting point (or its strike is over) there is time: the hold and the
        // release back to the guard never move the arm faster than the clip, limit or not.
        double speed_ratio = m_defence.settings().block_clip_max_speed_ratio; // 0: no limit
        if (lagging || m_defence.move_strike_over() || m_defence.time_to_block_point() <= 0.0) speed_ratio = speed_ratio > 0.0 ? std::min(speed_ratio, 1.0) : 1.0;
        const LimbChain& chain = anatomy.limbs[block_limb];
        if (speed_ratio > 0.0 && m_block_last_s >= 0.0 && m_now_s > m_block_last_s) {
            m_block_lagging = limit_arm_step(chain, limb_swivel_reference(m_defended_frame, block_limb), m_defended_frame.swivel[block_limb],
                                             m_block_last_wrist, m_block_last_elbow,
                                             speed_ratio * m_block_choice.clip_arm_speed_mps * (m_now_s - m_block_last_s), clip_wrist, bends[block_side]);
        }
        m_defended_frame.extremity[block_limb] = m_defended_frame.part_frames[chain.parent_part].conjugate() * clip_wrist / chain.length();
        pins.pinned[block_limb] = false;
        pins.extremity_offset_world[block_limb].setZero();
        asked = before[chain.root] + clip_wrist;
    }
    if (block > 0.0 || lagging) {
        // The elbow keeps its bend (the guard's, or the captured clip's) carried over to the new shoulder->wrist line,
        // as strikes keep their clip's bends, so it cannot flip.
        m_defended_frame.swivel[block_limb] = swivel_keeping_bend(before[anatomy.limbs[block_limb].root], asked, bends[block_side],
                                                                  limb_swivel_reference(m_defended_frame, block_limb), m_defended_frame.swivel[block_limb]);
    }
    body.decoder.decode(m_pose, m_defended_frame, pins);
    m_shown_by_adapter = false;
    // What is shown, for a recording (mir()): m_mir stays the undefended frame the next blend starts from.
    body.encoder.encode(m_shown_mir, m_pose.view());
    m_defence_shown = true;
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
    if (block > 0.0 || lagging) {
        // The blocking arm's fastest move relative to its shoulder, for the block's event (no pop: measured against
        // the captured clip's own).
        const LimbChain& arm = anatomy.limbs[m_defence.block_arm() == 0 ? int(Limb::arm_l) : int(Limb::arm_r)];
        const Eigen::Vector3d wrist = after[arm.extremity] - after[arm.root], elbow = after[arm.middle] - after[arm.root];
        if (m_block_last_s >= 0.0 && m_now_s - m_block_last_s > 1e-6) {
            const double step = std::max((wrist - m_block_last_wrist).norm(), (elbow - m_block_last_elbow).norm());
            m_defence.note_arm_speed(step / (m_now_s - m_block_last_s));
        }
        m_block_last_wrist = wrist;
        m_block_last_elbow = elbow;
        m_block_last_s = m_now_s;
    }
}

} // namespace kumite
