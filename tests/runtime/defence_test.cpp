// Defence against the user's strikes: segment distances, a fast hand coming at the head is a user strike that is
// blocked with the arm on its side (or slipped when there is no time), a hand that passes wide or moves slowly is
// not one, and with defence off a punch that arrives is `hit_by_user`.

#include "kumite/runtime/defence.h"
#include "kumite/core/split_mix.h"

#include <catch2/catch.hpp>

#include <vector>

using namespace kumite;

namespace {

// A fighter at the origin facing +Z (its left is +X), in a guard.
DefenderBody guard_body() {
    DefenderBody body;
    body.head = {0.0, 1.6, 0.0};
    body.chest = {0.0, 1.3, 0.0};
    body.shoulder = {Eigen::Vector3d(0.18, 1.42, 0.0), Eigen::Vector3d(-0.18, 1.42, 0.0)};
    body.elbow = {Eigen::Vector3d(0.2, 1.15, 0.15), Eigen::Vector3d(-0.2, 1.15, 0.15)};
    body.wrist = {Eigen::Vector3d(0.12, 1.4, 0.3), Eigen::Vector3d(-0.12, 1.4, 0.3)};
    body.arm_length = {0.6, 0.6};
    return body;
}

// Runs the user's hand `side` along `path(t)` for a second at 60 Hz (the other held still); the fighter's blocking
// forearm is put where the defence asks (wrist at the target, elbow 0.25 m below) when `follow`. `seen(t)` is
// called after each frame's update.
template <class Path, class Seen>
std::vector<UserStrikeEvent> run_hand(Defence& defence, int side, Path&& path, bool follow, Seen&& seen) {
    std::vector<UserStrikeEvent> events;
    DefenderBody body = guard_body();
    for (int frame = 0; frame < 60; ++frame) {
        const double t = frame / 60.0;
        UserHands hands;
        hands.present = {true, true};
        hands.world[1 - side] = Eigen::Vector3d(side == 0 ? 0.2 : -0.2, 1.35, 0.7);
        hands.world[side] = path(t);
        if (follow && defence.block_weight() > 0.0) {
            const int arm = defence.block_arm();
            const Eigen::Vector3d wrist = body.wrist[arm] + defence.block_weight() * (defence.block_wrist_target() - body.wrist[arm]);
            body = guard_body();
            body.wrist[arm] = wrist;
            body.elbow[arm] = wrist - Eigen::Vector3d(0.0, 0.25, 0.0);
        }
        defence.update(t, hands, body, true);
        for (const UserStrikeEvent& event : defence.events()) events.push_back(event);
        defence.clear_events();
        seen(t);
    }
    return events;
}

// A straight thrust of the user's hand `side` from `from` to `to` at `speed` after 0.2 s still, then held.
std::vector<UserStrikeEvent> thrust(Defence& defence, int side, const Eigen::Vector3d& from, const Eigen::Vector3d& to, double speed, bool follow) {
    const double out_s = (to - from).norm() / speed;
    const auto path = [&](double t) {
        const double thrust = t - 0.2;
        return thrust <= 0.0 ? from : thrust >= out_s ? to : Eigen::Vector3d(from + (to - from) * (thrust / out_s));
    };
    return run_hand(defence, side, path, follow, [](double) {});
}

} // namespace

TEST_CASE("defence: segment distance agrees with dense sampling", "[runtime]") {
    SplitMix64 random{2};
    for (int trial = 0; trial < 200; ++trial) {
        Eigen::Vector3d p[4];
        for (Eigen::Vector3d& point : p) point = Eigen::Vector3d(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1));
        if (trial % 10 == 0) p[1] = p[0]; // a degenerate one
        double sampled = 1e9;
        for (int i = 0; i <= 200; ++i) {
            for (int j = 0; j <= 200; ++j) {
                sampled = std::min(sampled, ((p[0] + (p[1] - p[0]) * (i / 200.0)) - (p[2] + (p[3] - p[2]) * (j / 200.0))).norm());
            }
        }
        const double exact = segment_distance(p[0], p[1], p[2], p[3]);
        CHECK(exact <= sampled + 1e-9);
        CHECK(exact >= sampled - 0.02);
    }
}

