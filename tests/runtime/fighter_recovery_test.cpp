// A strike's end (FighterSettings::strike_follow_s): its contact and recoil shown, the fighter recovers to its guard
// from where its limbs are, at human speed, instead of playing out the rest of the captured clip (a kata's goes on
// into the performer's next stance); played out, the strike lasts its clip.

#include "fighter_bout.h"
#include "support/reference_database.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

using namespace kumite;

namespace {

struct Strikes {
    std::vector<double> contact_to_end_s; // each strike: from its contact event to its strike_end
    double fastest_recovery_mps = 0.0;    // the fastest wrist or ankle in the recoveries (world, frame to frame)
    int recover_frames = 0;
};

// A still head 1.0 m away, a punch or kick every 2 s for 24 s.
Strikes strike_and_recover(const MotionDatabaseView& db, double follow_s) {
    FighterSettings settings;
    settings.strike_follow_s = follow_s;
    kumite::test::Bout b(db, "brawler", settings);
    const Eigen::Vector3d head(0.0, 1.6, 1.0);
    const RestAnatomy& anatomy = b.brawler.anatomy;
    Strikes strikes;
    double contact_s = -1.0;
    std::vector<Eigen::Vector3d> before;
    for (int frame = 0; frame < 24 * 60; ++frame) {
        const double t = frame / 60.0;
        if (frame >= 60 && frame % 120 == 60) b.fighter->order(b.retriever->semantics_id(frame % 240 == 60 ? "punch" : "kick"), Side::none);
        b.fighter->step(t, &head);
        for (const FighterEvent& e : b.fighter->events()) {
            if (e.type == FighterEvent::Type::strike) contact_s = e.t_s;
            if (e.type == FighterEvent::Type::strike_end && contact_s >= 0.0) strikes.contact_to_end_s.push_back(e.t_s - contact_s), contact_s = -1.0;
        }
        b.fighter->clear_events();
        const auto positions = b.fighter->positions();
        if (b.fighter->state() == FighterState::recover && before.size() == positions.size()) {
            ++strikes.recover_frames;
            for (const Limb limb : {Limb::arm_l, Limb::arm_r, Limb::leg_l, Limb::leg_r}) {
                const int end = anatomy.limbs[int(limb)].extremity;
                strikes.fastest_recovery_mps = std::max(strikes.fastest_recovery_mps, (positions[end] - before[end]).norm() * 60.0);
            }
        }
        before.assign(positions.begin(), positions.end());
    }
    return strikes;
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[values.size() / 2];
}

} // namespace

TEST_CASE("fighter: a strike ends after its contact and recoil and recovers at human speed, played out it lasts its clip", "[runtime][corpus]") {
    const MotionDatabaseContent* content = kumite::test::reference_database();
    if (!content) return;
    const double follow_s = FighterSettings{}.strike_follow_s;
    REQUIRE(follow_s > 0.0);
    const Strikes followed = strike_and_recover(content->view(), follow_s), played_out = strike_and_recover(content->view(), 0.0);
    INFO("after " << follow_s << " s: " << followed.contact_to_end_s.size() << " strikes, contact to end median " << median(followed.contact_to_end_s)
                  << " s, longest " << *std::max_element(followed.contact_to_end_s.begin(), followed.contact_to_end_s.end())
                  << " s, fastest wrist or ankle recovering " << followed.fastest_recovery_mps << " m/s; played out: median "
                  << median(played_out.contact_to_end_s) << " s, fastest " << played_out.fastest_recovery_mps << " m/s");
    REQUIRE(followed.contact_to_end_s.size() >= 8);
    REQUIRE(played_out.contact_to_end_s.size() >= 8);
    // Every strike ends within a frame of its recoil; played out, most go on well past it.
    for (const double s : followed.contact_to_end_s) CHECK(s <= follow_s + 1.5 / 60.0);
    CHECK(median(played_out.contact_to_end_s) > follow_s + 0.1);
    // Brought back from mid-strike, no wrist or ankle moves faster than a person's (12 m/s).
    REQUIRE(followed.recover_frames > 60);
    CHECK(followed.fastest_recovery_mps <= 12.0 + 1e-6);
}
