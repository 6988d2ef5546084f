// Orders with kind and height on the reference database: a bout cycling through every (semantics, kind, height,
// side) it holds strikes exactly those and hits a still user; identical orders in a row vary their clips; an
// order the database cannot serve is refused with a reason.

#include "support/reference_database.h"
#include "support/standing_character.h"

#include "kumite/runtime/combinations.h"
#include "kumite/runtime/fighter.h"
#include "kumite/runtime/simulated_user.h"

#include <catch2/catch.hpp>

#include <set>
#include <tuple>

using namespace kumite;

namespace {

struct OrderBout {
    RetrievalSettings settings;
    std::unique_ptr<Retriever> retriever;
    kumite::test::StandingCharacter character;
    std::unique_ptr<Fighter> fighter;
    std::vector<FighterEvent> events;

    OrderBout(const MotionDatabaseView& db, const std::string& name, FighterSettings fighter_settings = {}) : character(name, db) {
        settings.min_lead_frames = 12; // as kumite play
        retriever = std::make_unique<Retriever>(db, settings);
        fighter = std::make_unique<Fighter>(db, *retriever, std::vector<CharacterRig*>{character.rig.get()}, fighter_settings);
    }
    // 60 Hz against a still user; orders[k] is given at 3 s + 2.5 s * k (orders of one combination together).
    void run(const std::vector<StrikeOrder>& orders) {
        SimulatedUser user(SimulatedKind::still, 3);
        const int frames = static_cast<int>((3.0 + 2.5 * orders.size() + 2.0) * 60);
        std::size_t next = 0;
        for (int frame = 0; frame < frames; ++frame) {
            const double t = frame / 60.0;
            if (next < orders.size() && t >= 3.0 + 2.5 * next) {
                user.on_order(t);
                fighter->order(orders[next++]);
                while (next < orders.size() && orders[next].blow > 0) fighter->order(orders[next++]); // the rest of its combination
            }
            const Eigen::Vector3d head = user.head(t);
            fighter->step(t, &head);
            for (const FighterEvent& event : fighter->events()) events.push_back(event);
            fighter->clear_events();
        }
    }
};

std::vector<StrikeOrder> every_labelled_order(const MotionDatabaseView& db, const Retriever& retriever) {
    std::set<std::tuple<std::string, int, int, std::uint32_t>> seen;
    std::vector<StrikeOrder> orders;
    for (const DbClip& clip : db.clips) {
        if (!db_clip_is_strike(clip) || !seen.insert({std::string(db.string(clip.semantics)), clip.kind, clip.height, clip.side}).second) continue;
        orders.push_back({retriever.semantics_id(db.string(clip.semantics)), static_cast<Side>(clip.side), clip.strike_kind(), clip.strike_height()});
    }
    return orders;
}

} // namespace

TEST_CASE("fighter: orders cycling through kinds and heights strike exactly those and hit a still user", "[runtime][corpus]") {
    const MotionDatabaseContent* content = kumite::test::reference_database();
    if (!content) return;
    const MotionDatabaseView db = content->view();
    for (const char* name : {"scout", "brawler", "runner", "giant"}) {
        OrderBout bout(db, name);
        const std::vector<StrikeOrder> orders = every_labelled_order(db, *bout.retriever);
        REQUIRE(orders.size() >= 6);
        bout.run(orders);
        int strikes = 0, hits = 0;
        for (const FighterEvent& e : bout.events) {
            if (e.type != FighterEvent::Type::strike) continue;
            const DbClip& clip = db.clips[e.clip];
            INFO(name << ": ordered " << strike_kind_name(e.kind) << " " << strike_height_name(e.height) << ", struck " << db.string(clip.name));
            CHECK(e.kind == clip.strike_kind());
            CHECK(e.height == clip.strike_height());
            CHECK(e.side == static_cast<Side>(clip.side));
            ++strikes;
            hits += e.hit;
        }
        std::string not_struck; // the orders that expired or were ignored, and why
        for (const FighterEvent& e : bout.events) {
            if (e.type == FighterEvent::Type::order_expired || e.type == FighterEvent::Type::ignored_order)
                not_struck += " [" + std::string(e.semantics >= 0 ? bout.retriever->semantics_name(e.semantics) : "?") + " " + strike_kind_name(e.kind) +
                              " " + strike_height_name(e.height) + " at " + std::to_string(e.t_s) + " s: " + e.why + "]";
        }
        INFO(name << ": " << orders.size() << " orders, " << strikes << " strikes, " << hits << " hits;" << not_struck);
        CHECK(strikes == static_cast<int>(orders.size()));
        CHECK(hits >= 0.9 * strikes);
    }
}

TEST_CASE("fighter: twenty identical orders in a row use at least three clips, and one without variety fewer", "[runtime][corpus]") {
    const MotionDatabaseContent* content = kumite::test::reference_database();
    if (!content) return;
    const MotionDatabaseView db = content->view();
    auto clips_used = [&](FighterSettings settings, int& varied) {
        OrderBout bout(db, "brawler", settings);
        const StrikeOrder order{bout.retriever->semantics_id("punch"), Side::right, StrikeKind::straight, StrikeHeight::middle};
        bout.run(std::vector<StrikeOrder>(20, order));
        std::set<int> clips;
        varied = 0;
        for (const FighterEvent& e : bout.events) {
            if (e.type != FighterEvent::Type::strike) continue;
            clips.insert(e.clip);
            varied += e.varied;
        }
        return static_cast<int>(clips.size());
    };
    int varied = 0, varied_without = 0;
    const int with_variety = clips_used({}, varied);
    FighterSettings none;
    none.variety_recent = 0;
    const int without_variety = clips_used(none, varied_without);
    INFO("clips with variety " << with_variety << " (" << varied << " varied strikes), without " << without_variety);
    CHECK(with_variety >= 3);
    CHECK(varied > 0);
    CHECK(varied_without == 0);
    CHECK(without_variety < with_variety);
}

