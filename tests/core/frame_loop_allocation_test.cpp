// What a frame loop calls allocates nothing once set up: retrieval queries (with the caller's workspace) and
// adapting a strike frame by frame (after the adapter's first strike), the fighter and a whole bout's step.

#include "kumite/core/strike_adaptation.h"
#include "kumite/runtime/bout.h"
#include "kumite/runtime/fighter.h"
#include "kumite/formats/bvh_reader.h"
#include "kumite/formats/character_body.h"
#include "kumite/formats/motion_database_file.h"
#include "support/allocation_counter.h"
#include "support/reference_database.h"
#include "support/standing_character.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

using namespace kumite;

namespace {

MotionDatabase golden() {
    Result<MotionDatabase> opened = MotionDatabase::open(kumite::test::source_dir() / "data/golden/golden-v2.kdb");
    REQUIRE(opened.has_value());
    return std::move(*opened);
}

// A bout of the brawler on the reference database against a simulated punching user (seed 5), stepped once; null
// without the reference database.
std::unique_ptr<Bout> punching_bout_on_reference(const MotionDatabaseContent& content, const BoutOptions& options) {
    const kumite::test::StandingCharacter brawler("brawler", content.view());
    Result<std::unique_ptr<HeadTracker>> tracker = HeadTracker::open("simulate:punch", DtrackConfig{}, 5);
    REQUIRE(tracker);
    Result<std::unique_ptr<Bout>> bout = Bout::create(content.view(), {{"brawler", brawler.file, nullptr}}, std::move(*tracker), options);
    REQUIRE(bout);
    (*bout)->step(0.0);
    return std::move(*bout);
}

} // namespace

TEST_CASE("retrieval: fast and exhaustive queries allocate nothing", "[core]") {
    const MotionDatabase database = golden();
    const kumite::test::StandingCharacter standing("brawler", database.view());
    const Retriever retriever(database.view());
    RetrievalWorkspace workspace = retriever.make_workspace();
    RetrievalQuery query = standing.query;
    int found = 0;
    kumite::test::AllocationScope scope;
    for (int i = 0; i < 50; ++i) {
        query.semantics = retriever.semantics_id(i % 2 ? "kick" : "punch");
        query.side = i % 3 == 0 ? Side::none : i % 3 == 1 ? Side::left : Side::right;
        query.target_world = Eigen::Vector3d(0.02 * (i - 25), 0.8 + 0.02 * i, 0.5 + 0.01 * i);
        found += retriever.query(query, workspace).found;
        found += retriever.query_exhaustive(query).found;
    }
    CHECK(scope.count() == 0);
    CHECK(found > 50);
}

TEST_CASE("adaptation: begin and step allocate nothing after the first strike", "[core]") {
    const MotionDatabase database = golden();
    const kumite::test::StandingCharacter standing("giant", database.view());
    const Retriever retriever(database.view());
    RetrievalWorkspace workspace = retriever.make_workspace();
    auto plan_for = [&](const char* semantics, const Eigen::Vector3d& target) {
        const RetrievalResult found = retriever.query(standing.order(retriever, semantics, Side::none, target), workspace);
        REQUIRE(found.found);
        return StrikePlan{found.clip, found.start_frame, found.contact_frame, found.clip_to_world, target};
    };
    const StrikePlan first = plan_for("punch", Eigen::Vector3d(0.1, 1.5, 0.6));
    const StrikePlan far = plan_for("kick", Eigen::Vector3d(0.0, 1.4, 2.5)); // unreachable: the CCD runs
    StrikeAdapter adapter(*standing.rig, database.view());
    Pose pose;
    adapter.begin(first, standing.mir, {true, true}, standing.ankles);
    adapter.step(0, pose); // sizes the pose
    kumite::test::AllocationScope scope;
    for (const StrikePlan& plan : {first, far}) {
        adapter.begin(plan, standing.mir, {true, true}, standing.ankles);
        for (int i = 0; i < adapter.frame_count(); ++i) adapter.step(i, pose);
    }
    CHECK(scope.count() == 0);
}

