#include "fighter/strike.h"

#include "kumite/core/joint_limits.h"

#include <algorithm>

namespace kumite {

Strike::Strike(const MotionDatabaseView& db, const FighterSettings& settings)
    : m_db(db), m_hit_radius_m(settings.hit_radius_m), m_steer_until_s(settings.steer_until_s) {}

int Strike::segment() const { return m_plan.clip >= 0 ? m_db.clips[m_plan.clip].segment : -1; }

double Strike::try_plan(const RetrievalResult& found, const Eigen::Vector3d& target, const MirFrame& from, CharacterBody& body) {
    if (!found.found) return 1e9;
    m_plan = {found.clip, found.start_frame, found.contact_frame, found.clip_to_world, target};
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
    m_contact_now = false;
    m_over = false;
    m_overshoot_m = 0.0;
    m_held_s = 0.0;
    m_holding = false;
    m_violations = 0;
    m_impact = true;
    m_previous_effector_s = -1.0;
    m_planned_target = m_plan.target_world;
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
    return event;
}

void Strike::steer(double to_contact_s, CharacterBody& body, const TrackedUser& user) {
    // Predicted aim: the target follows the head until steer_until_s before the contact.
    if (m_steer_until_s <= 0.0 || m_purpose.aim != FighterAim::predicted || !user.tracking() || !user.motion().ready()) return;
    if (m_contact_done || to_contact_s <= m_steer_until_s) return;
    const Eigen::Vector3d target = user.motion().predict(to_contact_s) - Eigen::Vector3d(0.0, m_purpose.drop_m, 0.0);
    body.current().adapter.retarget(target);
    m_plan.target_world = target;
}

void Strike::play(double t_s, CharacterBody& body, const TrackedUser& user) {
    StrikeAdapter& adapter = body.current().adapter;
    // Frames of the database's rate, as a fractional index; the contact frame is played exactly.
    m_clock_before_s = m_clock_s;
    m_clock_s += t_s - m_last_play_s;
    m_last_play_s = t_s;
    double index = m_clock_s / m_db.meta.frame_time_s;
    const double contact = adapter.contact_index();
    // The database's frame time is a float: a frame landing on the contact can come out a few 1e-7 short of it.
    if (!m_contact_done && index >= contact - 1e-4) index = contact;
    index = std::min(index, double(adapter.frame_count() - 1));
    // At the contact: a head still at the latched target takes the impact (the strike stops there); a dodged
    // strike follows through from this frame on.
    const bool at_contact = !m_contact_done && index >= contact;
    steer((contact - index) * m_db.meta.frame_time_s, body, user);
    if (at_contact) {
        m_impact = user.tracking() && (aimed_point(user) - m_plan.target_world).norm() <= m_hit_radius_m;
        adapter.set_impact(m_impact);
    }
    const AdaptedFrame frame = adapter.step(index, body.pose());
    body.show_adapter();
    m_overshoot_m = std::max(m_overshoot_m, frame.past_target_m);
    m_violations += joint_violation_count(frame.joint_violations);
    body.encode(body.mir()); // what the defence's edits start from
    m_contact_now = at_contact;
    if (at_contact) m_contact_done = true;
    m_over = index >= adapter.frame_count() - 1;
}

void Strike::held_back(double share) {
    if (share >= 1.0) return;
    m_clock_s = m_clock_before_s + share * (m_clock_s - m_clock_before_s);
    m_over = false;
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
        contact_event.hit = contact_event.head_distance_m <= m_hit_radius_m;
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
    if (m_contact_now) m_holding = true;
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