TEST_CASE("fighter: an order the database cannot serve is refused with a reason, not replaced", "[runtime][corpus]") {
    const MotionDatabaseContent* content = kumite::test::reference_database();
    if (!content) return;
    OrderBout bout(content->view(), "scout");
    const int punch = bout.retriever->semantics_id("punch");
    REQUIRE(bout.retriever->candidate_count(punch, Side::none, StrikeKind::uppercut) == 0);
    bout.run({{punch, Side::left, StrikeKind::uppercut, StrikeHeight::high}});
    int refused = 0, strikes = 0;
    for (const FighterEvent& e : bout.events) {
        strikes += e.type == FighterEvent::Type::strike;
        if (e.type != FighterEvent::Type::ignored_order) continue;
        ++refused;
        CHECK(e.kind == StrikeKind::uppercut);
        CHECK_THAT(std::string(e.why), Catch::Contains("kind"));
    }
    CHECK(refused == 1);
    CHECK(strikes == 0);
}

TEST_CASE("fighter: a combination's second blow begins from the first's recoil, at the part its height names", "[runtime][corpus]") {
    const MotionDatabaseContent* content = kumite::test::reference_database();
    if (!content) return;
    const MotionDatabaseView db = content->view();
    for (const auto& [name, reaches_head] : {std::pair{"kid", false}, std::pair{"brawler", true}, std::pair{"giant", true}}) {
        OrderBout bout(db, name);
        std::vector<StrikeOrder> orders;
        for (int c = 0; c < int(combinations().size()); ++c) {
            for (int blow = 0; blow < 2; ++blow) {
                const CombinationBlow& b = combinations()[std::size_t(c)].blows[std::size_t(blow)];
                orders.push_back({bout.retriever->semantics_id(b.semantics), b.side, b.kind, b.height, c, blow, false});
            }
        }
        bout.run(orders);
        // Each strike in turn: the combination's blows in order, the second begun within a few frames of the first's
        // end (no recovery to the guard between), each the side, kind and height asked, a middle one at the body.
        double first_ended_s = -1.0;
        int strikes = 0, seconds = 0;
        for (const FighterEvent& e : bout.events) {
            if (e.type == FighterEvent::Type::strike_end && e.blow == 0) first_ended_s = e.t_s;
            if (e.type == FighterEvent::Type::state && e.state == FighterState::strike && first_ended_s >= 0.0) {
                INFO(name << ": a strike began " << e.t_s - first_ended_s << " s after the first blow's end");
                CHECK(e.t_s - first_ended_s <= 0.1);
                first_ended_s = -1.0;
                ++seconds;
            }
            if (e.type != FighterEvent::Type::strike) continue;
            const Combination& combination = combinations()[std::size_t(e.combination)];
            const CombinationBlow& asked = combination.blows[std::size_t(e.blow)];
            INFO(name << ": " << combination.name << " blow " << e.blow + 1);
            CHECK(e.combination == strikes / 2);
            CHECK(e.blow == strikes % 2);
            CHECK(db.clips[e.clip].strike_kind() == asked.kind);
            CHECK(static_cast<Side>(db.clips[e.clip].side) == asked.side);
            if (asked.height == StrikeHeight::middle) CHECK((e.target_part == TargetPart::chest || e.target_part == TargetPart::solar_plexus));
            if (asked.height == StrikeHeight::high && reaches_head) CHECK(e.target_part == TargetPart::head); // a kid's arms do not reach it
            ++strikes;
        }
        CHECK(strikes == 6);
        CHECK(seconds == 3);
    }
}

TEST_CASE("fighter: a combination whose first blow is refused does not throw its second", "[runtime][corpus]") {
    const MotionDatabaseContent* content = kumite::test::reference_database();
    if (!content) return;
    const MotionDatabaseView db = content->view();
    OrderBout bout(db, "brawler");
    const int punch = bout.retriever->semantics_id("punch");
    // The first blow's orders: one waiting (queued behind a strike) that a later order replaces, its follow-up with it.
    bout.run({{punch, Side::right, StrikeKind::straight, StrikeHeight::high, -1, 0, false}});
    bout.events.clear();
    SimulatedUser user(SimulatedKind::still, 3);
    int expired_follow_ups = 0, strikes = 0;
    for (int frame = 0; frame < 5 * 60; ++frame) {
        const double t = 20.0 + frame / 60.0;
        if (frame == 0) bout.fighter->order({punch, Side::right, StrikeKind::straight, StrikeHeight::high, -1, 0, false});
        if (frame == 1) { // while it strikes: a combination waits, then an order takes its first blow's place
            bout.fighter->order({punch, Side::right, StrikeKind::straight, StrikeHeight::high, 0, 0, false});
            bout.fighter->order({punch, Side::left, StrikeKind::straight, StrikeHeight::high, 0, 1, false});
            bout.fighter->order({punch, Side::left, StrikeKind::straight, StrikeHeight::high, -1, 0, false});
        }
        const Eigen::Vector3d head = user.head(t);
        bout.fighter->step(t, &head);
        for (const FighterEvent& e : bout.fighter->events()) {
            expired_follow_ups += e.type == FighterEvent::Type::order_expired && e.blow == 1;
            strikes += e.type == FighterEvent::Type::strike;
            if (e.type == FighterEvent::Type::strike) CHECK(e.combination < 0);
        }
        bout.fighter->clear_events();
    }
    CHECK(expired_follow_ups == 1);
    CHECK(strikes == 2); // the first order's and the one that took the combination's place
}
