// Hit reactions: the captured reactions' courses, the choice for a blow, and a fighter that answers every
// landed strike with one, its head going the way the blow pushed; rocked by a blow, it may still slip the next.

#include "fighter_bout.h"
#include "support/reference_database.h"
#include "support/test_paths.h"

#include "fighter/hit_reactions.h"

#include "kumite/core/hit_trajectory.h"
#include "kumite/runtime/capture_user.h"
#include "kumite/runtime/simulated_user.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <map>
#include <string>

using namespace kumite;
using kumite::test::reference_database;

TEST_CASE("hit reactions: the captured reactions go back, sideways and fold, and a blow gets the one that goes its way", "[runtime][corpus]") {
    const MotionDatabaseContent* content = reference_database();
    if (!content) return;
    const MotionDatabaseView db = content->view();
    kumite::test::StandingCharacter brawler("brawler", db);
    HitReactions reactions(db, *brawler.rig);
    // The SNU boxer's 17 reactions and their mirrors (../shared/mocap/snu-boxing/SOURCE.md: 5 back, 5 back and to a
    // side, 3 sideways, 3 folding, 1 sagging).
    REQUIRE(reactions.clips().size() == 34);
    std::map<std::string, Eigen::Vector3d> course_of;
    int back = 0, folding = 0, left = 0, right = 0;
    for (const HitReactions::Clip& clip : reactions.clips()) {
        course_of[std::string(db.string(db.clips[clip.clip].name))] = clip.head_course;
        back += clip.head_course.z() < -0.5;
        folding += clip.head_course.z() > 0.3 && clip.head_course.y() < -0.3;
        left += clip.head_course.x() > 0.5;
        right += clip.head_course.x() < -0.5;
        CHECK(clip.head_travel_legs > 0.05); // 0.15-0.53 m on a 1.75 m boxer (the light body blow's 5 cm down is the least)
        CHECK(clip.head_travel_legs < 0.8);
    }
    INFO(back << " back, " << folding << " folding, " << left << " to the left, " << right << " to the right");
    CHECK(back >= 10);
    CHECK(folding >= 4);
    CHECK(left >= 2);
    CHECK(left == right); // each clip and its mirror
    for (const auto& [name, course] : course_of) { // a mirrored clip's head goes the other side
        if (!name.ends_with("~mirror")) continue;
        const Eigen::Vector3d original = course_of.at(name.substr(0, name.size() - 7));
        CHECK(std::abs(course.x() + original.x()) < 0.1);
        CHECK(std::abs(course.y() - original.y()) < 0.1);
        CHECK(std::abs(course.z() - original.z()) < 0.1);
    }
    auto chosen_course = [&](const Eigen::Vector3d& push, bool at_head) {
        const HitReactions::Choice choice = reactions.choose(push, at_head);
        REQUIRE(choice.clip >= 0);
        return course_of.at(std::string(db.string(db.clips[choice.clip].name)));
    };
    for (int repeat = 0; repeat < 3; ++repeat) { // the variety among the clips that fit never picks one that does not
        CHECK(chosen_course({0.0, 0.0, -6.0}, true).z() < -0.6);  // a straight to the face: the head snaps back
        CHECK(chosen_course({5.0, 0.0, -1.0}, true).x() > 0.5);   // a hook pushing to its left
        CHECK(chosen_course({-5.0, 0.0, -1.0}, true).x() < -0.5); // ... to its right
        const Eigen::Vector3d fold = chosen_course({0.0, 0.5, -5.0}, false);
        CHECK(fold.y() < -0.3); // a body blow folds it
        CHECK(fold.z() > 0.3);
    }
}

