#include "fighter/captured_block_arm.h"

#include "fighter/arm_geometry.h"

#include "kumite/core/contact_point.h"
#include "kumite/core/joint_limits.h"
#include "kumite/core/smoothstep.h"
#include "kumite/core/two_bone_ik.h"

#include <algorithm>

namespace kumite {
namespace {

// A punch arriving this far below the chest joint or more is a low one (the solar plexus, the belly): the
// recorded boxers' body punches arrive 27 cm below it to 7 cm above, simulate:punch's at it.
constexpr double k_low_punch_below_chest_m = 0.1;

} // namespace

void CapturedBlockArm::measure_from_shown(const Defence& defence, const DefenderBody& defender, double shown_s) {
    if (m_measure_from_shown && defence.active()) {
        // A block started last frame, shown then at weight 0: its first step is measured from that pose.
        const int side = defence.block_arm();
        m_last_shown = {defender.shoulder[side], defender.elbow[side], defender.wrist[side]};
        m_last_s = shown_s;
    }
    m_measure_from_shown = false;
}

void CapturedBlockArm::start(Defence& defence, const RestAnatomy& anatomy, const DefenderBody& defender, const MirFrame& mir, double heading_yaw_rad,
                             double now_s) {
    m_last_s = -1.0;
    m_measure_from_shown = true;
    if (m_clips.empty() || !defence.settings().captured_blocks) return;
    const int side = defence.block_arm();
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
    defence.course_point(0.0, arrival, arrival_s);
    const bool low = !defence.move_strike().at_head && arrival.y() < defender.chest.y() - k_low_punch_below_chest_m;
    query.kind = defence.move_strike().at_head ? StrikeKind::rising : low ? StrikeKind::downward : StrikeKind::none;
    // Where on the course: from just outside the hit radius of the part it is aimed at (a fist blocked there has
    // not touched it yet) to `block_clip_span_m` further out, wherever the clip's forearm passes nearest.
    const DefenceSettings& settings = defence.settings();
    const double nearest_m = (defence.move_strike().at_head ? settings.head_radius_m : settings.chest_radius_m) + settings.block_contact_m;
    query.course_count = 0;
    for (int k = 0; k < int(query.course.size()); ++k) {
        const double before_m = nearest_m + settings.block_clip_span_m * k / double(query.course.size() - 1);
        CoursePoint& point = query.course[query.course_count];
        point.before_m = before_m;
        if (defence.course_point(before_m, point.point, point.time_s)) ++query.course_count;
    }
    if (query.course_count == 0) return;
    query.heading_yaw_rad = heading_yaw_rad;
    query.shoulder = defender.shoulder[side];
    query.wrist = defender.wrist[side];
    query.upper_length = chain.upper_length;
    query.lower_length = chain.lower_length;
    // A clip whose forearm would have to be carried more than half an arm away is another movement: synthesized.
    query.max_contact_error = settings.block_clip_reach;
    if (!m_clips.choose(query, anatomy, m_choice)) return; // no captured block gets there in time
    // And one whose elbow, bent as the clip bends it, cannot put the forearm there (the course too close to the
    // body for that arm's shape) is not played either.
    const auto at_meet = m_clips.arm_points(anatomy, limb, m_choice.clip, m_choice.meet_frame, query.shoulder, heading_yaw_rad, Eigen::Vector3d::Zero());
    const Eigen::Vector3d bend = limb_bend_direction(query.shoulder, at_meet.elbow, at_meet.wrist), reference = limb_swivel_reference(mir, limb);
    const CoursePoint& meeting = query.course[m_choice.course_point];
    const Eigen::Vector3d offset = contact_offset(chain, query.shoulder, at_meet.wrist, bend, reference, meeting.point);
    const Eigen::Vector3d asked = at_meet.wrist + offset;
    const TwoBoneSolution placed = two_bone_ik(query.shoulder, asked, chain.upper_length, chain.lower_length,
                                               swivel_keeping_bend(query.shoulder, asked, bend, reference, 0.0), reference);
    const Eigen::Vector3d contact = placed.extremity + k_block_contact_fraction * (placed.middle - placed.extremity);
    if ((contact - meeting.point).norm() > settings.block_contact_m) return;
    defence.use_block_clip(m_choice.clip, m_choice.clip_arm_from_shoulder_mps, std::max(0.03, 0.6 * meeting.time_s), meeting.before_m);
    m_played = 0.0;
    m_played_s = now_s;
}

Eigen::Vector3d CapturedBlockArm::clip_wrist(const Defence& defence, const RestAnatomy& anatomy, std::span<const Eigen::Vector3d> before,
                                             double weight, double heading_yaw_rad, double now_s, MirFrame& frame, Eigen::Vector3d& bend) {
    // The captured block's arm at the played frame over the shown pose, its wrist offset so that the forearm's
    // contact meets the course at the clip's meeting frame (the offset grows with the clip's progress).
    const int side = defence.block_arm();
    const int limb = side == 0 ? int(Limb::arm_l) : int(Limb::arm_r);
    const BlockClipChoice& choice = m_choice;
    const double lead = std::max(1, choice.meet_frame - choice.start_frame);
    // Timed by the fist: the clip's rest up to the meeting should end a little before the fist reaches the meeting
    // point (its course is known better every frame), at 0.4 to 3 times the captured speed.
    const double ft = m_clips.frame_time_s();
    const double remaining_clip_s = (lead - m_played) * ft, fist_s = defence.time_to_block_point();
    const double rate = std::clamp(remaining_clip_s / std::max(0.8 * fist_s, 1e-3), 0.4, 3.0);
    m_played = std::min(lead, m_played + (now_s - m_played_s) * rate / ft);
    m_played_s = now_s;
    const double played = m_played;
    const LimbChain& chain = anatomy.limbs[limb];
    const Eigen::Vector3d shoulder = before[chain.root];
    const Eigen::Vector3d guard_extremity = frame.extremity[limb]; // the undefended wrist, in its parent part
    m_clips.apply(frame, anatomy, limb, choice.clip, choice.start_frame + played, weight, shoulder, heading_yaw_rad);
    // The offset at the meeting frame, with the elbow bending as the clip's does there (as it will be decoded).
    const auto at_meet = m_clips.arm_points(anatomy, limb, choice.clip, choice.meet_frame, shoulder, heading_yaw_rad, Eigen::Vector3d::Zero());
    const Eigen::Vector3d offset = contact_offset(chain, shoulder, at_meet.wrist, limb_bend_direction(shoulder, at_meet.elbow, at_meet.wrist),
                                                  limb_swivel_reference(frame, limb), defence.block_wrist_target());
    const auto clip_arm = m_clips.arm_points(anatomy, limb, choice.clip, choice.start_frame + played, shoulder, heading_yaw_rad, Eigen::Vector3d::Zero());
    // The wrist from the guard's to the clip's (offset), turned about the shoulder and its reach blended: a
    // straight blend between them can pass by the shoulder, folding the arm shut and swinging the elbow round
    // in a frame (the elbow moved 20-48 cm a frame in releases).
    const Eigen::Quaterniond& parent = frame.part_frames[chain.parent_part];
    const Eigen::Vector3d wrist_in_block = clip_arm.wrist - shoulder + smoothstep(played / lead) * offset;
    const Eigen::Vector3d wrist = blend_about_root(parent * guard_extremity * chain.length(), wrist_in_block, weight);
    // The elbow bends as the clip's does (from the guard's, as the block blends in).
    const Eigen::Vector3d blended = (1.0 - weight) * bend + weight * limb_bend_direction(shoulder, clip_arm.elbow, clip_arm.wrist);
    if (blended.norm() > 1e-6) bend = blended.normalized();
    return wrist;
}

void CapturedBlockArm::limit_speed(const Defence& defence, const LimbChain& chain, const Eigen::Vector3d& reference, double swivel, bool lagging,
                                   double now_s, Eigen::Vector3d& wrist, Eigen::Vector3d& bend) {
    // No faster than the clip allows (block_clip_max_speed_ratio): the arm lags where the fist leaves too little
    // time. Once the fist has reached the meeting point (or its strike is over) there is time: the hold and the
    // release back to the guard never move the arm faster than the clip, limit or not.
    double speed_ratio = defence.settings().block_clip_max_speed_ratio; // 0: no limit
    if (lagging || defence.move_strike_over() || defence.time_to_block_point() <= 0.0) speed_ratio = speed_ratio > 0.0 ? std::min(speed_ratio, 1.0) : 1.0;
    if (speed_ratio > 0.0 && m_last_s >= 0.0 && now_s > m_last_s) {
        m_lagging = limit_arm_step(chain, reference, swivel, m_last_shown.wrist - m_last_shown.shoulder, m_last_shown.elbow - m_last_shown.shoulder, speed_ratio * m_choice.clip_arm_from_shoulder_mps * (now_s - m_last_s),
                                   wrist, bend);
    }
}

void CapturedBlockArm::note_shown(Defence& defence, const ShownArm& arm, double now_s) {
    // The blocking arm's fastest move relative to its shoulder, for the block's event (no pop: measured against the
    // captured clip's own), and its wrist's and elbow's in the world (as the motion meter measures them).
    if (m_last_s >= 0.0 && now_s - m_last_s > 1e-6) {
        const double dt_s = now_s - m_last_s;
        const ShownArm& last = m_last_shown;
        const double step = std::max(((arm.wrist - arm.shoulder) - (last.wrist - last.shoulder)).norm(),
                                     ((arm.elbow - arm.shoulder) - (last.elbow - last.shoulder)).norm());
        defence.note_arm_speed(step / dt_s, (arm.wrist - last.wrist).norm() / dt_s, (arm.elbow - last.elbow).norm() / dt_s);
    }
    m_last_shown = arm;
    m_last_s = now_s;
}

} // namespace kumite