TEST_CASE("defence: a punch at the head is blocked with the arm on its side; without defence it lands", "[runtime]") {
    // The user's left hand (on the fighter's right, -X) thrusts at the head from 0.8 m at 6 m/s.
    const Eigen::Vector3d from(-0.15, 1.45, 0.8), to(0.0, 1.6, 0.0);
    Defence defence;
    const std::vector<UserStrikeEvent> events = thrust(defence, 0, from, to, 6.0, true);
    REQUIRE(events.size() == 3); // seen, blocked, the path after the forearm
    CHECK(events[2].course_followed);
    CHECK(events[2].unblocked_clearance_m <= 0.0); // at the head: it would have landed
    CHECK_FALSE(events[0].ended);
    CHECK(events[0].at_head);
    CHECK(events[0].move == DefenceMove::synthesized);
    CHECK(events[0].arm == 1); // the fighter's right arm
    CHECK(events[0].time_to_impact_s > 0.05);
    CHECK(events[1].ended);
    CHECK(events[1].outcome == UserStrikeOutcome::blocked);
    CHECK(events[1].forearm_to_path_m <= 0.05);

    Defence off(DefenceSettings{.enabled = false});
    const std::vector<UserStrikeEvent> landed = thrust(off, 0, from, to, 6.0, true);
    REQUIRE(landed.size() == 2);
    CHECK(landed[0].move == DefenceMove::none);
    CHECK(landed[1].outcome == UserStrikeOutcome::hit_by_user);
}

TEST_CASE("defence: a fist faster than first seen: the forearm is in place a frame before it reaches the meeting point", "[runtime]") {
    // The user's left hand at the head from 0.8 m: seen while it speeds up (two frames at 4 m/s), then at 7 m/s. The
    // first estimate of the time to impact is twice too long; the ramp must still end before the fist gets there.
    const Eigen::Vector3d from(-0.15, 1.45, 0.8), to(0.0, 1.6, 0.0);
    const Eigen::Vector3d direction = (to - from).normalized();
    const auto fist = [&](double t) {
        const double slow_s = 2.0 / 60.0, run = t - 0.2;
        if (run <= 0.0) return from;
        const double travelled = run <= slow_s ? run * 4.0 : slow_s * 4.0 + (run - slow_s) * 7.0;
        return Eigen::Vector3d(from + direction * std::min(travelled, (to - from).norm()));
    };
    Defence defence;
    double weight_before_meeting = -1.0;
    const std::vector<UserStrikeEvent> events = run_hand(defence, 0, fist, true, [&](double t) {
        // The weight shown this frame, while the fist is still short of the meeting point next frame.
        if (defence.block_weight() > 0.0 && (defence.block_wrist_target() - fist(t + 1.0 / 60.0)).dot(direction) > 0.0) {
            weight_before_meeting = defence.block_weight();
        }
    });
    REQUIRE(events.size() == 3); // seen, blocked, the path after the forearm
    CHECK(events[0].move == DefenceMove::synthesized);
    CHECK(events[0].hand_speed_mps < 4.0); // seen early, while it speeds up
    CHECK(weight_before_meeting == Approx(1.0));
    CHECK(events[1].outcome == UserStrikeOutcome::blocked);
}

TEST_CASE("defence: too late to block, it slips; wide or slow hands are not strikes", "[runtime]") {
    // From 0.3 m at 8 m/s: under 0.04 s to impact, no wrist gets there: a slip.
    Defence late;
    const std::vector<UserStrikeEvent> events = thrust(late, 1, Eigen::Vector3d(0.05, 1.55, 0.3), Eigen::Vector3d(0.0, 1.6, 0.0), 8.0, false);
    REQUIRE(!events.empty());
    CHECK(events[0].move == DefenceMove::slip);
    CHECK(late.slip_offset().norm() == Approx(late.settings().slip_m));
    CHECK(late.slip_offset().y() == 0.0);
    // Passing 0.6 m to the side, or at 1.5 m/s: nothing.
    Defence wide, slow;
    CHECK(thrust(wide, 0, Eigen::Vector3d(0.6, 1.5, 0.8), Eigen::Vector3d(0.6, 1.6, -0.5), 6.0, false).empty());
    CHECK(thrust(slow, 0, Eigen::Vector3d(-0.15, 1.45, 0.8), Eigen::Vector3d(0.0, 1.6, 0.1), 1.5, false).empty());
}

