// The fighter's answer to a user strike (defence.h): a block planned onto the fist's course (which arm, where, when)
// or a slip off its line, the ramp that brings it in at a person's speed, and a captured block taking over.
#include "kumite/runtime/defence.h"

#include "kumite/core/smoothstep.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace kumite {

void Defence::cancel_move() {
    m_move = DefenceMove::none;
    m_move_hand = -1;
    m_weight = 0.0;
}

bool Defence::block_plan(const Hand& hand, const DefenderBody& body, double time_to_impact, const std::array<bool, 2>& arms,
                         Eigen::Vector3d& wrist_target, int& arm, double& meeting_s, bool nearer) const {
    const double speed = hand.velocity.norm();
    // The fighter's arm on the side the hand comes from first (+X of its heading frame is its left), then the other.
    const int near_arm = body.heading.to_heading(hand.position).x() >= 0.0 ? 0 : 1;
    for (const int candidate : {near_arm, 1 - near_arm}) {
        if (!arms[candidate]) continue;
        // Where the forearm meets the course: block_before_m short of the target, else half that (more time).
        for (const double before : {m_block_before_m, nearer ? 0.5 * m_block_before_m : m_block_before_m}) {
            const double intercept_s = time_to_impact - before / speed;
            const Eigen::Vector3d intercept = hand.position + hand.velocity * std::max(0.0, intercept_s);
            const double travel = (intercept - body.wrist[candidate]).norm();
            const bool within_arm = (intercept - body.shoulder[candidate]).norm() <= 0.95 * body.arm_length[candidate];
            if (intercept_s > 0.02 && within_arm && travel / intercept_s <= m_settings.max_block_speed_mps) {
                wrist_target = intercept;
                arm = candidate;
                meeting_s = intercept_s;
                return true;
            }
        }
    }
    return false;
}

bool Defence::block_is_over() const {
    return m_settings.hand_over_blocks && is_block(m_move) && m_move_hand >= 0 && !m_hands[m_move_hand].striking;
}

bool Defence::defends_next() {
    ++m_threats;
    if (m_settings.defend_share >= 1.0) return true;
    const double spread = double(m_threats) * 0.6180339887498949;
    return spread - std::floor(spread) < m_settings.defend_share;
}

void Defence::start_due_move(double t_s, Hand& hand, const DefenderBody& body, const Allowed& allowed) {
    hand.move_due_s = -1.0;
    if (!allowed.any() || !(m_move == DefenceMove::none || block_is_over())) return;
    // The time it has left: its course now, to the part it was aimed at.
    const double speed = hand.velocity.norm();
    if (speed < 1e-6) return;
    const Eigen::Vector3d to_part = (hand.strike.at_head ? body.head : body.chest) - hand.position;
    const double arrival = to_part.dot(hand.velocity) / (speed * speed);
    // Still coming, as a threat is (horizon_s): a hand that stopped short of the fighter meanwhile (a glove held
    // out) would give the move a hold of seconds, and the fighter would take no order while it lasted.
    if (arrival > 0.0 && arrival <= m_settings.horizon_s) start_move(t_s, hand, body, arrival, allowed);
}

