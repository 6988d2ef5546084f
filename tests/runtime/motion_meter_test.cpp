// The fighter's motion measured (issue 44): joint speeds from two poses (a wrist moved, an elbow bent), the library's
// fastest per kind of move on the reference database, and a fighter's frames counted by kind with the distance it
// keeps between strikes.

#include "fighter_bout.h"
#include "support/reference_database.h"

#include "kumite/runtime/motion_meter.h"

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

using namespace kumite;

TEST_CASE("joint speeds: a wrist moved 10 cm in a 60 Hz frame is 6 m/s, an elbow bent 0.5 rad in 0.1 s is 5 rad/s", "[runtime][corpus]") {
    const MotionDatabaseContent* content = kumite::test::reference_database();
    if (!content) return;
    const kumite::test::StandingCharacter brawler("brawler", content->view());
    const RestAnatomy& anatomy = brawler.anatomy;
    const std::vector<Eigen::Vector3d>& rest = anatomy.rest_positions;
    const LimbSample still = LimbSample::of(anatomy, rest);
    CHECK(joint_speeds(still, still, 1.0 / 60.0).wrist_mps == 0.0);

    std::vector<Eigen::Vector3d> moved = rest;
    const LimbChain& arm = anatomy.limbs[int(Limb::arm_r)];
    moved[arm.extremity] += Eigen::Vector3d(0.0, 0.0, 0.1);
    const JointSpeeds wrist = joint_speeds(still, LimbSample::of(anatomy, moved), 1.0 / 60.0);
    CHECK(wrist.wrist_mps == Approx(6.0));
    CHECK(wrist.ankle_mps == 0.0);

    // The right forearm turned 0.5 rad about the elbow in the plane of its bend: flexion changes by 0.5 rad.
    std::vector<Eigen::Vector3d> bent = rest;
    const Eigen::Vector3d upper = rest[arm.middle] - rest[arm.root], lower = rest[arm.extremity] - rest[arm.middle];
    Eigen::Vector3d axis = upper.cross(lower);
    if (axis.norm() < 1e-6) axis = upper.unitOrthogonal();
    bent[arm.extremity] = rest[arm.middle] + Eigen::AngleAxisd(0.5, axis.normalized()) * lower;
    const JointSpeeds elbow = joint_speeds(still, LimbSample::of(anatomy, bent), 0.1);
    CHECK(elbow.elbow_radps == Approx(5.0).margin(1e-6));
    CHECK(elbow.knee_radps == 0.0);
}

TEST_CASE("joint speeds: the library's fastest punches, kicks and guard on the reference database are a person's", "[runtime][corpus]") {
    const MotionDatabaseContent* content = kumite::test::reference_database();
    if (!content) return;
    const kumite::test::StandingCharacter brawler("brawler", content->view());
    const auto library = library_joint_speeds(content->view(), brawler.skeleton(), brawler.anatomy);
    // Punches ~10-12 m/s at the wrist, kicks as fast at the ankle (issue 44); a guard barely moves.
    CHECK(library[int(MoveKind::punch)].wrist_mps > 6.0);
    CHECK(library[int(MoveKind::punch)].wrist_mps < 20.0);
    CHECK(library[int(MoveKind::kick)].ankle_mps > 6.0);
    CHECK(library[int(MoveKind::kick)].ankle_mps < 20.0);
    CHECK(library[int(MoveKind::guard)].wrist_mps < 1.0);
    CHECK(library[int(MoveKind::punch)].elbow_radps > library[int(MoveKind::guard)].elbow_radps);
    // No slip clips in the reference database: nothing to measure, nothing made up.
    CHECK(library[int(MoveKind::slip)].wrist_mps == 0.0);
}

TEST_CASE("motion meter: a fighter's frames by kind of move, its strike's wrist speed, the distance it keeps", "[runtime][corpus]") {
    const MotionDatabaseContent* content = kumite::test::reference_database();
    if (!content) return;
    kumite::test::Bout bout(content->view());
    MotionMeter meter(1);
    const Eigen::Vector3d head(0.0, 1.65, 1.6);
    const int frames = 8 * 60;
    for (int frame = 0; frame < frames; ++frame) {
        const double t = frame / 60.0;
        if (frame == 120) bout.fighter->order(bout.retriever->semantics_id("punch"), Side::right);
        bout.fighter->step(t, &head);
        bout.fighter->clear_events();
        meter.measure(0, t, *bout.fighter, bout.db, bout.fighter->character() == 0 ? bout.brawler.anatomy : bout.giant.anatomy, &head);
    }
    long long counted = 0;
    for (long long n : meter.frames()) counted += n;
    CHECK(counted == frames);
    CHECK(meter.frames()[int(MoveKind::punch)] > 10);
    CHECK(meter.frames()[int(MoveKind::guard)] > 10);
    CHECK(meter.fastest()[int(MoveKind::punch)].wrist_mps > 1.0);
    CHECK(meter.fastest_overall().wrist_mps >= meter.fastest()[int(MoveKind::punch)].wrist_mps);
    // Between strikes only: the frames at rest or stepping, at a distance the fighter can stand at.
    CHECK(meter.distance_m().count() == meter.frames()[int(MoveKind::guard)] + meter.frames()[int(MoveKind::step)]);
    CHECK(meter.distance_m().quantile(0.5) > 0.2);
    CHECK(meter.distance_m().quantile(0.5) < 2.0);
    CHECK(meter.distance_legs().quantile(0.5) == Approx(meter.distance_m().quantile(0.5) / bout.brawler.anatomy.leg_length).epsilon(0.03));
}