namespace {

// The user's left hand (the other held still, wide) along `path(t)` for a second at 60 Hz against `body`.
template <class Path>
std::vector<UserStrikeEvent> follow(Defence& defence, Path&& path, const DefenderBody& body, const Defence::Allowed& allowed = {}) {
    std::vector<UserStrikeEvent> events;
    for (int frame = 0; frame < 60; ++frame) {
        const double t = frame / 60.0;
        UserHands hands;
        hands.present = {true, true};
        hands.world[0] = path(t);
        hands.world[1] = Eigen::Vector3d(-0.5, 1.3, 0.8);
        defence.update(t, hands, body, allowed);
        for (const UserStrikeEvent& event : defence.events()) events.push_back(event);
        defence.clear_events();
    }
    return events;
}

// From `from` to `to` at `speed` after 0.2 s still, then held.
auto straight(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double speed) {
    return [=](double t) {
        const double s = std::clamp((t - 0.2) * speed / (to - from).norm(), 0.0, 1.0);
        return Eigen::Vector3d(from + s * (to - from));
    };
}

} // namespace

TEST_CASE("defence: a hand that arrives unseen is counted; a forearm held in the guard on its path blocks it", "[runtime]") {
    // Too slow to be seen coming (2.2 m/s, under the 2.5 m/s of a threat), fast enough to be a strike arriving.
    Defence unseen;
    const auto events = follow(unseen, straight(Eigen::Vector3d(0.0, 1.6, 0.5), Eigen::Vector3d(0.0, 1.6, 0.0), 2.2), guard_body());
    REQUIRE(events.size() == 2);
    CHECK_FALSE(events[0].detected);
    CHECK(events[0].move == DefenceMove::none);
    CHECK(events[1].outcome == UserStrikeOutcome::hit_by_user);
    CHECK_FALSE(events[1].detected);
    // Held there, drawn back, pushed in again slowly: the same arrival is not counted twice, a slow one not at all.
    Defence slow;
    CHECK(follow(slow, straight(Eigen::Vector3d(0.0, 1.6, 0.5), Eigen::Vector3d(0.0, 1.6, 0.0), 1.5), guard_body()).empty());

    // The fighter's left forearm across the face (a high guard), no defence move: the punch stops on it.
    DefenderBody high_guard = guard_body();
    high_guard.elbow[0] = Eigen::Vector3d(0.15, 1.5, 0.2);
    high_guard.wrist[0] = Eigen::Vector3d(-0.1, 1.65, 0.2);
    Defence off(DefenceSettings{.enabled = false});
    const auto guarded = follow(off, straight(Eigen::Vector3d(0.0, 1.6, 0.8), Eigen::Vector3d(0.0, 1.6, 0.0), 6.0), high_guard);
    REQUIRE(guarded.size() == 3); // seen, blocked, and the path after the forearm (it would have landed)
    CHECK(guarded[2].unblocked_clearance_m <= 0.0);
    CHECK(guarded[0].detected);
    CHECK(guarded[0].move == DefenceMove::none);
    CHECK(guarded[1].outcome == UserStrikeOutcome::blocked);
    CHECK(guarded[1].blocking_arm == 0);
}

TEST_CASE("defence: only the allowed moves start: the free arm blocks while the other strikes, no slip mid-strike", "[runtime]") {
    // From the fighter's left (+X): its left arm would block; with that arm striking, the right arm reaches across.
    const Eigen::Vector3d from(0.15, 1.45, 0.8), to(0.0, 1.6, 0.0);
    Defence left_striking;
    const auto across = follow(left_striking, straight(from, to, 6.0), guard_body(), Defence::Allowed{{false, true}, false});
    REQUIRE(!across.empty());
    CHECK(across[0].move == DefenceMove::synthesized);
    CHECK(across[0].arm == 1);
    // No arm free and no slip (a kick that needs both arms? no: a strike that holds the trunk): taken as it comes.
    Defence nothing_free;
    const auto taken = follow(nothing_free, straight(from, to, 6.0), guard_body(), Defence::Allowed{{false, false}, false});
    REQUIRE(taken.size() == 2);
    CHECK(taken[0].move == DefenceMove::none);
    CHECK(taken[1].outcome == UserStrikeOutcome::hit_by_user);
    // Too late for any arm and slipping not allowed: no move either.
    Defence late;
    const auto too_late = follow(late, straight(Eigen::Vector3d(0.05, 1.55, 0.3), to, 8.0), guard_body(), Defence::Allowed{{true, true}, false});
    REQUIRE(!too_late.empty());
    CHECK(too_late[0].move == DefenceMove::none);
}

