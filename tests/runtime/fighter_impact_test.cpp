// Strikes that land stop at the target (the overshoot bar) against recorded boxers replayed as the user, as
// scripts/real_opponents.py plays them: a kick whose last chords turn back towards the kicker drops its foot to the
// floor after the head, which is not past the head (it was counted so: 12-16 cm, at 1.1 m from box-1 and box-2).

#include "fighter_bout.h"
#include "support/reference_database.h"
#include "support/test_paths.h"

#include "kumite/runtime/capture_user.h"
#include "kumite/runtime/fighter.h"

#include <catch2/catch.hpp>

#include <filesystem>

using namespace kumite;
using kumite::test::Bout;
using kumite::test::reference_database;

TEST_CASE("fighter: against recorded boxers at 1.1 m every strike that lands stops within 3 cm of the target", "[runtime][corpus]") {
    const MotionDatabaseContent* content = reference_database();
    const std::filesystem::path boxing = kumite::test::mocap_root() / "cmu14-boxing";
    if (!content || !std::filesystem::exists(boxing / "box-2.bvh")) return;
    int landed = 0, kicks_landed = 0;
    double farthest = 0.0;
    for (const std::string bout : {"box-1.bvh scout", "box-2.bvh brawler", "box-2.bvh scout"}) {
        const std::string file = bout.substr(0, bout.find(' ')), character = bout.substr(bout.find(' ') + 1);
        Result<CaptureUser> user = CaptureUser::open((boxing / file).string() + ":1.1");
        REQUIRE(user);
        FighterSettings settings;
        settings.aim = FighterAim::predicted;
        Bout b(content->view(), character, settings);
        const int kick = b.retriever->semantics_id("kick");
        int last_strike_semantics = -1;
        for (int frame = 0; frame < int(std::min(45.0, user->duration_s()) * 60.0); ++frame) {
            b.step_against_capture(*user, frame);
            for (const FighterEvent& e : b.fighter->events()) {
                if (e.type == FighterEvent::Type::strike) last_strike_semantics = e.semantics;
                if (e.type != FighterEvent::Type::strike_end || !e.impact) continue;
                INFO(bout << ": the strike ending at " << e.t_s << " s");
                CHECK(e.overshoot_m <= 0.03);
                farthest = std::max(farthest, e.overshoot_m);
                ++landed;
                kicks_landed += last_strike_semantics == kick;
            }
            b.fighter->clear_events();
        }
    }
    INFO(landed << " strikes stopped at the target, " << kicks_landed << " of them kicks; the farthest past it " << farthest << " m");
    CHECK(landed >= 30);
    CHECK(kicks_landed >= 10);
}
