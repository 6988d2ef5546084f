// The planning budget (planning_budget.h): fighters ordered at once plan over the following frames, oldest order
// first; a fighter whose plan is late keeps its guard (no pose jump) and strikes when its turn comes; with enough
// budget the bout is the same, event for event, as planning in the frame.

#include "kumite/runtime/bout.h"
#include "support/reference_database.h"
#include "support/standing_character.h"

#include <catch2/catch.hpp>

using namespace kumite;

namespace {

struct Crowd {
    std::vector<BoutEvent> events;
    std::vector<std::vector<Eigen::Vector3d>> pelvis_paths; // [fighter][frame] the shown pelvis
    std::vector<std::vector<Eigen::Vector3d>> hand_paths;   // [fighter][frame] the shown right wrist
};

// `fighters` fighters against a still user, every one ordered to punch at 2 s; 4 s at 60 Hz.
Crowd crowd_bout(const MotionDatabaseView& db, int fighters, int plans_per_frame) {
    const kumite::test::StandingCharacter brawler("brawler", db);
    Result<std::unique_ptr<HeadTracker>> tracker = HeadTracker::open("simulate:still", DtrackConfig{}, 1);
    REQUIRE(tracker);
    BoutOptions options;
    options.fighters = fighters;
    options.plans_per_frame = plans_per_frame;
    Result<std::unique_ptr<Bout>> created = Bout::create(db, {{"brawler", brawler.file, nullptr}}, std::move(*tracker), options);
    REQUIRE(created);
    Bout& bout = **created;
    Crowd crowd;
    crowd.pelvis_paths.resize(fighters);
    crowd.hand_paths.resize(fighters);
    for (int frame = 0; frame < 240; ++frame) {
        if (frame == 120) REQUIRE(bout.command("punch right"));
        bout.step(frame / 60.0);
        for (const BoutEvent& event : bout.events()) crowd.events.push_back(event);
        for (int f = 0; f < fighters; ++f) {
            crowd.pelvis_paths[f].push_back(bout.fighter(f).part_position(BodyPart::pelvis));
            crowd.hand_paths[f].push_back(bout.fighter(f).part_position(BodyPart::hand_r));
        }
    }
    return crowd;
}

std::vector<double> strike_starts(const Crowd& crowd, int fighters) {
    std::vector<double> starts(fighters, -1.0);
    for (const BoutEvent& e : crowd.events) {
        if (e.event.type == FighterEvent::Type::state && e.event.state == FighterState::strike && starts[e.fighter] < 0.0) starts[e.fighter] = e.event.t_s;
    }
    return starts;
}

} // namespace

TEST_CASE("planning budget: with room for every fighter, the bout is the same as planning in the frame", "[runtime][corpus]") {
    const MotionDatabaseContent* content = kumite::test::reference_database();
    if (!content) return;
    const Crowd budgeted = crowd_bout(content->view(), 3, 16), in_frame = crowd_bout(content->view(), 3, 0);
    REQUIRE(budgeted.events.size() == in_frame.events.size());
    for (std::size_t i = 0; i < budgeted.events.size(); ++i) {
        CHECK(budgeted.events[i].fighter == in_frame.events[i].fighter);
        CHECK(budgeted.events[i].event.type == in_frame.events[i].event.type);
        CHECK(budgeted.events[i].event.t_s == in_frame.events[i].event.t_s);
        CHECK(budgeted.events[i].event.clip == in_frame.events[i].event.clip);
        CHECK(budgeted.events[i].event.contact_error_m == in_frame.events[i].event.contact_error_m);
    }
}

TEST_CASE("planning budget: one plan a frame serves fighters in turn; a late one guards without a jump, then strikes", "[runtime][corpus]") {
    const MotionDatabaseContent* content = kumite::test::reference_database();
    if (!content) return;
    const int fighters = 3;
    const Crowd one_a_frame = crowd_bout(content->view(), fighters, 1), in_frame = crowd_bout(content->view(), fighters, 0);
    const std::vector<double> late = strike_starts(one_a_frame, fighters), prompt = strike_starts(in_frame, fighters);
    for (int f = 0; f < fighters; ++f) {
        INFO("fighter " << f << ": strike at " << late[f] << " s with one plan a frame, " << prompt[f] << " s planning in the frame");
        REQUIRE(late[f] > 0.0);
        REQUIRE(prompt[f] > 0.0);
        // Served in the order of the fighters (the same order time): fighter f plans f frames later. (A fighter that
        // cannot reach its target at once looks at one part per frame, so it may take a few frames more.)
        CHECK(late[f] - prompt[f] >= f / 60.0 - 1e-9);
        CHECK(late[f] - prompt[f] <= (f + 4) / 60.0 + 1e-9);
    }
    // Every fighter struck, and each strike landed as planning in the frame does.
    int strikes = 0, hits = 0, prompt_hits = 0;
    for (const BoutEvent& e : one_a_frame.events) {
        strikes += e.event.type == FighterEvent::Type::strike;
        hits += e.event.type == FighterEvent::Type::strike && e.event.hit;
    }
    for (const BoutEvent& e : in_frame.events) prompt_hits += e.event.type == FighterEvent::Type::strike && e.event.hit;
    CHECK(strikes == fighters);
    CHECK(hits == prompt_hits);
    // While it waited, the last fighter kept its guard: no joint of its shown pose jumped between frames.
    const int waiting_from = 120, waiting_to = static_cast<int>(late[fighters - 1] * 60.0 + 0.5);
    for (int frame = waiting_from; frame <= waiting_to; ++frame) {
        CHECK((one_a_frame.pelvis_paths[fighters - 1][frame] - one_a_frame.pelvis_paths[fighters - 1][frame - 1]).norm() < 0.02);
        CHECK((one_a_frame.hand_paths[fighters - 1][frame] - one_a_frame.hand_paths[fighters - 1][frame - 1]).norm() < 0.05);
    }
}
