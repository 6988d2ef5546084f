// Adaptation on the golden database (a right kick and its mirror, a left punch, the guard): the constraint ramp's
// shape, the three reachability classes, joint limits, no jitter near an unreachable target, planted support
// feet, exact bone lengths, and the support-foot rule of the retrieval.

#include "kumite/core/strike_adaptation.h"
#include "kumite/formats/motion_database_file.h"
#include "support/standing_character.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

using namespace kumite;

namespace {

// The golden database, a retriever, and a character standing in its guard.
struct Scene {
    MotionDatabase database;
    std::unique_ptr<Retriever> retriever;
    std::unique_ptr<kumite::test::StandingCharacter> character;

    explicit Scene(const std::string& name) {
        Result<MotionDatabase> opened = MotionDatabase::open(kumite::test::source_dir() / "data/golden/golden-v2.kdb");
        REQUIRE(opened.has_value());
        database = std::move(*opened);
        retriever = std::make_unique<Retriever>(database.view());
        character = std::make_unique<kumite::test::StandingCharacter>(name, database.view());
    }
    const RestAnatomy& anatomy() const { return character->anatomy; }
    const CharacterRig& rig() const { return *character->rig; }

    RetrievalQuery query(const char* semantics, Side side, const Eigen::Vector3d& target) const {
        return character->order(*retriever, semantics, side, target);
    }

    // Retrieves and begins; returns the plan.
    StrikePlan begin(StrikeAdapter& adapter, const char* semantics, Side side, const Eigen::Vector3d& target) const {
        RetrievalWorkspace workspace = retriever->make_workspace();
        const RetrievalResult result = retriever->query(query(semantics, side, target), workspace);
        REQUIRE(result.found);
        const StrikePlan plan{result.clip, result.start_frame, result.contact_frame, result.clip_to_world, target};
        adapter.begin(plan, character->mir, {true, true}, character->ankles);
        return plan;
    }
};

} // namespace

TEST_CASE("adaptation: the constraint ramp rises and falls smoothly", "[adaptation]") {
    const double t0 = 2.0, tc = 12.0, recovery = 8.0;
    CHECK(constraint_ramp(0.0, t0, tc, recovery) == 0.0);
    CHECK(constraint_ramp(t0, t0, tc, recovery) == 0.0);
    CHECK(constraint_ramp(tc, t0, tc, recovery) == 1.0);
    CHECK(constraint_ramp(tc + recovery, t0, tc, recovery) == 0.0);
    CHECK(constraint_ramp(40.0, t0, tc, recovery) == 0.0);
    CHECK(constraint_ramp(7.0, t0, tc, recovery) == Approx(0.5));
    const double h = 1e-4;
    auto slope = [&](double t) { return (constraint_ramp(t + h, t0, tc, recovery) - constraint_ramp(t - h, t0, tc, recovery)) / (2 * h); };
    // C1: no kink where the pieces meet.
    CHECK(std::abs(slope(t0)) < 1e-3);
    CHECK(std::abs(slope(tc)) < 1e-3);
    CHECK(std::abs(slope(tc + recovery)) < 1e-3);
    double previous = 0.0;
    for (double t = t0; t <= tc; t += 0.25) {
        const double value = constraint_ramp(t, t0, tc, recovery);
        CHECK(value >= previous); // monotone rise
        previous = value;
    }
}

TEST_CASE("adaptation: a reachable target is met at the contact frame (the trunk leaning for what is past limb_reach_share), with exact bones and planted feet", "[adaptation]") {
    for (const char* character : {"kid", "scout", "brawler", "runner", "giant"}) {
        const Scene scene(character);
        StrikeAdapter adapter(scene.rig(), scene.database.view());
        // A point between the shoulder and where the punch passes anyway: well inside the arm's reach.
        RetrievalWorkspace workspace = scene.retriever->make_workspace();
        const RetrievalResult natural =
            scene.retriever->query(scene.query("punch", Side::left, Eigen::Vector3d(0.1, 1.0, 0.5)), workspace);
        REQUIRE(natural.found);
        const Eigen::Vector3d shoulder = scene.rig().positions()[scene.anatomy().limbs[int(Limb::arm_l)].root];
        const Eigen::Vector3d target = shoulder + 0.8 * (natural.contact_point_world - shoulder);
        scene.begin(adapter, "punch", Side::left, target);
        Pose pose;
        INFO(character);
        for (int i = 0; i < adapter.frame_count(); ++i) {
            const AdaptedFrame frame = adapter.step(i, pose);
            CHECK(bone_length_error(scene.character->skeleton(), adapter.positions()) < 1e-9);
            for (int foot = 0; foot < 2; ++foot) {
                if (adapter.support_feet()[foot]) CHECK((adapter.positions()[scene.anatomy().limbs[2 + foot].extremity] - adapter.support_pins()[foot]).norm() < 1e-6);
            }
            if (frame.contact) {
                // Within the arm's reach; past the share of it the limb carries (the runner's target, with the clip's
                // trunk as it is at the contact), the trunk brings the shoulder nearer as far as that pays.
                CHECK(frame.reach != Reach::unreachable);
                CHECK((frame.effector - target).norm() < 1e-6);
                CHECK(frame.ramp == 1.0);
            }
        }
        CHECK((adapter.support_feet()[0] || adapter.support_feet()[1])); // the feet the clip keeps down are pinned
    }
}