TEST_CASE("fighter: a step keeps the guard's arms up: elbows bend no faster than in the step clips themselves", "[runtime][corpus]") {
    const MotionDatabaseContent* content = kumite::test::reference_database();
    if (!content) return;
    kumite::test::Bout bout(content->view());
    MotionMeter meter(1);
    // A user 3 m away walking back and forth: the fighter steps to keep its distance, many steps in a row.
    for (int frame = 0; frame < 12 * 60; ++frame) {
        const double t = frame / 60.0;
        const Eigen::Vector3d head(0.0, 1.65, 3.0 + 1.0 * std::sin(t * 0.8));
        bout.fighter->step(t, &head);
        bout.fighter->clear_events();
        meter.measure(0, t, *bout.fighter, bout.db, bout.brawler.anatomy, &head);
    }
    REQUIRE(meter.frames()[int(MoveKind::step)] > 60);
    const auto library = library_joint_speeds(bout.db, bout.brawler.skeleton(), bout.brawler.anatomy);
    // Blended from the guard into the walk's loose arms, the elbows swung at 20-26 rad/s; with the guard's arms kept
    // they move with the trunk only.
    CHECK(meter.fastest()[int(MoveKind::step)].elbow_radps <= library[int(MoveKind::step)].elbow_radps);
    CHECK(meter.fastest()[int(MoveKind::guard)].elbow_radps < 5.0);
}

TEST_CASE("fighter: how long a strike's hit point stays where it stopped, as its own pose shows it", "[runtime][corpus]") {
    const MotionDatabaseContent* content = kumite::test::reference_database();
    if (!content) return;
    kumite::test::Bout bout(content->view());
    const Eigen::Vector3d head(0.0, 1.65, 1.0);
    // Punches and kicks at a still head; after each contact, the frames the hit joint of the pose shown stays within
    // 1 cm of where it was at the contact, counted here from the fighter's positions.
    double held_seen_s = 0.0, held_total_s = 0.0;
    int joint = -1, strikes = 0, compared = 0;
    bool holding = false;
    Eigen::Vector3d stopped = Eigen::Vector3d::Zero();
    for (int frame = 0; frame < 20 * 60; ++frame) {
        const double t = frame / 60.0;
        if (frame >= 120 && frame % 150 == 0) bout.fighter->order(bout.retriever->semantics_id(frame % 300 ? "kick" : "punch"), Side::none);
        bout.fighter->step(t, &head);
        const auto positions = bout.fighter->positions();
        if (holding) {
            if ((positions[joint] - stopped).norm() <= 0.01) held_seen_s += 1.0 / 60.0;
            else holding = false;
        }
        for (const FighterEvent& event : bout.fighter->events()) {
            if (event.type == FighterEvent::Type::strike) {
                const int segment = bout.db.clips[event.clip].segment;
                const LimbChain& limb = bout.brawler.anatomy.limbs[limb_of_segment(static_cast<BodyPart>(segment))];
                joint = segment_strikes_with_middle(static_cast<BodyPart>(segment)) ? limb.middle : limb.extremity;
                stopped = positions[joint];
                holding = true;
                held_seen_s = 0.0;
                ++strikes;
            }
            if (event.type == FighterEvent::Type::strike_end && event.impact) {
                INFO("strike " << strikes << ": held " << event.held_at_target_s << " s, seen " << held_seen_s << " s");
                CHECK(event.held_at_target_s == Approx(held_seen_s).margin(1.5 / 60.0));
                held_total_s += event.held_at_target_s;
                ++compared;
            }
        }
        bout.fighter->clear_events();
    }
    CHECK(compared >= 4);
    CHECK(held_total_s > 0.0); // some stay a frame or two: the measure is not always 0
}
