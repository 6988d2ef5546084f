#pragma once
// The fighter tests' bout: the reference database, two characters (the first, and the giant to switch to), a fighter
// stepped at 60 Hz and the events it emitted.

#include "support/standing_character.h"

#include "kumite/core/retrieval.h"
#include "kumite/runtime/capture_user.h"
#include "kumite/runtime/fighter.h"
#include "kumite/runtime/simulated_user.h"

#include <Eigen/Core>

#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace kumite::test {

struct Bout {
    MotionDatabaseView db;
    RetrievalSettings settings;
    std::unique_ptr<Retriever> retriever;
    kumite::test::StandingCharacter brawler, giant;
    std::unique_ptr<Fighter> fighter;
    std::vector<FighterEvent> events;

    explicit Bout(const MotionDatabaseView& database, const std::string& first = "brawler", FighterSettings fighter_settings = {})
        : db(database), brawler(first, database), giant("giant", database) {
        settings.min_lead_frames = 12; // 0.4 s, as kumite play
        retriever = std::make_unique<Retriever>(db, settings);
        fighter = std::make_unique<Fighter>(db, *retriever, std::vector<CharacterRig*>{brawler.rig.get(), giant.rig.get()}, fighter_settings);
    }
    // Steps frames [from, to) at 60 Hz with the head from `head(t)` (null: no head).
    template <class Head>
    void run(int from, int to, Head&& head) {
        for (int frame = from; frame < to; ++frame) {
            const double t = frame / 60.0;
            const std::optional<Eigen::Vector3d> now = head(t);
            fighter->step(t, now ? &*now : nullptr);
            for (const FighterEvent& event : fighter->events()) events.push_back(event);
            fighter->clear_events();
        }
    }
    // One frame at `t` against a simulated user that strikes at the fighter's head and chest as they are now (as
    // kumite play --tracker simulate:KIND); the user's head.
    Eigen::Vector3d step_against(SimulatedUser& user, double t) {
        user.set_opponent(fighter->part_position(BodyPart::head), fighter->part_position(BodyPart::chest));
        const Eigen::Vector3d head = user.head(t);
        const UserHands hands = user.hands(t);
        fighter->step(t, &head, &hands);
        return head;
    }
    // One frame at 60 Hz against a recorded person (kumite play --tracker capture:), ordered as
    // scripts/real_opponents.py orders: punch, kick, sides alternating, every 2 s from 1 s. The fighter's events stay
    // in fighter->events() until the caller clears them.
    void step_against_capture(CaptureUser& user, int frame) {
        const double t = frame / 60.0;
        if (frame % 120 == 60) {
            const int n = frame / 120;
            fighter->order(retriever->semantics_id(n % 2 ? "kick" : "punch"), (n / 2) % 2 ? Side::right : Side::left);
        }
        UserHands hands;
        const Eigen::Vector3d head = user.head(t, hands);
        fighter->step(t, &head, &hands);
    }
    int count(FighterEvent::Type type) const {
        return static_cast<int>(std::count_if(events.begin(), events.end(), [&](const FighterEvent& e) { return e.type == type; }));
    }
    bool entered(FighterState state) const {
        return std::any_of(events.begin(), events.end(), [&](const FighterEvent& e) { return e.type == FighterEvent::Type::state && e.state == state; });
    }
};

} // namespace kumite::test
