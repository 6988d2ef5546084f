#pragma once
// What the fighter tells, one event per happening: its state changes, orders (taken, queued, performed, refused,
// expired), strikes (at the contact and at the end), the tracker lost and back, the character switched, and the
// user's strikes at it (seen, and how they ended).

#include "kumite/runtime/defence.h"
#include "kumite/runtime/user_guard.h"
#include "kumite/runtime/fighter_settings.h"
#include "kumite/runtime/user_response.h"

#include <Eigen/Core>

#include <optional>

namespace kumite {

enum class FighterState { rest, approach, strike, recover, hold, hit_reaction };
inline constexpr int k_fighter_state_count = 6;
const char* fighter_state_name(FighterState state);

struct FighterEvent {
    // Every order ends once, as order_performed (its strike began), ignored_order (refused, with why) or
    // order_expired (it waited order_wait_s, or a later order took its place); it starts as order (taken at once)
    // or order_queued (waiting).
    enum class Type { order, ignored_order, state, strike, strike_end, tracker_lost, tracker_back, character, user_strike, user_strike_end,
                      order_queued, order_performed, order_expired, hit_reaction, user_strike_course, user_response };
    Type type = Type::state;
    double t_s = 0.0;
    FighterState state = FighterState::rest; // state events: the new state
    int semantics = -1;                      // order and strike events
    Side side = Side::none;
    StrikeKind kind = StrikeKind::none;      // order and strike events: what the order asked for (none: any)
    StrikeHeight height = StrikeHeight::none;
    int combination = -1;                    // order, strike and user_response events: the order's combination (-1 none)
    int blow = 0;                            // ... and which blow of it
    bool own = false;                        // ... the fighter's own attack, not an order
    bool varied = false;                     // strike events: not the best clip, to vary from the last strikes
    int clip = -1;                           // strike events
    bool hit = false;
    GuardPart user_block = GuardPart::none;  // strike events: the user's glove or forearm its path met first (the
                                             // user blocked it: no hit), none when it met none
    double contact_error_m = 0.0;            // effector to the latched target at contact
    double head_distance_m = 0.0;            // effector to the head at contact
    double range_m = 0.0;                    // strike events: pelvis to head on the floor when the strike began
    double effector_speed_mps = 0.0;         // strike events: the hit point's speed arriving at the contact
    bool impact = true;                      // strike and strike_end events: the head was still at the target at
                                             // the contact, so the strike stops there; false: it follows through
    double overshoot_m = 0.0;                // strike_end events: the farthest past the target after the contact
    double held_at_target_s = 0.0;           // strike_end events: how long the hit point stayed within 1 cm of where
                                             // it stopped after the contact (a real strike recoils at once)
    int joint_limit_violations = 0;          // strike_end events: joints out of limits, summed over the frames
    FighterAim aim = FighterAim::latched;    // strike events: how the target was chosen
    Eigen::Vector3d target = Eigen::Vector3d::Zero(); // strike events: the target aimed at, world
    double head_speed_mps = 0.0;             // strike events: the head's filtered speed when the strike began
    double prediction_error_m = 0.0;         // strike events: the head at the contact to the target aimed at
    std::optional<Eigen::Vector3d> aimed_point_at_contact; // strike events: where the part aimed at was at the contact
                                                           // (world; none without a head then)
    double retrieval_offset_m = 0.0;         // strike events: the chosen clip's natural hit point to the target
    double steered_m = 0.0;                  // strike events: how far steering moved the target since the start
    double speedup = 1.0;                    // strike events: how much faster than captured it was played to the
                                             // contact (FighterSettings::max_speedup)
    TargetPart target_part = TargetPart::head; // strike events: the part aimed at
    bool reachable = true;                   // strike events: the adaptation gets the hit point to the target
    UserStrikeEvent user_strike;             // user_strike (seen, the move chosen) and user_strike_end (outcome; its
                                             // joint_limit_violations and foot_shift_m: what the defence did)
    double foot_shift_m = 0.0;
    double reaction_fit = 0.0;               // hit_reaction events: how nearly the clip's head goes the way the blow
                                             // pushed (cosine; `clip` the reaction played, -1 none in the database)
    double reaction_delay_s = 0.0;           // hit_reaction events: from the blow to the reaction (a strike under way
                                             // is played out first)
    int reaction_blows = 0;                  // hit_reaction events: the landed strikes it answers (several landed
                                             // during one strike of the fighter's: one reaction)
    UserResponse response;                   // user_response events (the rest as the blow's strike event told it)
    int character = -1;                      // character events
    const char* why = "";                    // ignored and expired orders
    double waited_s = 0.0;                   // order_performed and order_expired: since the order came
};
const char* fighter_event_name(FighterEvent::Type type);

} // namespace kumite