TEST_CASE("defence: a hand that jumps (a tracker glitch, a recording that loops) is not a strike", "[runtime]") {
    Defence defence;
    auto jump = [](double t) { return t < 0.5 ? Eigen::Vector3d(0.0, 1.4, 1.2) : Eigen::Vector3d(0.0, 1.6, 0.05); };
    CHECK(follow(defence, jump, guard_body()).empty());
}

TEST_CASE("defence: a block met nearer when the fist is seen late ramps over the time to that meeting point, at a person's speed", "[runtime]") {
    // With too little time before the fist reaches the point block_before_m short of the head, the plan meets it at
    // half that distance, but the ramp was timed to the first point: 0.02 s (two frames at 60 Hz) for the whole way
    // from the guard, a wrist at up to 24 m/s in the recorded-opponent bouts. Fists seen from 0.3 to 0.45 m away at 3
    // to 5 m/s: every block that starts is timed to its own meeting point, and ramps no faster than a person's
    // wrist moves (max_block_wrist_mps at the smoothstep's fastest) when that leaves it time.
    const DefenceSettings settings;
    int nearer = 0;
    for (const int side : {0, 1}) {
        for (const double distance : {0.3, 0.35, 0.4, 0.45}) {
            for (const double speed : {3.0, 4.0, 5.0}) {
                const Eigen::Vector3d to(0.0, 1.6, 0.0);
                const Eigen::Vector3d from = to + Eigen::Vector3d(side == 0 ? -0.1 : 0.1, -0.1, distance);
                Defence defence;
                const double out_s = (to - from).norm() / speed;
                const auto path = [&](double t) {
                    const double thrust = t - 0.2;
                    return thrust <= 0.0 ? from : thrust >= out_s ? to : Eigen::Vector3d(from + (to - from) * (thrust / out_s));
                };
                double intercept_s = -1.0, time_to_impact_s = -1.0, hand_speed_mps = -1.0;
                run_hand(defence, side, path, false, [&](double) {
                    if (!defence.block_started()) return;
                    intercept_s = defence.intercept_s();
                    time_to_impact_s = defence.move_strike().time_to_impact_s;
                    hand_speed_mps = defence.move_strike().hand_speed_mps;
                });
                if (intercept_s < 0.0) continue;
                const double at_first = time_to_impact_s - settings.block_before_m / hand_speed_mps;
                if (at_first > 0.02) continue; // met where it first would be: as before
                INFO("from " << distance << " m at " << speed << " m/s: impact in " << time_to_impact_s << " s, meeting in " << intercept_s << " s");
                CHECK(intercept_s == Approx(time_to_impact_s - 0.5 * settings.block_before_m / hand_speed_mps).margin(1e-9));
                ++nearer;
            }
        }
    }
    CHECK(nearer >= 3);
}

TEST_CASE("defence: a slip is counted as keeping a blow off only where the hand would have hit the head without it", "[runtime]") {
    // Slip only (no arm free), the head leaned as the defence asks; the user's left hand from 0.9 m in front at 5 m/s,
    // straight through where the head was, or 0.22 m beside it (inside the threat radius, outside the head's).
    const auto slipped = [](double beside_m) {
        Defence defence;
        const Defence::Allowed slip_only{{false, false}, true};
        const auto path = straight(Eigen::Vector3d(beside_m, 1.55, 0.9), Eigen::Vector3d(beside_m, 1.6, -0.3), 5.0);
        UserStrikeEvent ended;
        for (int frame = 0; frame < 60; ++frame) {
            const double t = frame / 60.0;
            DefenderBody body = guard_body();
            body.head += defence.slip_weight() * defence.slip_offset();
            body.chest += 0.5 * defence.slip_weight() * defence.slip_offset();
            UserHands hands;
            hands.present = {true, true};
            hands.world[0] = path(t);
            hands.world[1] = Eigen::Vector3d(-0.5, 1.3, 0.8);
            defence.update(t, hands, body, slip_only);
            for (const UserStrikeEvent& event : defence.events())
                if (event.ended) ended = event;
            defence.clear_events();
        }
        return ended;
    };
    const UserStrikeEvent through = slipped(0.0), beside = slipped(0.22);
    CHECK(through.move == DefenceMove::slip);
    CHECK(through.outcome == UserStrikeOutcome::slipped);
    CHECK(through.unslipped_clearance_m <= 0.0); // it would have landed: the slip kept it off
    CHECK(beside.move == DefenceMove::slip);
    CHECK(beside.outcome == UserStrikeOutcome::slipped);
    CHECK(beside.unslipped_clearance_m == Approx(0.22 - Defence{}.settings().head_radius_m).margin(0.02)); // it would have missed anyway
}

