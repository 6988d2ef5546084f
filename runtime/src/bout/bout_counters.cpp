// The report's counters fed one event at a time (bout_counters.h).
#include "kumite/runtime/bout_counters.h"

#include "kumite/runtime/joint_speeds.h"

#include <algorithm>
#include <cmath>

namespace kumite {

void BoutCounters::tally(const FighterEvent& event, long long frame, const MotionDatabaseView& database, FighterTally& fighter) {
    switch (event.type) {
    case FighterEvent::Type::order:
        ++orders;
        own_attacks += event.own && event.blow == 0;
        fighter.order_frame = frame;
        break;
    case FighterEvent::Type::ignored_order: ++ignored_orders; break;
    case FighterEvent::Type::order_queued:
        ++orders;
        own_attacks += event.own && event.blow == 0;
        ++orders_queued;
        break;
    case FighterEvent::Type::order_performed: ++orders_performed; break;
    case FighterEvent::Type::order_expired: ++orders_expired; break;
    case FighterEvent::Type::state:
        fighter.state = event.state;
        if (event.state == FighterState::strike && fighter.order_frame >= 0) {
            command_to_strike_frames.add(double(frame - fighter.order_frame));
            fighter.order_frame = -1;
        }
        break;
    case FighterEvent::Type::strike:
        ++strikes;
        (event.hit ? hits : misses) += 1;
        blocked_by_user += event.user_block != GuardPart::none;
        last_contact_error_m = event.contact_error_m;
        last_hit = event.hit;
        if (event.combination >= 0 && event.combination < int(combination_strikes.size()) && event.blow >= 0 && event.blow < 2) {
            ++combination_strikes[std::size_t(event.combination)][std::size_t(event.blow)];
            combination_hits[std::size_t(event.combination)][std::size_t(event.blow)] += event.hit;
        }
        contact_speed_mps.add(event.effector_speed_mps);
        if (event.clip >= 0 && event.clip < static_cast<int>(database.clips.size())) {
            const int segment = database.clips[event.clip].segment;
            if (segment >= 0 && segment < k_body_part_count) {
                const int kind = int(strike_move_kind(static_cast<BodyPart>(segment))) - int(MoveKind::punch);
                contact_speed_by_kind_mps[std::size_t(kind)].add(event.effector_speed_mps);
            }
        }
        if (event.clip >= 0 && event.clip < static_cast<int>(by_clip.size())) {
            by_clip[event.clip][0] += 1;
            by_clip[event.clip][1] += event.hit;
        }
        if (event.prediction_error_m < 1e8) prediction_error_m.add(event.prediction_error_m);
        (event.aim == FighterAim::predicted ? predicted_strikes : latched_strikes) += 1;
        (event.aim == FighterAim::predicted ? predicted_hits : latched_hits) += event.hit;
        break;
    case FighterEvent::Type::user_strike:
        ++user_strikes;
        blocks += is_block(event.user_strike.move);
        block_clips += event.user_strike.move == DefenceMove::block_clip;
        slips += event.user_strike.move == DefenceMove::slip;
        break;
    case FighterEvent::Type::user_strike_end:
        switch (event.user_strike.outcome) {
        case UserStrikeOutcome::blocked: ++blocked; break;
        case UserStrikeOutcome::slipped:
            ++slipped;
            slipped_on_course += event.user_strike.unslipped_clearance_m <= 0.0;
            break;
        case UserStrikeOutcome::hit_by_user: ++hit_by_user; break;
        case UserStrikeOutcome::missed: ++user_missed; break;
        }
        ++user_outcomes_by_target[event.user_strike.at_head ? 0 : 1][static_cast<int>(event.user_strike.outcome)];
        ++user_outcomes_by_fighter_state[static_cast<std::size_t>(fighter.state)][static_cast<int>(event.user_strike.outcome)];
        if (event.user_strike.forearm_to_path_m >= 0.0) forearm_to_path_m.add(event.user_strike.forearm_to_path_m);
        if (event.user_strike.move_after_seen_s >= 0.0) defence_move_after_seen_s.add(event.user_strike.move_after_seen_s);
        not_defended += event.user_strike.detected && !event.user_strike.defended;
        if (event.user_strike.wrist_mps >= 0.0) blocking_wrist_mps.add(event.user_strike.wrist_mps);
        if (event.user_strike.elbow_mps >= 0.0) blocking_elbow_mps.add(event.user_strike.elbow_mps);
        if (const UserStrikeEvent& block = event.user_strike; block.arm_from_shoulder_mps >= 0.0) {
            if (block.move == DefenceMove::synthesized) synthesized_arm_from_shoulder_mps.add(block.arm_from_shoulder_mps);
            if (block.move == DefenceMove::block_clip) {
                block_clip_arm_from_shoulder_mps.add(block.arm_from_shoulder_mps);
                if (block.clip_arm_from_shoulder_mps > 0.0) block_clip_speed_ratio.add(block.arm_from_shoulder_mps / block.clip_arm_from_shoulder_mps);
            }
        }
        defence_joint_limit_violations += event.joint_limit_violations;
        defence_foot_shift_m = std::max(defence_foot_shift_m, event.foot_shift_m);
        break;
    case FighterEvent::Type::user_strike_course:
        blocked_on_course += event.user_strike.unblocked_clearance_m <= 0.0;
        break;
    case FighterEvent::Type::hit_reaction:
        ++hit_reactions;
        hit_reaction_blows += event.reaction_blows;
        if (event.clip >= 0) {
            ++captured_hit_reactions;
            const double angle_deg = std::acos(std::clamp(event.reaction_fit, -1.0, 1.0)) * 180.0 / 3.14159265358979;
            hit_reaction_angle_deg.add(std::max(1e-2, angle_deg));
        }
        hit_reaction_delay_s.add(event.reaction_delay_s);
        break;
    case FighterEvent::Type::strike_end:
        (event.impact ? impacts : follow_throughs) += 1;
        if (event.impact) impact_overshoot_m.add(event.overshoot_m);
        if (event.impact) impact_held_s.add(event.held_at_target_s);
        joint_limit_violations += event.joint_limit_violations;
        break;
    case FighterEvent::Type::user_response: {
        const int segment = event.clip >= 0 && event.clip < static_cast<int>(database.clips.size()) ? database.clips[event.clip].segment : -1;
        if (segment < 0 || segment >= k_body_part_count) break;
        Responses& r = responses_by_kind[std::size_t(int(strike_move_kind(static_cast<BodyPart>(segment))) - int(MoveKind::punch))];
        const UserResponse& response = event.response;
        ++r.blows;
        r.moved += response.moved;
        r.countered += response.countered;
        r.counters_landed += response.counter_landed;
        ++r.kinds[std::size_t(response.kind)];
        ++r.quality[std::size_t(response.quality)];
        if (response.moved && response.visible_s >= 0.0) {
            if (response.response_time_s < 0.0) ++r.anticipated;
            else r.time_s.add(response.response_time_s);
        }
        break;
    }
    default: break;
    }
}

} // namespace kumite
