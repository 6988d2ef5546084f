// A bout's event as one JSON object (bout_event_json.h): the lines of `kumite play --events`, the C API's events.

#include "kumite/runtime/bout_event_json.h"

#include "kumite/runtime/combinations.h"

#include <nlohmann/json.hpp>

namespace kumite {

namespace {

const char* side_text(Side side) { return side == Side::left ? "left" : side == Side::right ? "right" : "any"; }
// An order's kind or height: "any" when it named none.
const char* label_text(const char* name) { return std::string_view(name) == "none" ? "any" : name; }
nlohmann::json xyz(const Eigen::Vector3d& point) { return {point.x(), point.y(), point.z()}; }

// An order's combination and blow, and whether the fighter chose it, where they apply.
void add_order_origin(nlohmann::json& line, const FighterEvent& event) {
    if (event.combination >= 0 && event.combination < int(combinations().size())) {
        line["combination"] = combinations()[std::size_t(event.combination)].name;
        line["blow"] = event.blow + 1;
    }
    if (event.own) line["own"] = true;
}

nlohmann::json event_object(const Bout& bout, const BoutEvent& bout_event) {

    const FighterEvent& event = bout_event.event;
    nlohmann::json line = {{"t", event.t_s}, {"type", fighter_event_name(event.type)}, {"fighter", bout_event.fighter}};
    const Retriever& retriever = bout.retriever();
    if (const CaptureUser* capture = bout.tracker().capture()) line["capture_s"] = capture->capture_time_s();
    switch (event.type) {
    case FighterEvent::Type::order:
    case FighterEvent::Type::order_queued:
    case FighterEvent::Type::order_performed:
    case FighterEvent::Type::order_expired:
        line["command"] = retriever.semantics_name(event.semantics);
        line["side"] = side_text(event.side);
        line["kind"] = label_text(strike_kind_name(event.kind));
        line["height"] = label_text(strike_height_name(event.height));
        if (event.type == FighterEvent::Type::order_performed || event.type == FighterEvent::Type::order_expired) line["waited_s"] = event.waited_s;
        if (event.type == FighterEvent::Type::order_expired) line["why"] = event.why;
        add_order_origin(line, event);
        break;
    case FighterEvent::Type::ignored_order:
        line["why"] = event.why;
        if (event.semantics >= 0) line["command"] = retriever.semantics_name(event.semantics);
        line["side"] = side_text(event.side);
        line["kind"] = label_text(strike_kind_name(event.kind));
        line["height"] = label_text(strike_height_name(event.height));
        add_order_origin(line, event);
        break;
    case FighterEvent::Type::state: line["state"] = fighter_state_name(event.state); break;
    case FighterEvent::Type::strike:
        line["result"] = event.user_block != GuardPart::none ? "blocked" : event.hit ? "hit" : "miss";
        if (event.user_block != GuardPart::none) line["blocked_by"] = guard_part_name(event.user_block);
        line["contact_error_m"] = event.contact_error_m;
        line["head_distance_m"] = event.head_distance_m;
        line["range_m"] = event.range_m;
        line["clip"] = bout.database().string(bout.database().clips[event.clip].name);
        line["command"] = bout.database().string(bout.database().clips[event.clip].semantics);
        line["kind"] = strike_kind_name(bout.database().clips[event.clip].strike_kind());
        line["height"] = strike_height_name(bout.database().clips[event.clip].strike_height());
        line["clip_side"] = side_text(static_cast<Side>(bout.database().clips[event.clip].side));
        line["ordered"] = {{"side", side_text(event.side)}, {"kind", label_text(strike_kind_name(event.kind))},
                           {"height", label_text(strike_height_name(event.height))}};
        line["varied"] = event.varied;
        line["effector_speed_at_contact_mps"] = event.effector_speed_mps;
        line["outcome"] = event.impact ? "impact" : "follow_through";
        line["aim"] = fighter_aim_name(event.aim);
        line["target"] = xyz(event.target);
        line["head_speed_mps"] = event.head_speed_mps;
        line["prediction_error_m"] = event.prediction_error_m;
        if (event.aimed_point_at_contact) line["aimed_point_at_contact"] = xyz(*event.aimed_point_at_contact);
        line["retrieval_offset_m"] = event.retrieval_offset_m;
        line["steered_m"] = event.steered_m;
        line["speedup"] = event.speedup;
        line["target_part"] = target_part_name(event.target_part);
        line["reachable"] = event.reachable;
        add_order_origin(line, event);
        break;
    case FighterEvent::Type::user_response: {
        // The blow as its strike event told it, then the user's answer.
        const DbClip& clip = bout.database().clips[event.clip];
        const UserResponse& r = event.response;
        line["command"] = bout.database().string(clip.semantics);
        line["kind"] = strike_kind_name(clip.strike_kind());
        line["height"] = strike_height_name(clip.strike_height());
        line["clip_side"] = side_text(static_cast<Side>(clip.side));
        line["target_part"] = target_part_name(event.target_part);
        line["result"] = event.user_block != GuardPart::none ? "blocked" : event.hit ? "hit" : "miss";
        if (event.user_block != GuardPart::none) line["blocked_by"] = guard_part_name(event.user_block);
        add_order_origin(line, event);
        line["began_s"] = r.began_s;
        line["visible_s"] = r.visible_s >= 0.0 ? nlohmann::json(r.visible_s) : nlohmann::json(nullptr);
        line["contact_s"] = r.contact_s;
        line["response"] = response_kind_name(r.kind);
        line["moved"] = r.moved;
        line["response_s"] = r.moved ? nlohmann::json(r.response_s) : nlohmann::json(nullptr);
        line["response_time_s"] = r.response_time_s >= 0.0 || (r.moved && r.visible_s >= 0.0) ? nlohmann::json(r.response_time_s) : nlohmann::json(nullptr);
        line["quality"] = response_quality_name(r.quality);
        line["countered"] = r.countered;
        if (r.countered) {
            line["counter_s"] = r.counter_s;
            line["counter_landed"] = r.counter_landed;
        }
        break;
    }
    case FighterEvent::Type::strike_end:
        line["clip"] = bout.database().string(bout.database().clips[event.clip].name);
        line["outcome"] = event.impact ? "impact" : "follow_through";
        line["overshoot_m"] = event.overshoot_m;
        line["held_at_target_s"] = event.held_at_target_s;
        line["joint_limit_violations"] = event.joint_limit_violations;
        break;
    case FighterEvent::Type::character: line["character"] = bout.character_name(event.character); break;
    case FighterEvent::Type::user_strike:
        line["hand"] = event.user_strike.hand == 0 ? "left" : "right";
        line["aimed_at"] = event.user_strike.at_head ? "head" : "chest";
        line["move"] = defence_move_name(event.user_strike.move);
        line["arm"] = event.user_strike.arm == 0 ? "left" : "right";
        if (event.user_strike.block_clip >= 0) line["block_clip"] = bout.database().string(bout.database().clips[event.user_strike.block_clip].name);
        line["time_to_impact_s"] = event.user_strike.time_to_impact_s;
        line["detected"] = event.user_strike.detected;
        line["hand_speed_mps"] = event.user_strike.hand_speed_mps;
        break;
    case FighterEvent::Type::user_strike_end:
        line["hand"] = event.user_strike.hand == 0 ? "left" : "right";
        line["aimed_at"] = event.user_strike.at_head ? "head" : "chest";
        line["move"] = defence_move_name(event.user_strike.move);
        line["outcome"] = user_strike_outcome_name(event.user_strike.outcome);
        if (event.user_strike.forearm_to_path_m >= 0.0) line["forearm_to_path_m"] = event.user_strike.forearm_to_path_m;
        if (event.user_strike.outcome == UserStrikeOutcome::slipped && event.user_strike.unslipped_clearance_m < 1e8)
            line["unslipped_clearance_m"] = event.user_strike.unslipped_clearance_m;
        line["detected"] = event.user_strike.detected;
        line["peak_speed_mps"] = event.user_strike.peak_speed_mps;
        if (event.user_strike.approach_s >= 0.0) line["approach_s"] = event.user_strike.approach_s;
        if (event.user_strike.blocking_arm >= 0) line["blocking_arm"] = event.user_strike.blocking_arm == 0 ? "left" : "right";
        if (event.user_strike.block_clip >= 0) line["block_clip"] = bout.database().string(bout.database().clips[event.user_strike.block_clip].name);
        if (event.user_strike.arm_from_shoulder_mps >= 0.0) line["arm_from_shoulder_mps"] = event.user_strike.arm_from_shoulder_mps;
        if (event.user_strike.wrist_mps >= 0.0) line["wrist_mps"] = event.user_strike.wrist_mps;
        if (event.user_strike.elbow_mps >= 0.0) line["elbow_mps"] = event.user_strike.elbow_mps;
        line["defended"] = event.user_strike.defended;
        if (event.user_strike.moved_s >= 0.0) {
            line["moved_s"] = event.user_strike.moved_s;
            line["move_after_seen_s"] = event.user_strike.move_after_seen_s;
        }
        if (event.user_strike.clip_arm_from_shoulder_mps >= 0.0) line["clip_arm_from_shoulder_mps"] = event.user_strike.clip_arm_from_shoulder_mps;
        line["joint_limit_violations"] = event.joint_limit_violations;
        line["foot_shift_m"] = event.foot_shift_m;
        break;
    case FighterEvent::Type::user_strike_course: // a blocked strike's path, followed on after the forearm
        line["hand"] = event.user_strike.hand == 0 ? "left" : "right";
        line["aimed_at"] = event.user_strike.at_head ? "head" : "chest";
        line["unblocked_clearance_m"] = event.user_strike.unblocked_clearance_m;
        line["on_course"] = event.user_strike.unblocked_clearance_m <= 0.0;
        break;
    case FighterEvent::Type::hit_reaction:
        line["hand"] = event.user_strike.hand == 0 ? "left" : "right";
        line["aimed_at"] = event.user_strike.at_head ? "head" : "chest";
        if (event.clip >= 0) line["clip"] = bout.database().string(bout.database().clips[event.clip].name);
        else line["clip"] = nullptr; // the database holds no hit reaction
        line["fit"] = event.reaction_fit;
        line["delay_s"] = event.reaction_delay_s;
        line["blows"] = event.reaction_blows;
        break;
    default: break;
    }
    return line;
}

} // namespace

std::string bout_event_json(const Bout& bout, const BoutEvent& event) {
    return event_object(bout, event).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

} // namespace kumite
