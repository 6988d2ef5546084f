// The fighter's captured blocks on the reference database: against recorded boxers (the forearm on the
// fist's path, most blocks captured), against simulate:punch (in front of the chest, low punches swept down, the hold
// and release no faster than the clip) and with a speed limit (never faster than the clip).

#include "fighter_bout.h"
#include "support/reference_database.h"
#include "support/test_paths.h"

#include "kumite/core/contact_point.h"
#include "kumite/runtime/capture_user.h"
#include "kumite/runtime/fighter.h"
#include "kumite/runtime/simulated_user.h"

#include <catch2/catch.hpp>

#include <filesystem>

using namespace kumite;
using kumite::test::Bout;
using kumite::test::reference_database;

TEST_CASE("fighter: captured blocks against recorded boxers put the forearm on the fist's path", "[runtime][corpus]") {
    const MotionDatabaseContent* content = reference_database();
    const std::filesystem::path boxing = kumite::test::mocap_root() / "cmu14-boxing";
    if (!content || !std::filesystem::exists(boxing / "box-1.bvh")) return;
    // Issue 26's bars: the forearm on the fist's path before the fist reaches the target, median within 5 cm, and at
    // least 70% of the blocks captured ones (4.4 cm, 44 of 54 on 2026-11-26).
    std::vector<double> to_path;
    int blocks = 0, captured = 0;
    for (const std::string bout : {"box-1.bvh brawler", "box-1.bvh scout", "box-1.bvh giant", "box-2.bvh brawler", "box-2.bvh scout", "box-2.bvh giant",
                                   "box-3.bvh brawler", "box-3.bvh scout", "box-3.bvh giant"}) {
        const std::string file = bout.substr(0, bout.find(' ')), character = bout.substr(bout.find(' ') + 1);
        Result<CaptureUser> user = CaptureUser::open((boxing / file).string());
        REQUIRE(user);
        FighterSettings settings;
        settings.defence.captured_blocks = true;
        settings.human_speed_blocks = false; // the clips' own geometry, at the speed the ramp asks (the captured blocks' own bars)
        settings.human_speed_but_strikes = false;
        Bout b(content->view(), character, settings);
        for (int frame = 0; frame < int(std::min(40.0, user->duration_s()) * 60.0); ++frame) {
            b.step_against_capture(*user, frame);
            for (const FighterEvent& e : b.fighter->events()) {
                if (e.type != FighterEvent::Type::user_strike_end || !is_block(e.user_strike.move)) continue;
                ++blocks;
                if (e.user_strike.move != DefenceMove::block_clip) continue;
                ++captured;
                to_path.push_back(e.user_strike.forearm_to_path_m);
            }
            b.fighter->clear_events();
        }
    }
    REQUIRE(to_path.size() >= 10);
    std::nth_element(to_path.begin(), to_path.begin() + to_path.size() / 2, to_path.end());
    const double median = to_path[to_path.size() / 2];
    INFO(captured << " of " << blocks << " blocks captured; forearm to the fist's path, median " << median << " m");
    CHECK(median <= 0.05);
    CHECK(captured >= 0.7 * blocks);
}

TEST_CASE("fighter: a block against a chest punch keeps the forearm in front of the chest", "[runtime][corpus]") {
    const MotionDatabaseContent* content = reference_database();
    if (!content) return;
    // A minute of simulate:punch (as `kumite play --tracker simulate:punch`, seed 1) on the brawler, captured blocks
    // on. Looked at: meeting chest punches further out once brought the forearm 3-8 cm behind the chest joint, inside
    // the torso (README, captured blocks). Measured here: the blocking forearm's wrist and contact point stay in front
    // of the chest joint along the line to the user for every chest block, captured or synthesized.
    FighterSettings settings;
    settings.defence.captured_blocks = true;
    Bout b(content->view(), "brawler", settings);
    const RestAnatomy& anatomy = b.brawler.rig->anatomy();
    SimulatedUser user(SimulatedKind::punch, 1);
    double deepest = 1.0;
    int chest_block_frames = 0;
    for (int frame = 0; frame < 60 * 60; ++frame) {
        const double t = frame / 60.0;
        const Eigen::Vector3d head = b.step_against(user, t);
        b.fighter->clear_events();
        const Defence& defence = b.fighter->defence();
        if (!is_block(defence.move()) || defence.block_weight() <= 0.0 || defence.move_strike().at_head) continue;
        const Eigen::Vector3d chest = b.fighter->part_position(BodyPart::chest);
        Eigen::Vector3d toward_user = head - chest;
        toward_user.y() = 0.0;
        toward_user.normalize();
        const LimbChain& arm = anatomy.limbs[defence.block_arm() == 0 ? int(Limb::arm_l) : int(Limb::arm_r)];
        const auto positions = b.fighter->positions();
        const Eigen::Vector3d wrist = positions[arm.extremity];
        const Eigen::Vector3d contact = wrist + k_block_contact_fraction * (positions[arm.middle] - wrist);
        deepest = std::min({deepest, (wrist - chest).dot(toward_user), (contact - chest).dot(toward_user)});
        ++chest_block_frames;
    }
    INFO("the blocking forearm's deepest point, ahead of the chest joint: " << deepest << " m over " << chest_block_frames << " frames");
    CHECK(chest_block_frames > 100);
    CHECK(deepest > 0.0);
}

