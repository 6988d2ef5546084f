// The defence's eyes (defence.h): the user's hands followed frame by frame, their strikes seen coming and how
// each ends (blocked, slipped, hit_by_user, missed), and the move's weight over time. The move itself (block or
// slip, planned and ramped) is in defence_move.cpp; the tests of where a path meets the body in defence_contacts.cpp.
#include "kumite/runtime/defence.h"

#include "kumite/core/smoothstep.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace kumite {

const char* defence_move_name(DefenceMove move) {
    switch (move) {
    case DefenceMove::none: return "none";
    case DefenceMove::synthesized: return "synthesized";
    case DefenceMove::block_clip: return "block_clip";
    case DefenceMove::slip: return "slip";
    }
    return "?";
}

const char* user_strike_outcome_name(UserStrikeOutcome outcome) {
    switch (outcome) {
    case UserStrikeOutcome::blocked: return "blocked";
    case UserStrikeOutcome::slipped: return "slipped";
    case UserStrikeOutcome::hit_by_user: return "hit_by_user";
    case UserStrikeOutcome::missed: return "missed";
    }
    return "?";
}

void Defence::reset() {
    for (Hand& hand : m_hands) {
        if (hand.watching) end_watch(hand);
        hand = Hand{};
    }
    m_move = DefenceMove::none;
    m_move_hand = -1;
    m_weight = 0.0;
}

void Defence::push(const UserStrikeEvent& event) {
    if (m_event_count < static_cast<int>(m_events.size())) m_events[m_event_count++] = event;
}

void Defence::watch_blocked(double t_s, Hand& hand, const Eigen::Vector3d& before, const Eigen::Vector3d& now, const DefenderBody& body) {
    constexpr double k_watch_s = 0.3;
    UserStrikeEvent& event = hand.watched;
    event.unblocked_clearance_m = std::min(event.unblocked_clearance_m, body_clearance(before, now, body));
    hand.watch_receding_frames = hand.velocity.dot(body.chest - now) < 0.0 ? hand.watch_receding_frames + 1 : 0;
    if (hand.watch_receding_frames >= 3 || t_s - event.t_s >= k_watch_s) {
        event.t_s = t_s;
        end_watch(hand);
    }
}

void Defence::end_watch(Hand& hand) {
    hand.watching = false;
    hand.watched.ended = false;
    hand.watched.course_followed = true;
    push(hand.watched);
}

void Defence::follow_closing(Hand& hand, double before_s, const Eigen::Vector3d& before, const Eigen::Vector3d& now, double dt_s, const DefenderBody& body) {
    constexpr double k_closing_mps = 0.5; // slower is a hand held or drifting, not yet a blow's approach
    for (int part = 0; part < 2; ++part) {
        const Eigen::Vector3d& centre = part == 0 ? body.head : body.chest;
        const double closing_mps = ((centre - before).norm() - (centre - now).norm()) / dt_s;
        double& since = hand.closing_since_s[part];
        since = closing_mps >= k_closing_mps ? (since < 0.0 ? before_s : since) : -1.0;
    }
}

double Defence::approach_time(const Hand& hand, double t_s, int part) {
    const double since = hand.closing_since_s[part];
    return since >= 0.0 ? t_s - since : -1.0;
}

void Defence::end_strike(double t_s, Hand& hand, UserStrikeOutcome outcome) {
    UserStrikeEvent event = hand.strike;
    event.ended = true;
    event.t_s = t_s;
    event.outcome = outcome;
    event.hand_velocity = hand.velocity;
    event.peak_speed_mps = hand.peak_speed_mps;
    event.forearm_to_path_m = is_block(event.move) ? hand.closest_forearm_m : -1.0;
    push(event);
    if (hand.watching) end_watch(hand); // an earlier block's, still followed
    if (outcome == UserStrikeOutcome::blocked) {
        hand.watching = true;
        hand.watched = event;
        hand.watch_receding_frames = 0;
    }
    hand.striking = false;
    hand.move_due_s = -1.0;
    hand.armed = false;
    // A hand that met the fighter or a forearm stays on it a moment: not a new strike until it has left.
    hand.touching = outcome == UserStrikeOutcome::blocked || outcome == UserStrikeOutcome::hit_by_user;
}