TEST_CASE("adaptation: beyond the arm the trunk leans within its limits, far away it stops at the closest point", "[adaptation]") {
    const Scene scene("brawler");
    StrikeAdapter adapter(scene.rig(), scene.database.view());
    const AdaptationSettings limits;
    const Eigen::Vector3d shoulder = scene.rig().positions()[scene.anatomy().limbs[int(Limb::arm_l)].root];
    const double arm = scene.anatomy().limbs[int(Limb::arm_l)].length();
    Pose pose;

    // Past the arm's reach in front of the shoulder: the first distance where the trunk has to lean.
    AdaptedFrame near;
    Eigen::Vector3d near_target;
    for (double extra = 0.0; extra < 0.6 && near.reach != Reach::torso; extra += 0.02) {
        near_target = shoulder + Eigen::Vector3d(0.0, 0.0, arm + extra);
        scene.begin(adapter, "punch", Side::left, near_target);
        near = adapter.step(adapter.contact_index(), pose);
    }
    REQUIRE(near.reach == Reach::torso);
    CHECK((near.effector - near_target).norm() <= 0.001 + 1e-9);
    CHECK(near.pivot_turn_rad[0] <= limits.clavicle_limit_rad + 1e-9);
    CHECK(near.pivot_turn_rad[1] <= limits.chest_limit_rad + 1e-9);
    CHECK(near.pivot_turn_rad[2] <= limits.spine_base_limit_rad + 1e-9);

    // Two metres out: unreachable; every pivot at most at its limit, the arm stretched towards the target.
    const Eigen::Vector3d far_target = shoulder + Eigen::Vector3d(0.0, 0.0, 2.0);
    scene.begin(adapter, "punch", Side::left, far_target);
    const AdaptedFrame far = adapter.step(adapter.contact_index(), pose);
    CHECK(far.reach == Reach::unreachable);
    CHECK(far.pivot_turn_rad[0] <= limits.clavicle_limit_rad + 1e-9);
    CHECK(far.pivot_turn_rad[1] <= limits.chest_limit_rad + 1e-9);
    CHECK(far.pivot_turn_rad[2] <= limits.spine_base_limit_rad + 1e-9);
    const Eigen::Vector3d arm_root = adapter.positions()[scene.anatomy().limbs[int(Limb::arm_l)].root];
    CHECK((far.effector - arm_root).norm() == Approx(arm).epsilon(1e-3)); // fully extended
    CHECK((far.effector - arm_root).normalized().dot((far_target - arm_root).normalized()) > 0.999); // pointing at it
    CHECK(bone_length_error(scene.character->skeleton(), adapter.positions()) < 1e-9);
}

TEST_CASE("adaptation: near an unreachable target the effector moves smoothly as the target moves", "[adaptation]") {
    const Scene scene("scout");
    StrikeAdapter adapter(scene.rig(), scene.database.view());
    const Eigen::Vector3d shoulder = scene.rig().positions()[scene.anatomy().limbs[int(Limb::arm_l)].root];
    const double arm = scene.anatomy().limbs[int(Limb::arm_l)].length();
    Pose pose;
    std::vector<Eigen::Vector3d> path;
    const double step = 0.005;
    for (int k = 0; k < 60; ++k) { // the target slides across the edge of the reach, 5 mm at a time
        const Eigen::Vector3d target = shoulder + Eigen::Vector3d(-0.15 + k * step, 0.05, arm + 0.25);
        scene.begin(adapter, "punch", Side::left, target);
        path.push_back(adapter.step(adapter.contact_index(), pose).effector);
    }
    double worst_jump = 0.0, least_agreement = 1.0;
    for (std::size_t k = 1; k < path.size(); ++k) worst_jump = std::max(worst_jump, (path[k] - path[k - 1]).norm());
    for (std::size_t k = 1; k + 1 < path.size(); ++k) {
        least_agreement = std::min(least_agreement, (path[k + 1] - path[k]).normalized().dot((path[k] - path[k - 1]).normalized()));
    }
    INFO("largest step " << worst_jump << " m, least agreement of successive steps " << least_agreement);
    CHECK(worst_jump < 3 * step);   // no jump bigger than a few target steps
    CHECK(least_agreement > 0.5);   // and no back and forth
    // The same frame and target give the same pose: nothing carries over from frame to frame.
    const Eigen::Vector3d target = shoulder + Eigen::Vector3d(0.0, 0.05, arm + 0.25);
    scene.begin(adapter, "punch", Side::left, target);
    const Eigen::Vector3d first = adapter.step(adapter.contact_index(), pose).effector;
    adapter.step(0, pose);
    CHECK(adapter.step(adapter.contact_index(), pose).effector == first);
}

