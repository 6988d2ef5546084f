// Strikes that land like strikes (issues 13, 44), on the reference database for all five characters: the contact is
// where the limb still travels fast (90% of its way to the annotated hit), the fist or foot does not travel on through the target after it, a dodged strike
// follows through, and no elbow or knee bends the wrong way, in reach or far out of it.

#include "support/reference_database.h"
#include "support/standing_character.h"

#include "kumite/core/joint_limits.h"
#include "kumite/core/strike_adaptation.h"

#include <random>

using namespace kumite;
using kumite::test::reference_database;

namespace {

const char* const k_characters[] = {"kid", "scout", "brawler", "runner", "giant"};

struct StrikeRun {
    bool found = false;
    int contact = 0;
    double contact_error_m = 0.0;
    double past_target_m = 0.0; // the most the effector got past the target after the contact, along its approach
    double reported_past_m = 0.0; // the same as the adapter reports it (AdaptedFrame::past_target_m: through the target)
    int violations = 0;
    std::string clip;
};

// Plays a strike at `target` and measures how far past the target the effector goes after the contact, along
// the direction it arrived in (from its own path over the two frames before the contact; this test does not
// trust the adapter's own approach).
StrikeRun run_strike(const MotionDatabaseView& db, const Retriever& retriever, const kumite::test::StandingCharacter& character,
                     const char* semantics, Side side, const Eigen::Vector3d& target, bool impact) {
    StrikeRun run;
    RetrievalWorkspace workspace = retriever.make_workspace();
    const RetrievalResult found = retriever.query(character.order(retriever, semantics, side, target), workspace);
    if (!found.found) return run;
    run.found = true;
    run.clip = db.string(db.clips[found.clip].name);
    StrikeAdapter adapter(*character.rig, db);
    adapter.begin({found.clip, found.start_frame, found.contact_frame, found.clip_to_world, target}, character.mir, {true, true},
                  character.ankles);
    adapter.set_impact(impact);
    run.contact = adapter.contact_index();
    // The contact: where the hit point has covered 90% of its way to the annotated hit, still travelling.
    CHECK(found.contact_frame == db_clip_contact_frame(db, db.clips[found.clip], 0.9, RetrievalSettings{}.contact_speed_share));
    CHECK(found.contact_frame <= int(db.clips[found.clip].hit_frame));
    std::vector<Eigen::Vector3d> path;
    Eigen::Vector3d root_at_contact = Eigen::Vector3d::Zero();
    Pose pose;
    const int effector = adapter.effector_joint();
    const int root = character.skeleton().parents[character.skeleton().parents[effector]]; // shoulder or hip
    for (int i = 0; i < adapter.frame_count(); ++i) {
        const AdaptedFrame frame = adapter.step(i, pose);
        path.push_back(frame.effector);
        run.reported_past_m = std::max(run.reported_past_m, frame.past_target_m);
        if (i == run.contact) root_at_contact = adapter.positions()[root];
        run.violations += joint_violation_count(frame.joint_violations);
    }
    run.contact_error_m = (path[run.contact] - target).norm();
    // The approach: how the effector moved over the frame before the contact (two if it barely moved; from the
    // shoulder or hip if it arrived at rest).
    Eigen::Vector3d approach = (path[run.contact] - root_at_contact).normalized();
    for (int back = 1; back <= 2 && run.contact - back >= 0; ++back) {
        const Eigen::Vector3d arriving = path[run.contact] - path[run.contact - back];
        if (arriving.norm() > 0.01) {
            approach = arriving.normalized();
            break;
        }
    }
    for (std::size_t i = std::size_t(run.contact) + 1; i < path.size(); ++i) {
        run.past_target_m = std::max(run.past_target_m, (path[i] - path[run.contact]).dot(approach));
    }
    return run;
}

// Targets in front of the character, between its hips and its head, within its limb's reach of the limb's root.
std::vector<Eigen::Vector3d> targets_in_reach(const kumite::test::StandingCharacter& character, Limb limb, int count, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const LimbChain& chain = character.anatomy.limbs[int(limb)];
    const Eigen::Vector3d root = character.rig->positions()[chain.root];
    std::vector<Eigen::Vector3d> targets;
    while (int(targets.size()) < count) {
        const Eigen::Vector3d target(-0.3 + 0.6 * unit(random), character.pelvis_y + (character.head_y - character.pelvis_y) * unit(random),
                                     0.2 + 0.8 * unit(random));
        if ((target - root).norm() < 0.9 * chain.length() && target.z() > root.z() + 0.15) targets.push_back(target);
    }
    return targets;
}

} // namespace