void Defence::update(double t_s, const UserHands& hands, const DefenderBody& body, const Allowed& allowed) {
    m_block_started = false;
    const double shown_slip_weight = slip_weight(); // the lean `body` shows: last frame's
    // The move's weight: in over its ramp, held until after the hand's arrival, then out.
    if (m_move != DefenceMove::none) {
        if (t_s <= m_hold_until_s) {
            m_weight = ramp_weight(t_s);
        } else {
            const double out = smoothstep((t_s - m_hold_until_s) / m_settings.release_s);
            m_weight = std::min(m_weight, 1.0 - out);
            if (out >= 1.0) {
                m_move = DefenceMove::none;
                m_weight = 0.0;
            }
        }
    }
    for (int side = 0; side < 2; ++side) {
        Hand& hand = m_hands[side];
        if (!hands.present[side]) {
            if (hand.striking) end_strike(t_s, hand, hand.strike.move == DefenceMove::slip ? UserStrikeOutcome::slipped : UserStrikeOutcome::missed);
            if (hand.watching) end_watch(hand);
            hand.seen = false;
            continue;
        }
        const Eigen::Vector3d now = hands.world[side];
        // A hand that jumps further in one sample than a fist flies (a tracker glitch, a recording that loops)
        // starts a new track: its jump is not a strike.
        const bool jumped = hand.seen && (now - hand.position).norm() > m_settings.max_hand_speed_mps * std::max(t_s - hand.last_s, 1.0 / 120.0);
        if (jumped && hand.striking) end_strike(t_s, hand, hand.strike.move == DefenceMove::slip ? UserStrikeOutcome::slipped : UserStrikeOutcome::missed);
        if (!hand.seen || t_s - hand.last_s > 0.25 || jumped) {
            if (hand.watching) end_watch(hand);
            hand = Hand{};
            hand.seen = true;
            hand.position = now;
            hand.last_s = t_s;
            continue;
        }
        const double dt = t_s - hand.last_s;
        if (dt <= 1e-6) continue;
        const Eigen::Vector3d before = hand.position;
        hand.velocity = 0.3 * hand.velocity + 0.7 * (now - before) / dt;
        hand.position = now;
        hand.last_s = t_s;
        if (hand.watching) watch_blocked(t_s, hand, before, now, body);
        follow_closing(hand, t_s - dt, before, now, dt, body);

        if (hand.striking) {
            hand.peak_speed_mps = std::max(hand.peak_speed_mps, hand.velocity.norm());
            if (hand.move_due_s >= 0.0 && t_s >= hand.move_due_s) start_due_move(t_s, hand, body, allowed);
            // Its path this frame against the blocking forearm, the head and the chest.
            const bool blocking = is_block(m_move) && m_move_hand == side;
            if (blocking && hand.velocity.norm() >= m_settings.reaim_min_speed_mps) {
                // The course is known better each frame (the first estimate mixes in the draw back): re-aim.
                const Eigen::Vector3d target = hand.strike.at_head ? body.head : body.chest;
                const double speed = hand.velocity.norm();
                const double arrival = (target - now).dot(hand.velocity) / (speed * speed);
                Eigen::Vector3d wrist_target;
                int arm = 0;
                std::array<bool, 2> same_arm{};
                same_arm[m_arm] = true;
                // A captured block keeps its meeting point's distance: nearer, it would follow a fist that got past
                // it into the chest (the forearm inside the torso).
                double meeting_s = 0.0;
                if (arrival > 0.0 && block_plan(hand, body, arrival, same_arm, wrist_target, arm, meeting_s, m_move == DefenceMove::synthesized))
                    m_wrist_target = wrist_target;
                // The first estimate of its speed mixes in the draw back too: a fist faster than first seen reaches
                // the meeting point sooner, and the forearm, shown from the next frame on, has to be there a frame
                // before it. The ramp starts again from where it is, to end then.
                const double to_meeting_s = (m_wrist_target - now).dot(hand.velocity) / (speed * speed) - dt;
                const double ramp_end_s = m_ramp_start_s + m_ramp_s;
                // Never faster than a person's wrist: what is left of the way at its fastest (it arrives late).
                if (m_weight < 1.0 && t_s + to_meeting_s < ramp_end_s) {
                    m_ramp_from = m_weight;
                    m_ramp_start_s = t_s - dt; // this frame's weight is already a step in
                    m_ramp_s = std::max({dt, to_meeting_s + dt, shortest_ramp_s((1.0 - m_weight) * m_block_travel_m)});
                    m_weight = ramp_weight(t_s);
                }
            }
            if (m_move == DefenceMove::slip && m_move_hand == side) {
                const Eigen::Vector3d lean = shown_slip_weight * m_slip_offset;
                const Eigen::Vector3d part = hand.strike.at_head ? Eigen::Vector3d(body.head - lean) : Eigen::Vector3d(body.chest - 0.5 * lean);
                const double radius = hand.strike.at_head ? m_settings.head_radius_m : m_settings.chest_radius_m;
                hand.strike.unslipped_clearance_m = std::min(hand.strike.unslipped_clearance_m, segment_distance(before, now, part, part) - radius);
            }
            if (blocking) {
                const double to_forearm = segment_distance(before, now, body.elbow[m_arm], body.wrist[m_arm]);
                hand.closest_forearm_m = std::min(hand.closest_forearm_m, to_forearm);
            }
            // Any forearm on the path stops it: the blocking one, or the other held in the guard.
            if (const int arm = forearm_met(before, now, body); arm >= 0) {
                hand.strike.blocking_arm = arm;
                hand.strike.unblocked_clearance_m = course_clearance(before, hand.velocity, body);
                hand.strike.approach_s = approach_time(hand, t_s, hand.strike.at_head ? 0 : 1);
                end_strike(t_s, hand, UserStrikeOutcome::blocked);
                continue;
            }
            if (body_met(before, now, body)) {
                hand.strike.approach_s = approach_time(hand, t_s, met_part(before, now, body));
                end_strike(t_s, hand, UserStrikeOutcome::hit_by_user);
                continue;
            }
            const bool receding = hand.velocity.dot(body.chest - now) < 0.0;
            hand.receding_frames = receding ? hand.receding_frames + 1 : 0;
            if (hand.receding_frames >= 3 || t_s - hand.strike.t_s > 1.0) {
                end_strike(t_s, hand, hand.strike.move == DefenceMove::slip ? UserStrikeOutcome::slipped : UserStrikeOutcome::missed);
            }
            continue;
        }
        // A hand that meets the fighter without having been seen coming: a strike that arrived, counted once until
        // the hand has left (a blocked one too, when a forearm was on its way). The thrust must be a new one: a
        // hand whose strike just ended (blocked: in the room the forearm stopped it) has to slow down first.
        const double speed = hand.velocity.norm();
        const int forearm = forearm_met(before, now, body);
        const bool met = forearm >= 0 || body_met(before, now, body);
        if (!hand.armed) hand.armed = speed < m_settings.min_speed_mps;
        // Closing in on what it meets (the nearer of head and chest) at a striking speed, not drawing back from it.
        const Eigen::Vector3d& part = (now - body.head).norm() < (now - body.chest).norm() ? body.head : body.chest;
        const double closing_mps = (part - before).norm() > 1e-9 ? hand.velocity.dot((part - before).normalized()) : 0.0;
        if (met && hand.armed && !hand.touching && closing_mps >= m_settings.contact_speed_mps) {
            hand.touching = true;
            hand.strike = UserStrikeEvent{};
            hand.strike.t_s = t_s;
            hand.strike.hand = side;
            hand.strike.at_head = (now - body.head).norm() < (now - body.chest).norm();
            hand.strike.hand_speed_mps = speed;
            hand.strike.detected = false;
            hand.strike.blocking_arm = forearm;
            hand.strike.approach_s = approach_time(hand, t_s, forearm >= 0 ? (hand.strike.at_head ? 0 : 1) : met_part(before, now, body));
            hand.peak_speed_mps = speed;
            if (forearm >= 0) hand.strike.unblocked_clearance_m = course_clearance(before, hand.velocity, body);
            push(hand.strike);
            end_strike(t_s, hand, forearm >= 0 ? UserStrikeOutcome::blocked : UserStrikeOutcome::hit_by_user);
            continue;
        }
        if (hand.touching) {
            // Still on the fighter (10 cm of margin): the same strike.
            const double margin = 0.1;
            hand.touching = (now - body.head).norm() < m_settings.head_radius_m + margin ||
                            (now - body.chest).norm() < m_settings.chest_radius_m + margin ||
                            segment_distance(now, now, body.elbow[0], body.wrist[0]) < m_settings.block_contact_m + margin ||
                            segment_distance(now, now, body.elbow[1], body.wrist[1]) < m_settings.block_contact_m + margin;
            continue;
        }
        // A threat: a fast hand whose straight course passes near the head or chest soon (one strike per thrust;
        // armed again once the thrust is over: a blocked hand, in the room, stops).
        if (!hand.armed) continue;
        if (speed < m_settings.min_speed_mps) continue;
        double best_miss = m_settings.threat_radius_m, best_time = 0.0;
        int aimed = -1; // 0 head, 1 chest
        for (int part = 0; part < 2; ++part) {
            const Eigen::Vector3d to_part = (part == 0 ? body.head : body.chest) - now;
            const double arrival = to_part.dot(hand.velocity) / (speed * speed);
            if (arrival <= 0.0 || arrival > m_settings.horizon_s) continue;
            const double miss = (to_part - hand.velocity * arrival).norm();
            if (miss <= best_miss) best_miss = miss, best_time = arrival, aimed = part;
        }
        if (aimed < 0) continue;
        // Before this hand counts as striking again: the block of its own last blow may be the one handed over (a
        // double jab).
        const bool free_to_move = m_move == DefenceMove::none || block_is_over();
        const bool defended = defends_next();
        hand.striking = true;
        hand.closest_forearm_m = 1e9;
        hand.receding_frames = 0;
        hand.strike = UserStrikeEvent{};
        hand.strike.t_s = t_s;
        hand.strike.hand = side;
        hand.strike.at_head = aimed == 0;
        hand.strike.time_to_impact_s = best_time;
        hand.strike.hand_speed_mps = speed;
        hand.peak_speed_mps = speed;
        hand.strike.defended = defended;
        if (m_settings.enabled && defended && m_settings.reaction_delay_s > 0.0) hand.move_due_s = t_s + m_settings.reaction_delay_s;
        else if (m_settings.enabled && defended && allowed.any() && free_to_move) start_move(t_s, hand, body, best_time, allowed);
        push(hand.strike);
    }
}

} // namespace kumite
