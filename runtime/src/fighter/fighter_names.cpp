// The names of the fighter's states, aims, target parts and events (fighter_settings.h, fighter_event.h), as the
// events and reports write them.

#include "kumite/runtime/fighter_event.h"

namespace kumite {

const char* fighter_state_name(FighterState state) {
    switch (state) {
    case FighterState::rest: return "rest";
    case FighterState::approach: return "approach";
    case FighterState::strike: return "strike";
    case FighterState::recover: return "recover";
    case FighterState::hold: return "hold";
    case FighterState::hit_reaction: return "hit_reaction";
    }
    return "?";
}

const char* fighter_aim_name(FighterAim aim) { return aim == FighterAim::predicted ? "predicted" : "latched"; }

std::optional<FighterAim> fighter_aim_from_name(std::string_view name) {
    if (name == "latched") return FighterAim::latched;
    if (name == "predicted") return FighterAim::predicted;
    return std::nullopt;
}

const char* target_part_name(TargetPart part) {
    switch (part) {
    case TargetPart::head: return "head";
    case TargetPart::chin: return "chin";
    case TargetPart::chest: return "chest";
    case TargetPart::solar_plexus: return "solar_plexus";
    }
    return "?";
}

const char* response_kind_name(ResponseKind kind) {
    switch (kind) {
    case ResponseKind::none: return "none";
    case ResponseKind::block: return "block";
    case ResponseKind::parry: return "parry";
    case ResponseKind::slip: return "slip";
    case ResponseKind::duck: return "duck";
    case ResponseKind::step_back: return "step_back";
    }
    return "none";
}

const char* response_quality_name(ResponseQuality quality) {
    switch (quality) {
    case ResponseQuality::in_time: return "in_time";
    case ResponseQuality::late: return "late";
    case ResponseQuality::none: return "none";
    }
    return "none";
}

const char* fighter_event_name(FighterEvent::Type type) {
    switch (type) {
    case FighterEvent::Type::order: return "order";
    case FighterEvent::Type::ignored_order: return "ignored_order";
    case FighterEvent::Type::state: return "state";
    case FighterEvent::Type::strike: return "strike";
    case FighterEvent::Type::strike_end: return "strike_end";
    case FighterEvent::Type::tracker_lost: return "tracker_lost";
    case FighterEvent::Type::tracker_back: return "tracker_back";
    case FighterEvent::Type::character: return "character";
    case FighterEvent::Type::user_strike: return "user_strike";
    case FighterEvent::Type::user_strike_end: return "user_strike_end";
    case FighterEvent::Type::user_strike_course: return "user_strike_course";
    case FighterEvent::Type::user_response: return "user_response";
    case FighterEvent::Type::order_queued: return "order_queued";
    case FighterEvent::Type::order_performed: return "order_performed";
    case FighterEvent::Type::order_expired: return "order_expired";
    case FighterEvent::Type::hit_reaction: return "hit_reaction";
    }
    return "?";
}

} // namespace kumite