TEST_CASE("impact: a kick's foot and a punch's fist stop at the target after the contact, for every character", "[adaptation][corpus]") {
    const MotionDatabaseContent* content = reference_database();
    if (!content) return;
    const MotionDatabaseView db = content->view();
    const Retriever retriever(db);
    int strikes = 0;
    for (const char* name : k_characters) {
        const kumite::test::StandingCharacter character(name, db);
        for (const Side side : {Side::left, Side::right}) {
            for (const char* semantics : {"kick", "punch"}) {
                const bool kick = std::string(semantics) == "kick";
                const Limb limb = kick ? (side == Side::left ? Limb::leg_l : Limb::leg_r) : (side == Side::left ? Limb::arm_l : Limb::arm_r);
                for (const Eigen::Vector3d& target : targets_in_reach(character, limb, 4, 7u + strikes)) {
                    const StrikeRun run = run_strike(db, retriever, character, semantics, side, target, true);
                    if (!run.found) continue;
                    ++strikes;
                    INFO(name << " " << semantics << " " << int(side) << " at " << target.transpose() << ": " << run.clip);
                    CHECK(run.contact_error_m < 0.01);
                    CHECK(run.past_target_m <= 0.03);
                    CHECK(run.reported_past_m <= 0.03);
                    CHECK(run.violations == 0);
                }
            }
        }
    }
    CHECK(strikes >= 60);
}

TEST_CASE("impact: a dodged kick follows through past where the target was", "[adaptation][corpus]") {
    // The same kicks without the impact: the clip's own swing carries the foot on through the target. This is
    // what every kick did before the impact existed, and what the test above would catch.
    const MotionDatabaseContent* content = reference_database();
    if (!content) return;
    const MotionDatabaseView db = content->view();
    const Retriever retriever(db);
    const kumite::test::StandingCharacter character("brawler", db);
    // The adapter's own figure (what strike events and reports give as overshoot) sees it too.
    double farthest = 0.0, farthest_reported = 0.0;
    for (const Eigen::Vector3d& target : targets_in_reach(character, Limb::leg_r, 8, 3u)) {
        const StrikeRun stopped = run_strike(db, retriever, character, "kick", Side::right, target, true);
        const StrikeRun through = run_strike(db, retriever, character, "kick", Side::right, target, false);
        REQUIRE(stopped.found);
        CHECK(stopped.past_target_m <= 0.03);
        CHECK(stopped.reported_past_m <= 0.03);
        CHECK(through.violations == 0);
        farthest = std::max(farthest, through.past_target_m);
        farthest_reported = std::max(farthest_reported, through.reported_past_m);
    }
    CHECK(farthest > 0.05);
    CHECK(farthest_reported > 0.05);
}

TEST_CASE("impact: far targets, out of reach: the limb extends towards them with no violation and no pass-through", "[adaptation][corpus]") {
    const MotionDatabaseContent* content = reference_database();
    if (!content) return;
    const MotionDatabaseView db = content->view();
    const Retriever retriever(db);
    for (const char* name : k_characters) {
        const kumite::test::StandingCharacter character(name, db);
        for (const char* semantics : {"kick", "punch"}) {
            const bool kick = std::string(semantics) == "kick";
            const LimbChain& chain = character.anatomy.limbs[int(kick ? Limb::leg_r : Limb::arm_r)];
            const Eigen::Vector3d root = character.rig->positions()[chain.root];
            for (const double beyond : {0.3, 0.8}) {
                const Eigen::Vector3d target = root + Eigen::Vector3d(0.0, 0.1, 1.0).normalized() * (chain.length() + beyond);
                const StrikeRun run = run_strike(db, retriever, character, semantics, Side::right, target, true);
                REQUIRE(run.found);
                INFO(name << " " << semantics << " " << beyond << " m beyond");
                CHECK(run.violations == 0);
                CHECK(run.past_target_m <= 0.03); // past the closest point reached, which is the contact
                CHECK(run.contact_error_m < beyond);                    // the limb (and trunk) extend towards it
                if (beyond > 0.5) CHECK(run.contact_error_m > 0.01);     // and it is truly out of reach
            }
        }
    }
}

TEST_CASE("joint limits: a knee bent backwards is a violation, the clip's own bend is not", "[adaptation]") {
    const Eigen::Vector3d hip(0.0, 1.0, 0.0), ankle(0.0, 0.15, 0.05);
    const Eigen::Vector3d knee_forward(0.0, 0.58, 0.15), knee_backward(0.0, 0.58, -0.12), knee_straight(0.0, 0.575, 0.025);
    const Eigen::Vector3d clip_bend = limb_bend_direction(hip, knee_forward, ankle);
    REQUIRE(clip_bend.norm() == Approx(1.0));
    CHECK(clip_bend.z() > 0.9);
    CHECK_FALSE(limb_bend_flipped(limb_bend_direction(hip, knee_forward, ankle), clip_bend));
    CHECK(limb_bend_flipped(limb_bend_direction(hip, knee_backward, ankle), clip_bend));
    CHECK(limb_bend_direction(hip, knee_straight, ankle).isZero()); // straight: no bend to flip
    CHECK_FALSE(limb_bend_flipped(limb_bend_direction(hip, knee_straight, ankle), clip_bend));
    // An elbow bent sideways by less than the flip angle is not a violation; at 120 degrees it is.
    const Eigen::Vector3d shoulder(0.0, 1.4, 0.0), wrist(0.0, 1.4, 0.5);
    const Eigen::Vector3d elbow_down(0.0, 1.28, 0.25), elbow_side(0.12 * std::sin(1.0), 1.4 - 0.12 * std::cos(1.0), 0.25);
    const Eigen::Vector3d elbow_up_side(0.12 * std::sin(2.1), 1.4 - 0.12 * std::cos(2.1), 0.25);
    const Eigen::Vector3d down = limb_bend_direction(shoulder, elbow_down, wrist);
    CHECK_FALSE(limb_bend_flipped(limb_bend_direction(shoulder, elbow_side, wrist), down));
    CHECK(limb_bend_flipped(limb_bend_direction(shoulder, elbow_up_side, wrist), down));
}