TEST_CASE("adaptation: a kick keeps its support foot down, and never starts on the kicking leg", "[adaptation]") {
    const Scene scene("runner");
    // Support-foot rule in the retrieval: with only the right foot down, a right kick cannot start; a left can.
    RetrievalWorkspace workspace = scene.retriever->make_workspace();
    RetrievalQuery on_right_foot = scene.query("kick", Side::right, Eigen::Vector3d(0.0, 1.0, 0.8));
    on_right_foot.planted_feet = db_pose_right_foot_planted;
    CHECK_FALSE(scene.retriever->query(on_right_foot, workspace).found);
    CHECK_FALSE(scene.retriever->query_exhaustive(on_right_foot).found);
    on_right_foot.side = Side::none;
    const RetrievalResult left_kick = scene.retriever->query(on_right_foot, workspace);
    REQUIRE(left_kick.found);
    CHECK(scene.database.view().clips[left_kick.clip].segment == int(BodyPart::foot_l));

    // Adapted: the support foot does not move or lift while the other kicks.
    StrikeAdapter adapter(scene.rig(), scene.database.view());
    scene.begin(adapter, "kick", Side::right, Eigen::Vector3d(-0.1, 1.0, 0.7));
    CHECK(adapter.support_feet()[0]);
    CHECK_FALSE(adapter.support_feet()[1]);
    Pose pose;
    double highest_right = 0.0;
    for (int i = 0; i < adapter.frame_count(); ++i) {
        adapter.step(i, pose);
        const Eigen::Vector3d left_ankle = adapter.positions()[scene.anatomy().limbs[int(Limb::leg_l)].extremity];
        CHECK((left_ankle - adapter.support_pins()[0]).norm() < 1e-6);
        highest_right = std::max(highest_right, adapter.positions()[scene.anatomy().limbs[int(Limb::leg_r)].extremity].y());
    }
    CHECK(highest_right > 0.6); // the kicking foot did rise
}

TEST_CASE("adaptation: a target moved during the strike is met at the contact, the hit point's path staying smooth", "[adaptation]") {
    for (const char* character : {"kid", "brawler", "giant"}) {
        const Scene scene(character);
        StrikeAdapter steered(scene.rig(), scene.database.view()), planned(scene.rig(), scene.database.view());
        RetrievalWorkspace workspace = scene.retriever->make_workspace();
        const RetrievalResult natural =
            scene.retriever->query(scene.query("punch", Side::left, Eigen::Vector3d(0.1, 1.0, 0.5)), workspace);
        REQUIRE(natural.found);
        const Eigen::Vector3d shoulder = scene.rig().positions()[scene.anatomy().limbs[int(Limb::arm_l)].root];
        const Eigen::Vector3d first_target = shoulder + 0.8 * (natural.contact_point_world - shoulder);
        // The head drifts 1 cm a frame sideways and down during the strike: 8 cm by the time it stops moving.
        const Eigen::Vector3d drift(0.008, -0.006, 0.0);
        const StrikePlan plan = scene.begin(steered, "punch", Side::left, first_target);
        scene.begin(planned, "punch", Side::left, first_target);
        Pose pose;
        INFO(character);
        Eigen::Vector3d target = first_target;
        std::vector<Eigen::Vector3d> path;
        for (int i = 0; i <= steered.contact_index(); ++i) {
            if (i > 0 && i <= 10 && i < steered.contact_index()) {
                target += drift;
                steered.retarget(target);
            }
            const AdaptedFrame frame = steered.step(i, pose);
            path.push_back(frame.effector);
            CHECK(bone_length_error(scene.character->skeleton(), steered.positions()) < 1e-9);
            if (frame.contact) CHECK((frame.effector - target).norm() < 1e-6);
        }
        CHECK(steered.plan().target_world == target);
        CHECK(steered.stop_point() == target);
        CHECK(plan.target_world == first_target);
        // Smooth: no frame-to-frame change of the hit point's velocity larger than the unsteered strike's largest
        // plus what the drift adds (1 cm a frame at most).
        auto largest_velocity_change = [](const std::vector<Eigen::Vector3d>& points) {
            double largest = 0.0;
            for (std::size_t k = 2; k < points.size(); ++k) largest = std::max(largest, (points[k] - 2.0 * points[k - 1] + points[k - 2]).norm());
            return largest;
        };
        std::vector<Eigen::Vector3d> planned_path;
        for (int i = 0; i <= planned.contact_index(); ++i) planned_path.push_back(planned.step(i, pose).effector);
        CHECK(largest_velocity_change(path) <= largest_velocity_change(planned_path) + drift.norm());
    }
}