TEST_CASE("fighter: a step allocates nothing, through guard, strike, recovery and a character switch", "[core]") {
    const MotionDatabase database = golden();
    const kumite::test::StandingCharacter brawler("brawler", database.view());
    const kumite::test::StandingCharacter giant("giant", database.view());
    const Retriever retriever(database.view());
    Fighter fighter(database.view(), retriever, {brawler.rig.get(), giant.rig.get()});
    const Eigen::Vector3d head(0.0, 1.5, 0.7);
    fighter.step(0.0, &head); // the first step starts the guard
    fighter.clear_events();
    kumite::test::AllocationScope scope;
    for (int frame = 1; frame < 300; ++frame) {
        if (frame == 60) fighter.order(retriever.semantics_id("punch"), Side::left);
        if (frame == 70) fighter.set_character(1);
        if (frame == 200) fighter.order(retriever.semantics_id("kick"), Side::none);
        fighter.step(frame / 60.0, frame < 250 ? &head : nullptr);
        fighter.clear_events();
    }
    CHECK(scope.count() == 0);
}

TEST_CASE("bout: a step allocates nothing, with bodies, a dodging simulated user, orders and a character switch", "[core]") {
    const MotionDatabase database = golden();
    const kumite::test::StandingCharacter brawler("brawler", database.view());
    const kumite::test::StandingCharacter giant("giant", database.view());
    Result<std::unique_ptr<HeadTracker>> tracker = HeadTracker::open("simulate:dodge", DtrackConfig{}, 5);
    REQUIRE(tracker);
    // With their skinned bodies, as kumite play loads them: prepared once, nothing per frame.
    const std::filesystem::path characters = kumite::test::source_dir() / "data/characters";
    Result<std::optional<SkinnedMesh>> brawler_body = load_character_body(characters, "brawler", brawler.skeleton());
    Result<std::optional<SkinnedMesh>> giant_body = load_character_body(characters, "giant", giant.skeleton());
    REQUIRE((brawler_body && *brawler_body && giant_body && *giant_body));
    Result<std::unique_ptr<Bout>> bout = Bout::create(database.view(),
                                                      {{"brawler", brawler.file, std::make_shared<const SkinnedMesh>(std::move(**brawler_body))},
                                                       {"giant", giant.file, std::make_shared<const SkinnedMesh>(std::move(**giant_body))}},
                                                      std::move(*tracker), BoutOptions{});
    REQUIRE(bout);
    REQUIRE((*bout)->character_body(0) != nullptr);
    (*bout)->step(0.0);
    std::size_t events = 0;
    kumite::test::AllocationScope scope;
    for (int frame = 1; frame < 600; ++frame) {
        if (frame == 120) CHECK((*bout)->command("punch left"));
        if (frame == 130) CHECK((*bout)->command("character giant"));
        if (frame == 300) CHECK((*bout)->command("kick"));
        (*bout)->step(frame / 60.0);
        events += (*bout)->events().size();
    }
    CHECK(scope.count() == 0);
    CHECK((*bout)->counters().strikes == 2);
    CHECK(events > 4);
}

TEST_CASE("bout: a step allocates nothing while a punching user's strikes are defended", "[core]") {
    const MotionDatabase database = golden();
    const kumite::test::StandingCharacter brawler("brawler", database.view());
    Result<std::unique_ptr<HeadTracker>> tracker = HeadTracker::open("simulate:punch", DtrackConfig{}, 5);
    REQUIRE(tracker);
    Result<std::unique_ptr<Bout>> bout = Bout::create(database.view(), {{"brawler", brawler.file, nullptr}}, std::move(*tracker), BoutOptions{});
    REQUIRE(bout);
    (*bout)->step(0.0);
    kumite::test::AllocationScope scope;
    for (int frame = 1; frame < 12 * 60; ++frame) (*bout)->step(frame / 60.0);
    CHECK(scope.count() == 0);
    CHECK((*bout)->counters().user_strikes >= 3);
    CHECK((*bout)->counters().blocks + (*bout)->counters().slips >= 3);
}