TEST_CASE("defence: a block is counted as keeping a blow off only where the hand's path went on to the head or chest", "[runtime]") {
    // A high guard's left forearm across the face, no defence move; a punch at 6 m/s from 0.8 m in front, straight
    // through the head, or 0.2 m beside it (through the forearm, wide of the head): both are blocked, and the hand
    // goes on (nothing stops a tracked hand at a virtual arm) to where the path says whether it would have landed.
    DefenderBody high_guard = guard_body();
    high_guard.elbow[0] = Eigen::Vector3d(0.35, 1.6, 0.2);
    high_guard.wrist[0] = Eigen::Vector3d(-0.25, 1.6, 0.2);
    const auto blocked = [&](double beside_m) {
        Defence off(DefenceSettings{.enabled = false});
        const auto events = follow(off, straight(Eigen::Vector3d(beside_m, 1.6, 0.8), Eigen::Vector3d(beside_m, 1.6, -0.3), 6.0), high_guard);
        // Seen, ended blocked at the forearm (0.6 m from the start at 6 m/s), then its path told.
        REQUIRE(events.size() == 3);
        CHECK(events[1].ended);
        CHECK(events[1].outcome == UserStrikeOutcome::blocked);
        CHECK(events[1].t_s == Approx(0.2 + 0.6 / 6.0).margin(1.5 / 60.0));
        CHECK(events[2].course_followed);
        CHECK_FALSE(events[2].ended);
        CHECK(events[2].t_s > events[1].t_s);
        CHECK(events[2].t_s <= events[1].t_s + 0.3 + 1e-9);
        return events[2];
    };
    const UserStrikeEvent through = blocked(0.0), beside = blocked(0.2);
    CHECK(through.unblocked_clearance_m <= 0.0); // it would have landed: the forearm kept it off
    CHECK(beside.unblocked_clearance_m == Approx(0.2 - Defence{}.settings().head_radius_m).margin(0.02)); // wide anyway
}

TEST_CASE("defence: a combination's second blow gets a block once the first block's blow is over, not one move at a time", "[runtime]") {
    // A one-two at the head from 0.8 m at 6 m/s: the user's left hand at 0.2 s, the right 0.25 s later. The fighter's
    // blocking forearm is put where the defence asks (wrist at the target, elbow 0.25 m below), the other in the guard.
    const auto one_two = [](bool hand_over) {
        DefenceSettings settings;
        settings.hand_over_blocks = hand_over;
        Defence defence(settings);
        const auto left = straight(Eigen::Vector3d(-0.15, 1.45, 0.8), Eigen::Vector3d(0.0, 1.6, -0.2), 6.0);
        const auto right_path = straight(Eigen::Vector3d(0.15, 1.45, 0.8), Eigen::Vector3d(0.0, 1.6, -0.2), 6.0);
        std::vector<UserStrikeEvent> events;
        for (int frame = 0; frame < 60; ++frame) {
            const double t = frame / 60.0;
            DefenderBody body = guard_body();
            if (defence.block_weight() > 0.0) {
                const int arm = defence.block_arm();
                body.wrist[arm] += defence.block_weight() * (defence.block_wrist_target() - body.wrist[arm]);
                body.elbow[arm] = body.wrist[arm] - Eigen::Vector3d(0.0, 0.25, 0.0);
            }
            UserHands hands;
            hands.present = {true, true};
            hands.world[0] = left(t);
            hands.world[1] = right_path(t - 0.25);
            defence.update(t, hands, body, true);
            for (const UserStrikeEvent& event : defence.events()) events.push_back(event);
            defence.clear_events();
        }
        return events;
    };
    const auto outcome_of = [](const std::vector<UserStrikeEvent>& events, int hand) {
        const UserStrikeEvent* seen = nullptr;
        const UserStrikeEvent* ended = nullptr;
        for (const UserStrikeEvent& event : events) {
            if (event.hand != hand || event.course_followed) continue;
            (event.ended ? ended : seen) = &event;
        }
        REQUIRE(seen);
        REQUIRE(ended);
        return std::pair(seen->move, ended->outcome);
    };
    const auto handed = one_two(true), held = one_two(false);
    CHECK(outcome_of(handed, 0) == std::pair(DefenceMove::synthesized, UserStrikeOutcome::blocked));
    CHECK(outcome_of(held, 0) == std::pair(DefenceMove::synthesized, UserStrikeOutcome::blocked));
    // Handed over, the second blow is blocked too; one move at a time, the first block is still held and released
    // when it comes: no move, and it lands.
    CHECK(outcome_of(handed, 1) == std::pair(DefenceMove::synthesized, UserStrikeOutcome::blocked));
    CHECK(outcome_of(held, 1).first == DefenceMove::none);
    CHECK(outcome_of(held, 1).second == UserStrikeOutcome::hit_by_user);
}