TEST_CASE("fighter: a captured block's hold and release move the arm no faster than its clip", "[runtime][corpus]") {
    const MotionDatabaseContent* content = reference_database();
    if (!content) return;
    // A minute of simulate:punch on three characters, captured blocks on (no speed limit asked). After the fist's
    // strike ends the arm holds, then returns to the guard; its fastest move there (wrist or elbow relative to the
    // shoulder, up to the first frame back on the guard) against the clip's own. A straight blend of the wrist
    // between the block and the guard passed by the shoulder, folding the arm shut and swinging the elbow round
    // (20-48 cm in a frame): 51 of 84 blocks within the clip's speed, at worst 7.7 times; turned about the shoulder,
    // 57 of 84 and at worst 6.4 times; with the arm kept within its clip's speed once the fist's strike is over,
    // 84 of 84 and at worst 1.0 times (2026-11-27). The bout is seeded: the same every run. 1% allowed for rounding.
    int blocks = 0, within = 0;
    double worst = 0.0;
    for (const char* character : {"brawler", "runner", "giant"}) {
        FighterSettings settings;
        settings.defence.captured_blocks = true;
        Bout b(content->view(), character, settings);
        const RestAnatomy& anatomy = b.brawler.rig->anatomy();
        SimulatedUser user(SimulatedKind::punch, 1);
        double clip_speed = -1.0, fastest = 0.0, last_t = -1.0;
        int limb = 0;
        Eigen::Vector3d last_wrist = Eigen::Vector3d::Zero(), last_elbow = Eigen::Vector3d::Zero();
        auto close_block = [&] {
            if (clip_speed > 0.0 && fastest > 0.0) {
                ++blocks;
                within += fastest <= 1.01 * clip_speed;
                worst = std::max(worst, fastest / clip_speed);
            }
            clip_speed = -1.0;
            fastest = 0.0;
            last_t = -1.0;
        };
        for (int frame = 0; frame < 60 * 60; ++frame) {
            const double t = frame / 60.0;
            b.step_against(user, t);
            for (const FighterEvent& e : b.fighter->events()) {
                if (e.type == FighterEvent::Type::user_strike) close_block();
                if (e.type == FighterEvent::Type::user_strike_end && e.user_strike.move == DefenceMove::block_clip) {
                    clip_speed = e.user_strike.clip_arm_from_shoulder_mps;
                    last_t = -1.0;
                }
            }
            b.fighter->clear_events();
            const Defence& defence = b.fighter->defence();
            const bool on = defence.move() == DefenceMove::block_clip;
            if (clip_speed <= 0.0 || (!on && last_t < 0.0)) {
                close_block();
                continue;
            }
            if (on) limb = defence.block_arm() == 0 ? int(Limb::arm_l) : int(Limb::arm_r);
            const LimbChain& arm = anatomy.limbs[limb];
            const auto positions = b.fighter->positions();
            const Eigen::Vector3d wrist = positions[arm.extremity] - positions[arm.root], elbow = positions[arm.middle] - positions[arm.root];
            if (last_t >= 0.0) fastest = std::max(fastest, std::max((wrist - last_wrist).norm(), (elbow - last_elbow).norm()) / (t - last_t));
            last_wrist = wrist, last_elbow = elbow, last_t = t;
            if (!on) close_block(); // the release is over: this frame, back on the guard, was the last measured
        }
        close_block();
    }
    INFO(within << " of " << blocks << " blocks held and released within the clip's speed; at worst " << worst << " times it");
    CHECK(blocks >= 40);
    CHECK(within == blocks);
}

