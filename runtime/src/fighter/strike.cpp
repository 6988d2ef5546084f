#include "fighter/strike.h"

#include "kumite/core/joint_limits.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <string_view>

namespace kumite {
namespace {

constexpr double k_max_strike_speedup = 1.9; // the time warp's pace at the start, 2 - s, stays over 0.1
constexpr double k_pace_back_s = 0.1;        // after the contact, the clip's clock back to its own pace over this long
constexpr double k_block_give_m = 0.005;     // how far a blocked blow may press into the part that blocked it
constexpr int k_block_holds = 2;             // the frame stepped again at most this often to hold it there

} // namespace

double strike_speedup(const MotionDatabaseView& db, const FighterSettings& settings, int clip, int contact_frame) {
    if (clip < 0 || contact_frame < 1 || settings.max_speedup <= 1.0) return 1.0;
    const DbClip& c = db.clips[clip];
    const std::string_view semantics = db.string(c.semantics);
    const double real_mps = semantics == "punch" ? settings.punch_speed_mps : semantics == "kick" ? settings.kick_speed_mps : 0.0;
    const float* before = db.poses[c.first_pose + contact_frame - 1].hit_point;
    const float* at = db.poses[c.first_pose + contact_frame].hit_point;
    const double captured_mps = Eigen::Vector3d(at[0] - before[0], at[1] - before[1], at[2] - before[2]).norm() / db.meta.frame_time_s;
    if (real_mps <= 0.0 || captured_mps <= 1e-6 || captured_mps >= real_mps) return 1.0;
    return std::min({real_mps / captured_mps, settings.max_speedup, k_max_strike_speedup});
}

double strike_clip_time(double clock_s, double to_contact_s, double speedup) {
    if (speedup <= 1.0 || to_contact_s <= 0.0) return clock_s;
    if (clock_s <= to_contact_s) {
        const double u = std::max(0.0, clock_s / to_contact_s);
        return to_contact_s * ((2.0 - speedup) * u + (speedup - 1.0) * u * u);
    }
    // After the contact the pace falls from `speedup` to 1 over k_pace_back_s, linearly.
    const double after = clock_s - to_contact_s;
    if (after < k_pace_back_s) return to_contact_s + speedup * after - (speedup - 1.0) * after * after / (2.0 * k_pace_back_s);
    return to_contact_s + 0.5 * (speedup + 1.0) * k_pace_back_s + (after - k_pace_back_s);
}

Strike::Strike(const MotionDatabaseView& db, const FighterSettings& settings)
    : m_db(db), m_settings(settings), m_hit_radius_m(settings.hit_radius_m), m_steer_until_s(settings.steer_until_s) {}

int Strike::segment() const { return m_plan.clip >= 0 ? m_db.clips[m_plan.clip].segment : -1; }

double Strike::try_plan(const RetrievalResult& found, const Eigen::Vector3d& target, const MirFrame& from, CharacterBody& body) {
    if (!found.found) return 1e9;
    m_plan = {found.clip, found.start_frame, found.contact_frame, found.clip_to_world, target};
    m_speedup = strike_speedup(m_db, m_settings, found.clip, found.contact_frame);
    m_start_frame = from;
    m_impact = true;
    begin(body);
    return (body.current().adapter.stop_point() - target).norm();
}

void Strike::start(double t_s, const Purpose& purpose) {
    m_purpose = purpose;
    m_start_s = t_s;
    m_clock_s = m_clock_before_s = 0.0;
    m_last_play_s = t_s;
    m_contact_done = false;
    m_contact_shown_s = -1.0;
    m_contact_now = false;
    m_over = false;
    m_overshoot_m = 0.0;
    m_held_s = 0.0;
    m_holding = false;
    m_violations = 0;
    m_impact = true;
    m_previous_effector_s = -1.0;
    m_planned_target = m_plan.target_world;
    m_have_path = false;
    m_met_body = false;
    m_user_block = GuardPart::none;
}

void Strike::carry_over(CharacterBody& body) {
    body.decode(m_start_frame);
    begin(body);
}

void Strike::begin(CharacterBody& body) {
    // The feet stay where the last decoded pose (the strike's start) has them.
    CharacterBody::Rig& rig = body.current();
    const auto positions = rig.decoder.model_positions();
    const RestAnatomy& anatomy = rig.rig->anatomy();
    rig.adapter.begin(m_plan, m_start_frame, {true, true},
                      {positions[anatomy.limbs[int(Limb::leg_l)].extremity], positions[anatomy.limbs[int(Limb::leg_r)].extremity]});
    rig.adapter.set_impact(m_impact); // a switch after the contact keeps the strike's outcome
}

FighterEvent Strike::event(FighterEvent::Type type, double t_s) const {
    FighterEvent event = EventLog::of_order(type, t_s, m_purpose.order);
    event.varied = m_purpose.varied;
    event.clip = m_plan.clip;
    event.impact = m_impact;
    event.aim = m_purpose.aim;
    event.target = m_plan.target_world;
    event.head_speed_mps = m_purpose.head_speed_mps;
    event.retrieval_offset_m = m_purpose.retrieval_offset_m;
    event.target_part = m_purpose.part;
    event.reachable = m_purpose.reachable;
    event.steered_m = (m_plan.target_world - m_planned_target).norm();
    event.speedup = m_speedup;
    event.user_block = m_user_block;
    return event;
}

void Strike::steer(double to_contact_s, CharacterBody& body, const TrackedUser& user) {
    // Predicted aim: the target follows the head until steer_until_s before the contact.
    if (m_steer_until_s <= 0.0 || m_purpose.aim != FighterAim::predicted || !user.tracking() || !user.motion().ready()) return;
    if (m_contact_done || to_contact_s <= m_steer_until_s) return;
    const Eigen::Vector3d target = user.motion().predict(to_contact_s) + m_purpose.aim_offset;
    body.current().adapter.retarget(target);
    m_plan.target_world = target;
}

void Strike::play(double t_s, CharacterBody& body, const TrackedUser& user) {
    StrikeAdapter& adapter = body.current().adapter;
    // Frames of the database's rate, as a fractional index; the contact frame is played exactly.
    m_clock_before_s = m_clock_s;
    m_clock_s += t_s - m_last_play_s;
    m_last_play_s = t_s;
    const double contact = adapter.contact_index();
    const double to_contact_s = contact * m_db.meta.frame_time_s;
    double index = strike_clip_time(m_clock_s, to_contact_s, m_speedup) / m_db.meta.frame_time_s;
    // The database's frame time is a float: a frame landing on the contact can come out a few 1e-7 short of it.
    if (!m_contact_done && index >= contact - 1e-4) index = contact;
    index = std::min(index, double(adapter.frame_count() - 1));
    // At the contact: a head still at the latched target takes the impact (the strike stops there); a dodged
    // strike follows through from this frame on.
    const bool at_contact = !m_contact_done && index >= contact;
    steer(to_contact_s - m_clock_s, body, user);
    if (at_contact && m_user_block == GuardPart::none) {
        m_impact = user.tracking() && (aimed_point(user) - m_plan.target_world).norm() <= m_hit_radius_m;
        adapter.set_impact(m_impact);
    }
    if (m_user_block != GuardPart::none) follow_block(index, body, user);
    AdaptedFrame frame = adapter.step(index, body.pose());
    body.show_adapter();
    const bool blocked = m_settings.user_guard.enabled && meet_guard(index, body, user);
    if (blocked) {
        frame = adapter.step(index, body.pose()); // held where the guard met it, from this frame
        body.show_adapter();
        m_impact = true; // the strike's contact is here (measure() tells it)
    }
    // The limb turns about the hit joint as it is held (the fist about the wrist, the foot about the ankle): held
    // off again from where the striking part now is, twice at most.
    for (int again = 0; again < k_block_holds && m_user_block != GuardPart::none && into_block(body, user) > k_block_give_m; ++again) {
        follow_block(index, body, user);
        frame = adapter.step(index, body.pose());
        body.show_adapter();
    }
    m_overshoot_m = std::max(m_overshoot_m, frame.past_target_m);
    m_violations += joint_violation_count(frame.joint_violations);
    body.encode(body.mir()); // what the defence's edits start from
    m_contact_now = at_contact || blocked;
    if (m_contact_now) m_contact_done = true;
    m_over = index >= adapter.frame_count() - 1;
}

namespace {

// The striking part's centre in `positions` (world): the fist or foot `knuckles_m` past the wrist or ankle along the
// lower bone, or the elbow or knee itself.
Eigen::Vector3d striking_point_in(std::span<const Eigen::Vector3d> positions, const RestAnatomy& anatomy, int segment, double knuckles_m) {
    const BodyPart part = static_cast<BodyPart>(segment);
    const LimbChain& limb = anatomy.limbs[limb_of_segment(part)];
    const Eigen::Vector3d middle = positions[std::size_t(limb.middle)];
    if (segment_strikes_with_middle(part)) return middle;
    const Eigen::Vector3d extremity = positions[std::size_t(limb.extremity)];
    const Eigen::Vector3d along = extremity - middle;
    return along.norm() > 1e-6 ? Eigen::Vector3d(extremity + knuckles_m * along.normalized()) : extremity;
}

} // namespace

Eigen::Vector3d Strike::striking_point(const CharacterBody& body) const {
    return striking_point_in(body.positions(), body.anatomy(), segment(), m_settings.user_guard.knuckles_past_wrist_m);
}

bool Strike::guard_in_the_way(CharacterBody& body, const UserGuard& guard) {
    // The planned strike played to its contact against the guard as it is now, half a database frame at a time (a
    // kick's arc, cut by chords a frame long, passes under a glove it meets).
    StrikeAdapter& adapter = body.current().adapter;
    if (segment() < 0) return false;
    Eigen::Vector3d previous = Eigen::Vector3d::Zero();
    for (int step = 0; step <= 2 * adapter.contact_index(); ++step) {
        const double index = 0.5 * step;
        adapter.step(index, body.pose());
        const Eigen::Vector3d point = striking_point_in(adapter.positions(), body.anatomy(), segment(), m_settings.user_guard.knuckles_past_wrist_m);
        if (step > 0) {
            const GuardPart met = guard.first_contact(previous, point, m_settings.user_guard.striking_radius_m).part;
            if (met != GuardPart::none) return guard_part_blocks(met);
        }
        previous = point;
    }
    return false;
}

bool Strike::meet_guard(double index, CharacterBody& body, const TrackedUser& user) {
    if (segment() < 0 || !user.tracking() || m_user_block != GuardPart::none || m_met_body || (m_contact_done && m_impact)) return false;
    const Eigen::Vector3d point = striking_point(body);
    const Eigen::Vector3d hit_joint = body.positions()[std::size_t(body.current().adapter.effector_joint())];
    const bool had_path = m_have_path;
    const Eigen::Vector3d from = m_previous_striking_point, joint_from = m_previous_hit_joint;
    m_have_path = true;
    m_previous_striking_point = point;
    m_previous_hit_joint = hit_joint;
    if (!had_path) return false;
    const GuardContact met = user.guard().first_contact(from, point, m_settings.user_guard.striking_radius_m);
    if (met.part == GuardPart::head || met.part == GuardPart::trunk) m_met_body = true;
    if (!guard_part_blocks(met.part)) return false;
    m_user_block = met.part;
    m_block_stop = joint_from + met.share * (hit_joint - joint_from);
    const Eigen::Vector3d to_target = m_plan.target_world - m_block_stop;
    m_block_course = to_target.norm() > 1e-6 ? Eigen::Vector3d(to_target.normalized()) : body.current().adapter.approach_direction();
    hold_off_block(index, body.current().adapter, met.sphere_at_touch, m_block_stop, user.guard());
    return true;
}

void Strike::follow_block(double index, CharacterBody& body, const TrackedUser& user) {
    // Where the part is this frame, from where the striking part was shown last.
    hold_off_block(index, body.current().adapter, striking_point(body), body.positions()[std::size_t(body.current().adapter.effector_joint())], user.guard());
}

double Strike::into_block(const CharacterBody& body, const TrackedUser& user) const {
    const Eigen::Vector3d striking = striking_point(body);
    const double reach = user.guard().radius(m_user_block) + m_settings.user_guard.striking_radius_m;
    return reach - (striking - user.guard().nearest_core(m_user_block, striking)).norm();
}

void Strike::hold_off_block(double index, StrikeAdapter& adapter, const Eigen::Vector3d& striking, const Eigen::Vector3d& hit_joint, const UserGuard& guard) const {
    // The striking part may not pass the plane that touches the blocking part on its side (the stop is that plane,
    // moved from the striking part's centre to the hit joint the adapter holds), nor advance towards its target
    // past where the block first stopped it: a glove that comes on pushes the blow back; one that moves away leaves it
    // where it stopped (its force went into the block).
    const Eigen::Vector3d core = guard.nearest_core(m_user_block, striking);
    Eigen::Vector3d towards = core - striking;
    towards = towards.norm() > 1e-6 ? Eigen::Vector3d(towards.normalized()) : m_block_course;
    const Eigen::Vector3d surface = core - (guard.radius(m_user_block) + m_settings.user_guard.striking_radius_m) * towards;
    adapter.stop_early(index, surface - (striking - hit_joint), towards, m_block_stop, m_block_course);
}

void Strike::held_back(double share) {
    if (share >= 1.0) return;
    m_clock_s = m_clock_before_s + share * (m_clock_s - m_clock_before_s);
    m_over = false;
    // The pose shown stopped short of the contact: it is yet to come (measured where it is shown, not here).
    if (m_contact_now) m_contact_now = m_contact_done = false;
}

void Strike::measure(double t_s, CharacterBody& body, const TrackedUser& user, EventLog& log) {
    // The hit point as the adapter places it: the striking limb's extremity, or its middle joint (knee, elbow).
    const BodyPart part = static_cast<BodyPart>(segment());
    const int limb_index = segment() >= 0 ? limb_of_segment(part) : -1;
    Eigen::Vector3d effector = body.heading().origin;
    if (limb_index >= 0) {
        const LimbChain& limb = body.anatomy().limbs[limb_index];
        effector = body.positions()[std::size_t(segment_strikes_with_middle(part) ? limb.middle : limb.extremity)];
    }
    if (m_contact_now) {
        FighterEvent contact_event = event(FighterEvent::Type::strike, t_s);
        contact_event.contact_error_m = (effector - m_plan.target_world).norm();
        contact_event.head_distance_m = user.tracking() ? (effector - aimed_point(user)).norm() : 1e9;
        contact_event.hit = m_user_block == GuardPart::none && contact_event.head_distance_m <= m_hit_radius_m;
        contact_event.prediction_error_m = user.tracking() ? (aimed_point(user) - m_plan.target_world).norm() : 1e9;
        if (user.tracking()) contact_event.aimed_point_at_contact = aimed_point(user);
        contact_event.range_m = m_purpose.range_m;
        if (m_previous_effector_s >= 0.0 && t_s > m_previous_effector_s) {
            contact_event.effector_speed_mps = (effector - m_previous_effector).norm() / (t_s - m_previous_effector_s);
        }
        log.push(contact_event);
    }
    // From the contact on, while the hit point stays where it stopped (the target, or out of reach the nearest point
    // to it): how long it is held there.
    if (m_contact_now) {
        m_contact_shown_s = t_s;
        m_holding = true;
    }
    else if (m_holding && (effector - body.current().adapter.stop_point()).norm() <= 0.01 && t_s > m_previous_effector_s) m_held_s += t_s - m_previous_effector_s;
    else m_holding = false;
    m_previous_effector = effector;
    m_previous_effector_s = t_s;
}

void Strike::end(double t_s, EventLog& log) {
    FighterEvent end_event = event(FighterEvent::Type::strike_end, t_s);
    end_event.overshoot_m = m_overshoot_m;
    end_event.held_at_target_s = m_held_s;
    end_event.joint_limit_violations = m_violations;
    log.push(end_event);
}

} // namespace kumite