TEST_CASE("defence: a double jab's second blow gets a block too, handed over from the same hand's first", "[runtime]") {
    // The user's left hand at the head from 0.8 m at 6 m/s, drawn back over 0.2 s and thrown again. The blocking
    // forearm is put where the defence asks, as in the one-two above.
    const Eigen::Vector3d from(-0.15, 1.45, 0.8), to(0.0, 1.6, -0.2);
    const double out_s = (to - from).norm() / 6.0;
    const auto jab = [&](double t) {
        const double second = 0.2 + out_s + 0.2; // the second thrust starts here
        if (t < 0.2) return from;
        if (t < 0.2 + out_s) return Eigen::Vector3d(from + (to - from) * ((t - 0.2) / out_s));
        if (t < second) return Eigen::Vector3d(to + (from - to) * ((t - 0.2 - out_s) / 0.2));
        return Eigen::Vector3d(from + (to - from) * std::min(1.0, (t - second) / out_s));
    };
    const auto run = [&](bool hand_over) {
        DefenceSettings settings;
        settings.hand_over_blocks = hand_over;
        Defence defence(settings);
        std::vector<UserStrikeEvent> started;
        for (const UserStrikeEvent& event : run_hand(defence, 0, jab, true, [](double) {})) {
            if (!event.ended && !event.course_followed) started.push_back(event);
        }
        return started;
    };
    const auto handed = run(true), held = run(false);
    REQUIRE(handed.size() == 2);
    REQUIRE(held.size() == 2);
    CHECK(handed[0].move == DefenceMove::synthesized);
    CHECK(handed[1].move == DefenceMove::synthesized);
    CHECK(held[1].move == DefenceMove::none); // one move at a time: the first block is still held and released
}

TEST_CASE("defence: a blow's end tells how long the hand had been closing on what it met, and its fastest speed", "[runtime]") {
    // The thrust starts at 0.2 s: from then on the hand closes on the head, at 3 m/s, or at 6 m/s into a block.
    const Eigen::Vector3d from(-0.15, 1.45, 0.8), to(0.0, 1.6, 0.0);
    Defence off(DefenceSettings{.enabled = false});
    const std::vector<UserStrikeEvent> landed = thrust(off, 0, from, to, 3.0, true);
    REQUIRE(landed.size() == 2);
    REQUIRE(landed[1].outcome == UserStrikeOutcome::hit_by_user);
    CHECK(landed[1].approach_s == Approx(landed[1].t_s - 0.2).margin(1e-9));
    CHECK(landed[1].approach_s > 0.15); // 0.8 m less the head's radius at 3 m/s
    CHECK(landed[1].peak_speed_mps == Approx(3.0).margin(0.05));
    CHECK(landed[1].peak_speed_mps >= landed[0].hand_speed_mps);

    Defence defence;
    const std::vector<UserStrikeEvent> blocked = thrust(defence, 0, from, to, 6.0, true);
    REQUIRE(blocked.size() == 3);
    REQUIRE(blocked[1].outcome == UserStrikeOutcome::blocked);
    CHECK(blocked[1].approach_s == Approx(blocked[1].t_s - 0.2).margin(1e-9));
    CHECK(blocked[1].peak_speed_mps == Approx(6.0).margin(0.1));

    // A hand that comes halfway, waits, then goes on: its approach is the last one, from where it waited.
    const Eigen::Vector3d halfway = 0.5 * (from + to);
    const double half_s = (halfway - from).norm() / 3.0, resume_s = 0.2 + half_s + 0.15;
    const auto feint = [&](double t) -> Eigen::Vector3d {
        if (t <= 0.2) return from;
        if (t <= 0.2 + half_s) return from + (halfway - from) * ((t - 0.2) / half_s);
        if (t <= resume_s) return halfway;
        return halfway + (to - halfway) * std::min(1.0, (t - resume_s) / half_s);
    };
    Defence after_feint(DefenceSettings{.enabled = false});
    std::vector<UserStrikeEvent> feinted = run_hand(after_feint, 0, feint, true, [](double) {});
    REQUIRE_FALSE(feinted.empty());
    REQUIRE(feinted.back().outcome == UserStrikeOutcome::hit_by_user);
    CHECK(feinted.back().approach_s == Approx(feinted.back().t_s - resume_s).margin(1.0 / 60.0 + 1e-9));
}

