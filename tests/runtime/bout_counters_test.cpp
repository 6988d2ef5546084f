// The report's counters fed a fighter's events one at a time (bout_counters.h): what an event counts depends on
// what came before it from the same fighter (its order's frame, its state).

#include "kumite/runtime/bout_counters.h"

#include <catch2/catch.hpp>

using namespace kumite;

namespace {

FighterEvent event_of(FighterEvent::Type type) {
    FighterEvent event;
    event.type = type;
    return event;
}

FighterEvent state_event(FighterState state) {
    FighterEvent event = event_of(FighterEvent::Type::state);
    event.state = state;
    return event;
}

} // namespace

TEST_CASE("bout_counters: an order's wait is counted once, from the order's frame to its strike's", "[runtime]") {
    const MotionDatabaseView no_clips;
    BoutCounters counters;
    FighterTally fighter;
    counters.tally(event_of(FighterEvent::Type::order), 10, no_clips, fighter);
    counters.tally(state_event(FighterState::approach), 12, no_clips, fighter);
    counters.tally(state_event(FighterState::strike), 25, no_clips, fighter);
    counters.tally(state_event(FighterState::strike), 40, no_clips, fighter); // no order waits: not counted again
    CHECK(counters.orders == 1);
    CHECK(counters.command_to_strike_frames.count() == 1);
    CHECK(counters.command_to_strike_frames.max() == Approx(15.0).epsilon(0.01));
    CHECK(fighter.order_frame == -1);
    CHECK(fighter.state == FighterState::strike);
}

TEST_CASE("bout_counters: a user strike's end is counted by its target and by the fighter's state then", "[runtime]") {
    const MotionDatabaseView no_clips;
    BoutCounters counters;
    FighterTally fighter;
    counters.tally(state_event(FighterState::hit_reaction), 5, no_clips, fighter);
    FighterEvent landed = event_of(FighterEvent::Type::user_strike_end);
    landed.user_strike.outcome = UserStrikeOutcome::hit_by_user;
    landed.user_strike.at_head = false;
    counters.tally(landed, 6, no_clips, fighter);
    const int hit = static_cast<int>(UserStrikeOutcome::hit_by_user);
    CHECK(counters.hit_by_user == 1);
    CHECK(counters.user_outcomes_by_target[1][hit] == 1);
    CHECK(counters.user_outcomes_by_target[0][hit] == 0);
    CHECK(counters.user_outcomes_by_fighter_state[static_cast<std::size_t>(FighterState::hit_reaction)][hit] == 1);
    CHECK(counters.user_outcomes_by_fighter_state[static_cast<std::size_t>(FighterState::rest)][hit] == 0);
}

TEST_CASE("bout_counters: a strike naming no clip of the database is counted, not by clip", "[runtime]") {
    const MotionDatabaseView no_clips;
    BoutCounters counters;
    FighterTally fighter;
    FighterEvent strike = event_of(FighterEvent::Type::strike);
    strike.clip = 3;
    strike.hit = true;
    strike.effector_speed_mps = 5.0;
    counters.tally(strike, 1, no_clips, fighter);
    CHECK(counters.strikes == 1);
    CHECK(counters.hits == 1);
    CHECK(counters.latched_hits == 1);
    CHECK(counters.contact_speed_mps.count() == 1);
    for (const ValueHistogram& by_kind : counters.contact_speed_by_kind_mps) CHECK(by_kind.empty());
}