TEST_CASE("bout: a step allocates nothing against a recorded boxer, steering strikes, queuing orders, defending, its guard in the way", "[core][corpus]") {
    const std::filesystem::path boxer = kumite::test::mocap_root() / "cmu14-boxing" / "box-1.bvh";
    if (!std::filesystem::exists(boxer)) return;
    const MotionDatabase database = golden();
    const kumite::test::StandingCharacter brawler("brawler", database.view());
    Result<std::unique_ptr<HeadTracker>> tracker = HeadTracker::open("capture:" + boxer.string(), DtrackConfig{}, 5);
    REQUIRE(tracker);
    BoutOptions options;
    options.fighter.aim = FighterAim::predicted;
    options.fighter.user_guard.enabled = GENERATE(false, true); // the boxer's gloves and forearms in the strikes' way
    Result<std::unique_ptr<Bout>> bout = Bout::create(database.view(), {{"brawler", brawler.file, nullptr}}, std::move(*tracker), options);
    REQUIRE(bout);
    (*bout)->step(0.0);
    kumite::test::AllocationScope scope;
    for (int frame = 1; frame < 20 * 60; ++frame) {
        if (frame % 42 == 0) CHECK((*bout)->command(frame % 84 ? "kick" : "punch")); // faster than strikes end: orders wait
        (*bout)->step(frame / 60.0);
    }
    CHECK(scope.count() == 0);
    CHECK((*bout)->counters().strikes >= 5);
    CHECK((*bout)->counters().orders_queued >= 3);
    CHECK((*bout)->counters().user_strikes >= 1); // the boxer's punches reached the fighter: the defence ran
    if (options.fighter.user_guard.enabled) CHECK((*bout)->counters().blocked_by_user >= 1);
}

TEST_CASE("bout: a step allocates nothing while captured blocks, limited to their clip's speed, meet a punching user", "[core][corpus]") {
    const MotionDatabaseContent* content = kumite::test::reference_database(); // the golden database holds no blocks
    if (!content) return;
    BoutOptions options;
    options.fighter.defence.captured_blocks = true;
    options.fighter.defence.block_clip_max_speed_ratio = 1.0;
    const std::unique_ptr<Bout> bout = punching_bout_on_reference(*content, options);
    kumite::test::AllocationScope scope;
    for (int frame = 1; frame < 20 * 60; ++frame) bout->step(frame / 60.0);
    CHECK(scope.count() == 0);
    CHECK(bout->counters().block_clips >= 3);
}

TEST_CASE("bout: a step allocates nothing while landed blows are answered by hit reactions, held to human speed", "[core][corpus]") {
    const MotionDatabaseContent* content = kumite::test::reference_database(); // the golden database holds no reactions
    if (!content) return;
    BoutOptions options;
    options.fighter.defence.enabled = false; // every punch that arrives lands
    options.fighter.human_speed = true;      // the limbs held by the speed limit, one by one
    const std::unique_ptr<Bout> bout = punching_bout_on_reference(*content, options);
    kumite::test::AllocationScope scope;
    for (int frame = 1; frame < 20 * 60; ++frame) {
        if (frame % 120 == 0) CHECK(bout->command(frame % 240 ? "kick" : "punch"));
        bout->step(frame / 60.0);
    }
    CHECK(scope.count() == 0);
    CHECK(bout->counters().hit_reactions >= 3);
    CHECK(bout->counters().strikes >= 3);
    long long held = 0;
    for (long long frames : bout->fighter(0).held_back_frames()) held += frames;
    CHECK(held > 0);
}
