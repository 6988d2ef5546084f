// The guard kept while striking (DefenceSettings::keep_guard): the arm a strike leaves free stays where
// the guard had it from the head (a kata's punch pulls its other hand to the hip); with defence.keep_guard = false it moves as
// captured. On the reference database against a still user.

#include "fighter_bout.h"
#include "support/reference_database.h"

#include "kumite/runtime/fighter.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

using namespace kumite;
using kumite::test::Bout;
using kumite::test::reference_database;

namespace {

struct StrikeHands {
    double free_hand_moved_m = 0.0; // the hand that moved least from where it was from the head at the strike's start
    double striking_hand_moved_m = 0.0;
};

// 19 punches, one every 2 s, against a still head; per strike, how far each hand went from its place relative to
// the fighter's own head (heading axes) at the strike's first frame. `hits` and `strikes` from the events.
std::vector<StrikeHands> punching(bool keep_guard, int& strikes, int& hits) {
    FighterSettings settings;
    settings.defence.keep_guard = keep_guard;
    Bout bout(reference_database()->view(), "brawler", settings);
    const Eigen::Vector3d head(0.0, 1.6, 1.5);
    std::vector<StrikeHands> out;
    std::array<Eigen::Vector3d, 2> start{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    std::array<double, 2> moved{};
    bool striking = false;
    int ordered = 0;
    auto from_head = [&](BodyPart hand) {
        const HeadingFrame heading = bout.fighter->heading();
        return heading.direction_to_heading(bout.fighter->part_position(hand) - bout.fighter->part_position(BodyPart::head));
    };
    auto close = [&] {
        out.push_back({std::min(moved[0], moved[1]), std::max(moved[0], moved[1])});
    };
    bout.run(0, 40 * 60, [&](double t) -> std::optional<Eigen::Vector3d> {
        if (t >= 1.0 + 2.0 * ordered && ordered < 19) {
            bout.fighter->order(bout.retriever->semantics_id("punch"), ordered % 2 ? Side::right : Side::left);
            ++ordered;
        }
        const bool now_striking = bout.fighter->state() == FighterState::strike;
        if (now_striking && !striking) {
            start = {from_head(BodyPart::hand_l), from_head(BodyPart::hand_r)};
            moved = {0.0, 0.0};
        } else if (now_striking) {
            moved[0] = std::max(moved[0], (from_head(BodyPart::hand_l) - start[0]).norm());
            moved[1] = std::max(moved[1], (from_head(BodyPart::hand_r) - start[1]).norm());
        } else if (striking) {
            close();
        }
        striking = now_striking;
        return head;
    });
    strikes = bout.count(FighterEvent::Type::strike);
    hits = static_cast<int>(std::count_if(bout.events.begin(), bout.events.end(),
                                          [](const FighterEvent& e) { return e.type == FighterEvent::Type::strike && e.hit; }));
    return out;
}

} // namespace

TEST_CASE("fighter: while it punches, the free hand stays where the guard had it from the head; dropped, it moves as captured",
          "[runtime][corpus]") {
    if (!reference_database()) return;
    int strikes = 0, hits = 0;
    const std::vector<StrikeHands> kept = punching(true, strikes, hits);
    REQUIRE(kept.size() >= 15);
    double worst_free = 0.0, least_striking = 1e9;
    for (const StrikeHands& s : kept) {
        worst_free = std::max(worst_free, s.free_hand_moved_m);
        least_striking = std::min(least_striking, s.striking_hand_moved_m);
    }
    INFO(kept.size() << " punches, " << hits << " hits of " << strikes << "; the free hand moved at most " << worst_free
                     << " m from its place by the head, the striking hand at least " << least_striking << " m");
    CHECK(worst_free < 0.08);
    CHECK(least_striking > 0.25); // the punches themselves still go out
    CHECK(hits >= 0.9 * strikes);

    int strikes_dropped = 0, hits_dropped = 0;
    const std::vector<StrikeHands> dropped = punching(false, strikes_dropped, hits_dropped);
    double most_free = 0.0;
    for (const StrikeHands& s : dropped) most_free = std::max(most_free, s.free_hand_moved_m);
    INFO("dropped guard: the free hand moved up to " << most_free << " m");
    CHECK(most_free > 0.15); // the case exists: a clip's free arm leaves the face
}