void Defence::start_move(double t_s, Hand& hand, const DefenderBody& body, double time_to_impact, const Allowed& allowed) {
    // A block handed over (block_is_over): the same arm goes on from the weight it has.
    const bool was_blocking = is_block(m_move);
    const int was_arm = m_arm;
    const double was_weight = m_weight;
    Eigen::Vector3d wrist_target;
    int arm = 0;
    m_block_before_m = m_settings.block_before_m;
    m_time_to_impact_s = time_to_impact;
    double meeting_s = 0.0;
    if (block_plan(hand, body, time_to_impact, allowed.block_arms, wrist_target, arm, meeting_s)) {
        m_move = DefenceMove::synthesized;
        m_arm = arm;
        m_wrist_target = wrist_target;
        m_intercept_s = std::max(0.02, meeting_s); // at block_before_m, or nearer when that left too little time
        m_block_travel_m = (wrist_target - body.wrist[arm]).norm();
        // In place a little before the hand, at a person's speed: up to all the time there is.
        m_ramp_s = std::max({0.03, 0.6 * m_intercept_s, std::min(shortest_ramp_s(m_block_travel_m), 0.95 * m_intercept_s)});
        m_block_started = true;
    } else if (allowed.slip) {
        // Off the line: from the course's closest point to the head, sideways; straight at the head, to the side
        // the course does not favour.
        const Eigen::Vector3d closest = hand.position + hand.velocity * time_to_impact;
        Eigen::Vector3d away = body.head - closest;
        away.y() = 0.0;
        if (away.norm() < 0.03) {
            away = Eigen::Vector3d::UnitY().cross(hand.velocity);
            away.y() = 0.0;
        }
        m_move = DefenceMove::slip;
        m_slip_offset = away.norm() > 1e-9 ? Eigen::Vector3d(away.normalized() * m_settings.slip_m) : Eigen::Vector3d(m_settings.slip_m, 0.0, 0.0);
        m_ramp_s = std::max(0.03, 0.8 * time_to_impact);
    } else {
        return; // no arm gets there, and the trunk may not lean: taken as it comes
    }
    m_move_start_s = t_s;
    m_ramp_start_s = t_s;
    m_ramp_from = was_blocking && is_block(m_move) && was_arm == m_arm ? was_weight : 0.0;
    m_hold_until_s = t_s + time_to_impact + m_settings.hold_s;
    m_move_hand = static_cast<int>(&hand - m_hands.data());
    hand.strike.move = m_move;
    hand.strike.arm = m_arm;
    hand.strike.moved_s = t_s;
    hand.strike.move_after_seen_s = t_s - hand.strike.t_s;
}

void Defence::use_block_clip(int clip, double clip_arm_from_shoulder_mps, double ramp_s, double before_m) {
    if (m_move != DefenceMove::synthesized || m_move_hand < 0) return;
    m_move = DefenceMove::block_clip;
    m_ramp_s = ramp_s;
    m_block_before_m = before_m;
    double time_s = 0.0;
    course_point(m_block_before_m, m_wrist_target, time_s);
    m_intercept_s = std::max(0.02, time_s);
    UserStrikeEvent& strike = m_hands[m_move_hand].strike;
    strike.move = DefenceMove::block_clip;
    strike.block_clip = clip;
    strike.clip_arm_from_shoulder_mps = clip_arm_from_shoulder_mps;
    // The strike's event of this frame says so too.
    for (int e = 0; e < m_event_count; ++e) {
        UserStrikeEvent& event = m_events[e];
        if (!event.ended && event.hand == strike.hand && event.t_s == strike.t_s) event = strike;
    }
}

bool Defence::course_point(double before_m, Eigen::Vector3d& point, double& time_s) const {
    if (m_move_hand < 0) return false;
    const Hand& hand = m_hands[m_move_hand];
    const double speed = hand.velocity.norm();
    if (speed < 1e-6) return false;
    time_s = m_time_to_impact_s - before_m / speed;
    point = hand.position + hand.velocity * std::max(0.0, time_s);
    return time_s > 0.02;
}

double Defence::time_to_block_point() const {
    if (m_move_hand < 0) return 0.0;
    const Hand& hand = m_hands[m_move_hand];
    const double speed_squared = hand.velocity.squaredNorm();
    return speed_squared > 1e-9 ? std::max(0.0, (m_wrist_target - hand.position).dot(hand.velocity) / speed_squared) : 0.0;
}

void Defence::note_arm_speed(double from_shoulder_mps, double wrist_mps, double elbow_mps) {
    if (!is_block(m_move) || m_move_hand < 0 || !m_hands[m_move_hand].striking) return;
    UserStrikeEvent& strike = m_hands[m_move_hand].strike;
    strike.arm_from_shoulder_mps = std::max(strike.arm_from_shoulder_mps, from_shoulder_mps);
    strike.wrist_mps = std::max(strike.wrist_mps, wrist_mps);
    strike.elbow_mps = std::max(strike.elbow_mps, elbow_mps);
}

double Defence::shortest_ramp_s(double travel_m) const {
    // A smoothstep over T covers `travel_m` at 1.5 travel / T at its fastest.
    return m_settings.max_block_wrist_mps > 0.0 ? 1.5 * travel_m / m_settings.max_block_wrist_mps : 0.0;
}

double Defence::ramp_weight(double t_s) const { return m_ramp_from + (1.0 - m_ramp_from) * smoothstep((t_s - m_ramp_start_s) / m_ramp_s); }

} // namespace kumite