TEST_CASE("adaptation: a target out of reach that moves on after the strike began stops the fist where it got to, no jump back", "[adaptation]") {
    // The stop point out of reach was the closest point found at begin(), moved along with the target by each
    // retarget: the fist, stopped where it really got to, was pulled across the gap in one frame after the contact
    // (a giant's punch at a retreating head: 0.35 m, 21 m/s).
    const Scene scene("giant");
    StrikeAdapter adapter(scene.rig(), scene.database.view());
    const Eigen::Vector3d shoulder = scene.rig().positions()[scene.anatomy().limbs[int(Limb::arm_l)].root];
    const double arm = scene.anatomy().limbs[int(Limb::arm_l)].length();
    scene.begin(adapter, "punch", Side::left, shoulder + Eigen::Vector3d(0.0, 0.0, arm + 0.4));
    Pose pose;
    Eigen::Vector3d previous = Eigen::Vector3d::Zero(), at_contact = Eigen::Vector3d::Zero();
    double step_after_m = -1.0;
    for (int i = 0; i < adapter.frame_count(); ++i) {
        if (i == adapter.contact_index() - 2) adapter.retarget(shoulder + Eigen::Vector3d(0.0, 0.0, arm + 1.0)); // it backs away
        const AdaptedFrame frame = adapter.step(i, pose);
        if (frame.contact) {
            CHECK(frame.reach == Reach::unreachable);
            at_contact = frame.effector;
        }
        if (i == adapter.contact_index() + 1) step_after_m = (frame.effector - previous).norm();
        previous = frame.effector;
    }
    INFO("the step after the contact " << step_after_m << " m");
    CHECK((adapter.stop_point() - at_contact).norm() < 1e-9); // where it got to
    CHECK(step_after_m >= 0.0);
    CHECK(step_after_m < 0.08); // the recovery at the clip's own pace, not 0.6 m back to where the target went
}

TEST_CASE("adaptation: the offset ramp starts at 0 and rises with the clip's own hit point, from any start frame", "[adaptation]") {
    // The ramp followed the hit point's distance to its contact point as a share of the farthest it was: from a
    // start after which the fist first draws back, that share was already large at the start, and the whole
    // offset came in one frame (a kid's punch: 0.75 of 0.3 m between the first two half frames, 22 m/s). Now the
    // share of the hit point's path covered: every start frame of the golden punch, the ramp rises from 0 no faster
    // than the hit point itself moves along its path.
    const Scene scene("scout");
    StrikeAdapter adapter(scene.rig(), scene.database.view());
    const Eigen::Vector3d shoulder = scene.rig().positions()[scene.anatomy().limbs[int(Limb::arm_l)].root];
    const StrikePlan retrieved = scene.begin(adapter, "punch", Side::left, shoulder + Eigen::Vector3d(0.1, 0.0, 0.5));
    const MotionDatabaseView db = scene.database.view();
    const DbClip& clip = db.clips[retrieved.clip];
    auto hit_point = [&](int frame) {
        const float* p = db.poses[clip.first_pose + frame].hit_point;
        return Eigen::Vector3d(p[0], p[1], p[2]);
    };
    const int contact_frame = retrieved.start_frame + adapter.contact_index();
    int starts = 0;
    for (int start = 0; start + 3 <= contact_frame; ++start) {
        StrikePlan plan = retrieved;
        plan.start_frame = start;
        adapter.begin(plan, scene.character->mir, {true, true}, scene.character->ankles);
        const int contact = adapter.contact_index();
        double path = 0.0;
        for (int i = 1; i <= contact; ++i) path += (hit_point(start + i) - hit_point(start + i - 1)).norm();
        INFO("start " << start << ", contact " << contact << ", path " << path << " m");
        CHECK(adapter.offset_ramp(0.0) == 0.0);
        CHECK(adapter.offset_ramp(double(contact)) == Approx(1.0));
        double previous = 0.0;
        for (int i = 1; i <= contact; ++i) {
            const double ramp = adapter.offset_ramp(double(i));
            const double moved = (hit_point(start + i) - hit_point(start + i - 1)).norm();
            CHECK(ramp >= previous - 1e-12);
            CHECK(ramp - previous <= 1.5 * moved / path + 1e-9); // smoothstep's steepest slope, times the share moved
            previous = ramp;
        }
        ++starts;
    }
    CHECK(starts >= 5);
}