TEST_CASE("fighter: a low punch is met by a downward captured block, one at the head by a rising one", "[runtime][corpus]") {
    const MotionDatabaseContent* content = reference_database();
    if (!content) return;
    // Issue 26: low attacks (a punch to the solar plexus) get a downward block. A straight punch of the user's right
    // hand at 6 m/s from 0.9 m away to 20 cm below the fighter's chest joint, then one to its head.
    for (const double below_chest : {0.2, -1.0}) { // -1: at the head
        FighterSettings settings;
        settings.defence.captured_blocks = true;
        Bout b(content->view(), "brawler", settings);
        const Eigen::Vector3d head(0.0, 1.65, 1.2);
        UserHands hands;
        hands.present = {true, true};
        const Eigen::Vector3d guard_left = head + Eigen::Vector3d(0.15, -0.2, -0.2), guard_right = head + Eigen::Vector3d(-0.15, -0.2, -0.2);
        hands.world = {guard_left, guard_right};
        const UserStrikeEvent* seen = nullptr;
        Eigen::Vector3d from = guard_right, direction = Eigen::Vector3d::Zero();
        double launched = -1.0;
        for (int frame = 0; frame < 4 * 60 && !seen; ++frame) {
            const double t = frame / 60.0;
            if (frame == 3 * 60) { // the fighter stands by now; the punch starts 0.9 m in front of its target
                const Eigen::Vector3d chest = b.fighter->part_position(BodyPart::chest);
                const Eigen::Vector3d target = below_chest < 0.0 ? b.fighter->part_position(BodyPart::head) : chest - Eigen::Vector3d(0.0, below_chest, 0.0);
                Eigen::Vector3d toward_user = head - chest;
                toward_user.y() = 0.0;
                from = target + 0.9 * toward_user.normalized() + Eigen::Vector3d(0.0, 0.1, 0.0);
                direction = (target - from).normalized();
                launched = t;
            }
            if (launched >= 0.0) hands.world[1] = from + 6.0 * (t - launched) * direction;
            b.fighter->step(t, &head, &hands);
            for (const FighterEvent& e : b.fighter->events()) {
                if (e.type == FighterEvent::Type::user_strike) b.events.push_back(e);
            }
            b.fighter->clear_events();
            if (!b.events.empty()) seen = &b.events.front().user_strike;
        }
        REQUIRE(seen != nullptr);
        INFO((below_chest < 0.0 ? "at the head: " : "low: ") << defence_move_name(seen->move) << ", clip " << seen->block_clip << ", seen at " << seen->t_s << " s, " << seen->time_to_impact_s << " s before the impact, at the head " << seen->at_head);
        REQUIRE(seen->move == DefenceMove::block_clip);
        const StrikeKind kind = b.db.clips[seen->block_clip].strike_kind();
        CHECK(kind == (below_chest < 0.0 ? StrikeKind::rising : StrikeKind::downward));
    }
}

TEST_CASE("fighter: with a block speed limit a captured block moves the arm no faster than its clip", "[runtime][corpus]") {
    const MotionDatabaseContent* content = reference_database();
    if (!content) return;
    // The pop bar, asked for (kumite play --set defence.block_clip_max_speed_ratio=1): every captured block's fastest arm move
    // (wrist or elbow relative to the shoulder, from the frame it starts) within its clip's own, where without the
    // limit most are faster (the fist leaves 2-8 frames: README, captured blocks). 1% allowed for rounding.
    for (const double limit : {1.0, 0.0}) {
        FighterSettings settings;
        settings.defence.captured_blocks = true;
        settings.defence.block_clip_max_speed_ratio = limit;
        Bout b(content->view(), "brawler", settings);
        SimulatedUser user(SimulatedKind::punch, 1);
        int blocks = 0, within = 0;
        double worst = 0.0;
        for (int frame = 0; frame < 40 * 60; ++frame) {
            b.step_against(user, frame / 60.0);
            for (const FighterEvent& e : b.fighter->events()) {
                const UserStrikeEvent& strike = e.user_strike;
                if (e.type != FighterEvent::Type::user_strike_end || strike.move != DefenceMove::block_clip || strike.arm_from_shoulder_mps < 0.0) continue;
                ++blocks;
                within += strike.arm_from_shoulder_mps <= 1.01 * strike.clip_arm_from_shoulder_mps;
                worst = std::max(worst, strike.arm_from_shoulder_mps / strike.clip_arm_from_shoulder_mps);
            }
            b.fighter->clear_events();
        }
        INFO("limit " << limit << ": " << within << " of " << blocks << " captured blocks within their clip's speed, at worst " << worst << " times it");
        REQUIRE(blocks >= 10);
        if (limit > 0.0) {
            CHECK(within == blocks);
        } else {
            CHECK(within < blocks / 2);
        }
    }
}