TEST_CASE("impact: near targets get a shorter strike, not a full one pulled back onto them at the end", "[adaptation][corpus]") {
    // Seen in filmstrips with the paper's time ramp: the fist reaches its full extension while the ramp lags,
    // then the offset pulls it back onto the target, and it arrives moving towards the body. The progress ramp
    // (the default) follows the clip's own approach to its hit instead. The loop shows on clips whose hit is at
    // full extension after a long approach (Bandai's punches): first on those alone, then on the whole database.
    const MotionDatabaseContent* content = reference_database();
    if (!content) return;
    const MotionDatabaseView db = content->view();
    const Retriever retriever(db);
    std::vector<int> not_bandai;
    for (int c = 0; c < int(db.clips.size()); ++c) {
        if (!db.string(db.clips[c].source).starts_with("bandai-namco-1/")) not_bandai.push_back(c);
    }
    for (const bool bandai_only : {true, false}) {
        int towards_body[2] = {0, 0}, strikes = 0;
        std::string looped; // the clips that arrive towards the body with the progress ramp
        for (const char* name : k_characters) {
            const kumite::test::StandingCharacter character(name, db);
            for (const Side side : {Side::left, Side::right}) {
                const Limb limb = side == Side::left ? Limb::arm_l : Limb::arm_r;
                const LimbChain& chain = character.anatomy.limbs[int(limb)];
                const Eigen::Vector3d shoulder = character.rig->positions()[chain.root];
                for (const double fraction : {0.5, 0.6, 0.7}) {
                    for (const double height : {-0.15, 0.0, 0.1}) {
                        const Eigen::Vector3d target = shoulder + fraction * chain.length() * Eigen::Vector3d(0.0, height, 1.0).normalized();
                        RetrievalWorkspace workspace = retriever.make_workspace();
                        // Straight punches: a hook's fist arrives sweeping across, towards the midline, by design.
                        RetrievalQuery order = character.order(retriever, "punch", side, target);
                        order.kind = StrikeKind::straight;
                        if (bandai_only) order.excluded_clips = not_bandai;
                        const RetrievalResult found = retriever.query(order, workspace);
                        REQUIRE(found.found);
                        ++strikes;
                        for (const OffsetRamp ramp : {OffsetRamp::progress, OffsetRamp::time}) {
                            AdaptationSettings settings;
                            settings.offset_ramp = ramp;
                            StrikeAdapter adapter(*character.rig, db, settings);
                            adapter.begin({found.clip, found.start_frame, found.contact_frame, found.clip_to_world, target}, character.mir,
                                          {true, true}, character.ankles);
                            Pose pose;
                            const Eigen::Vector3d before = adapter.step(std::max(0, adapter.contact_index() - 1), pose).effector;
                            const AdaptedFrame contact = adapter.step(adapter.contact_index(), pose);
                            const Eigen::Vector3d root = adapter.positions()[chain.root];
                            const Eigen::Vector3d arriving = contact.effector - before;
                            const bool towards = arriving.norm() > 0.01 && arriving.dot(contact.effector - root) < 0.0;
                            towards_body[ramp == OffsetRamp::time] += towards;
                            if (towards && ramp == OffsetRamp::progress) looped += std::string(db.string(db.clips[found.clip].name)) + " ";
                        }
                    }
                }
            }
        }
        INFO((bandai_only ? "Bandai's punches" : "every punch") << ": arriving towards the body: progress " << towards_body[0] << ", time "
                                                                << towards_body[1] << " of " << strikes << ": " << looped);
        // The progress ramp never loops more often than the time ramp. (With the contact at the annotated hit, the
        // time ramp looped on 8-12 of Bandai's 90; with the contact where the fist still travels, both
        // rarely do.)
        if (bandai_only) CHECK(towards_body[0] <= towards_body[1]);
        CHECK(towards_body[0] <= strikes / 10);
    }
}