TEST_CASE("defence: a block follows a fist that turns onto the head as it slows, while it still travels", "[runtime]") {
    // Kata-like: from 0.8 m the fist heads for a point 0.25 m beside the head at 3 m/s (a threat: within 0.3 m),
    // then, 0.45 m out, turns onto the head and slows to 1.8 m/s, under the 2.5 m/s that makes a strike.
    const Eigen::Vector3d from(-0.15, 1.45, 0.8), beside(-0.25, 1.6, 0.0), head(0.0, 1.6, 0.0);
    const Eigen::Vector3d turn = from + (beside - from).normalized() * ((from - head).norm() - 0.45);
    const double first_s = (turn - from).norm() / 3.0, second_s = (head - turn).norm() / 1.8;
    const auto path = [&](double t) -> Eigen::Vector3d {
        const double moving = t - 0.2;
        if (moving <= 0.0) return from;
        if (moving <= first_s) return from + (turn - from) * (moving / first_s);
        return turn + (head - turn) * std::min(1.0, (moving - first_s) / second_s);
    };
    const auto outcome = [&](double reaim_mps) {
        DefenceSettings settings;
        settings.reaim_min_speed_mps = reaim_mps;
        Defence defence(settings);
        const std::vector<UserStrikeEvent> events = run_hand(defence, 0, path, true, [](double) {});
        REQUIRE(events.size() >= 2);
        CHECK(events[0].move == DefenceMove::synthesized);
        for (const UserStrikeEvent& event : events) {
            if (event.ended) return event.outcome;
        }
        return UserStrikeOutcome::missed;
    };
    CHECK(outcome(DefenceSettings{}.reaim_min_speed_mps) == UserStrikeOutcome::blocked);
    CHECK(outcome(2.5) == UserStrikeOutcome::hit_by_user); // followed only while over 2.5 m/s: the forearm stays beside
}

TEST_CASE("defence: with a reaction time, a hand that stopped short meanwhile gets no move (no hold of seconds)", "[runtime]") {
    // The user's hand starts at the head at 4 m/s, stops 0.4 m short after 0.1 s, and drifts on at 3 cm/s: a glove
    // held out. 0.2 s after it was seen it is no threat any more; a move then would be held until it "arrived" (11 s).
    DefenceSettings settings;
    settings.reaction_delay_s = 0.2;
    Defence defence(settings);
    const Eigen::Vector3d from(-0.1, 1.55, 0.8), head(0.0, 1.6, 0.0);
    const Eigen::Vector3d way = (head - from).normalized();
    const auto path = [&](double t) {
        if (t <= 0.2) return from;
        if (t <= 0.3) return Eigen::Vector3d(from + way * 4.0 * (t - 0.2));
        return Eigen::Vector3d(from + way * (0.4 + 0.03 * (t - 0.3)));
    };
    bool ever_active = false;
    run_hand(defence, 0, path, false, [&](double) { ever_active = ever_active || defence.active(); });
    CHECK_FALSE(ever_active);
    CHECK_FALSE(defence.active());
}