TEST_CASE("fighter: every user strike that lands is answered by a captured hit reaction, the head going the way the blow pushed",
          "[runtime][corpus]") {
    const MotionDatabaseContent* content = reference_database();
    if (!content) return;
    FighterSettings settings;
    settings.defence.enabled = false; // every punch that arrives lands
    kumite::test::Bout b(content->view(), "brawler", settings);
    SimulatedUser user(SimulatedKind::punch, 4);
    const RestAnatomy& anatomy = b.brawler.rig->anatomy();
    const int head = anatomy.body_map.joint(BodyPart::head), pelvis = anatomy.body_map.joint(BodyPart::pelvis);
    struct Reaction {
        HeadingFrame heading;
        Eigen::Vector3d push, head_start;
        double t_s;
        bool at_head;
        double largest_m = 0.0;
        Eigen::Vector3d largest = Eigen::Vector3d::Zero();
    };
    std::vector<Reaction> reactions;
    int landed = 0, answered = 0, rocked = 0, back_to_guard = 0; // (rocked: entered the hit_reaction state)
    FighterState state = FighterState::rest;
    for (int frame = 0; frame < 30 * 60; ++frame) {
        const double t = frame / 60.0;
        b.step_against(user, t);
        const auto positions = b.fighter->positions();
        for (const FighterEvent& e : b.fighter->events()) {
            landed += e.type == FighterEvent::Type::user_strike_end && e.user_strike.outcome == UserStrikeOutcome::hit_by_user;
            if (e.type == FighterEvent::Type::state) {
                rocked += e.state == FighterState::hit_reaction;
                back_to_guard += state == FighterState::hit_reaction && e.state == FighterState::recover;
                state = e.state;
            }
            if (e.type != FighterEvent::Type::hit_reaction) continue;
            CHECK(e.clip >= 0);
            answered += e.reaction_blows;
            const HeadingFrame heading = b.fighter->heading();
            reactions.push_back({heading, heading.to_heading(heading.origin + e.user_strike.hand_velocity) - heading.to_heading(heading.origin),
                                 heading.to_heading(positions[head]) - heading.to_heading(positions[pelvis]), t, e.user_strike.at_head});
        }
        b.fighter->clear_events();
        // The head relative to the hips, over the reaction's first half second.
        for (Reaction& r : reactions) {
            if (t - r.t_s > 0.5) continue;
            const Eigen::Vector3d moved = r.heading.to_heading(positions[head]) - r.heading.to_heading(positions[pelvis]) - r.head_start;
            if (moved.norm() > r.largest_m) r.largest_m = moved.norm(), r.largest = moved;
        }
    }
    int moved = 0, along = 0;
    for (const Reaction& r : reactions) {
        moved += r.largest_m > 0.05;
        // A blow to the head pushes it along; one to the body folds it (forward, over the blow, and down).
        const Eigen::Vector3d push(r.push.x(), 0.0, r.push.z()), went(r.largest.x(), 0.0, r.largest.z());
        if (r.at_head) along += push.norm() > 1e-6 && went.norm() > 1e-6 && push.normalized().dot(went.normalized()) > 0.0;
        else along += r.largest.z() > 0.0 && r.largest.y() < 0.0;
    }
    INFO(landed << " landed, " << answered << " answered by " << reactions.size() << " reactions; the head moved 5 cm in " << moved
                << ", along the blow (folding at the body) in " << along);
    CHECK(landed >= 10);
    CHECK(answered >= landed - 1); // (the last may land as the bout ends)
    CHECK(moved >= 0.9 * reactions.size());
    CHECK(along >= 0.7 * reactions.size());
    CHECK(rocked > 0);
    CHECK(back_to_guard >= rocked - 1); // each reaction (or a blow's that came during it) ends back in the guard
}

TEST_CASE("fighter: rocked by a blow, it may still slip the next one, the trunk within its limit", "[runtime][corpus]") {
    const MotionDatabaseContent* content = reference_database();
    const std::filesystem::path boxing = kumite::test::mocap_root() / "cmu14-boxing";
    if (!content || !std::filesystem::exists(boxing / "box-1.bvh")) return;
    // Recorded combinations land blows close together: some next blow comes while the fighter reels from the last.
    const auto count = [&](bool slip_in_hit_reaction, int& violations) {
        int slips_in_reaction = 0;
        for (const std::string bout : {"box-1.bvh brawler", "box-1.bvh scout", "box-2.bvh brawler", "box-2.bvh scout"}) {
            const std::string file = bout.substr(0, bout.find(' ')), character = bout.substr(bout.find(' ') + 1);
            Result<CaptureUser> user = CaptureUser::open((boxing / file).string());
            REQUIRE(user);
            FighterSettings settings;
            settings.defence.slip_in_hit_reaction = slip_in_hit_reaction;
            kumite::test::Bout b(content->view(), character, settings);
            FighterState state = FighterState::rest;
            for (int frame = 0; frame < int(std::min(40.0, user->duration_s()) * 60.0); ++frame) {
                b.step_against_capture(*user, frame);
                for (const FighterEvent& e : b.fighter->events()) {
                    if (e.type == FighterEvent::Type::state) state = e.state;
                    if (e.type == FighterEvent::Type::user_strike) slips_in_reaction += state == FighterState::hit_reaction && e.user_strike.move == DefenceMove::slip;
                    if (e.type == FighterEvent::Type::user_strike_end) violations += e.joint_limit_violations;
                }
                b.fighter->clear_events();
            }
        }
        return slips_in_reaction;
    };
    int violations = 0, violations_without = 0;
    const int slips = count(true, violations), slips_without = count(false, violations_without);
    INFO(slips << " slips started in hit reactions (" << slips_without << " with the option off)");
    CHECK(slips >= 1);
    CHECK(slips_without == 0);
    CHECK(violations == 0); // the lean on top of a reaction's never turns the trunk past its limit
    CHECK(violations_without == 0);
}
