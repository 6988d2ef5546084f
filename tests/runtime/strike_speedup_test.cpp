// Strikes at a real strike's speed: a punch or kick captured slower than a real one lands is played
// faster towards its contact (fighter/strike.h: strike_speedup, strike_clip_time), its contact coming when it would
// as captured; on the reference database against a still user.

#include "fighter_bout.h"
#include "support/reference_database.h"

#include "fighter/strike.h"

#include "kumite/runtime/fighter.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace kumite;
using kumite::test::Bout;
using kumite::test::reference_database;

TEST_CASE("strike speedup: the clip's time runs slow then fast, reaches the contact on time, and comes back to its own pace", "[runtime]") {
    const double contact_s = 0.4;
    for (const double speedup : {1.0, 1.3, 1.6, 1.9}) {
        INFO("speedup " << speedup);
        CHECK(strike_clip_time(0.0, contact_s, speedup) == Approx(0.0));
        CHECK(strike_clip_time(contact_s, contact_s, speedup) == Approx(contact_s));
        const double h = 1e-4;
        const double pace_at_start = strike_clip_time(h, contact_s, speedup) / h;
        const double pace_at_contact = (strike_clip_time(contact_s, contact_s, speedup) - strike_clip_time(contact_s - h, contact_s, speedup)) / h;
        const double pace_just_after = (strike_clip_time(contact_s + h, contact_s, speedup) - strike_clip_time(contact_s, contact_s, speedup)) / h;
        CHECK(pace_at_start == Approx(2.0 - speedup).margin(1e-3));
        CHECK(pace_at_contact == Approx(speedup).margin(1e-3));
        CHECK(pace_just_after == Approx(speedup).margin(1e-3)); // no jump at the contact
        const double late = (strike_clip_time(contact_s + 0.5 + h, contact_s, speedup) - strike_clip_time(contact_s + 0.5, contact_s, speedup)) / h;
        CHECK(late == Approx(1.0).margin(1e-3));
        double before = -1.0; // never backwards
        for (double t = 0.0; t < contact_s + 0.5; t += 0.005) {
            const double clip_s = strike_clip_time(t, contact_s, speedup);
            CHECK(clip_s > before);
            before = clip_s;
        }
    }
}

TEST_CASE("strike speedup: only punches and kicks captured slower than a real one, at most max_speedup", "[runtime][corpus]") {
    const MotionDatabaseContent* content = reference_database();
    if (!content) return;
    const MotionDatabaseView db = content->view();
    const FighterSettings settings;
    int sped_up = 0, strikes = 0;
    for (int clip = 0; clip < int(db.clips.size()); ++clip) {
        const DbClip& c = db.clips[clip];
        if (!db_clip_is_strike(c)) continue;
        ++strikes;
        const int contact = db_clip_contact_frame(db, c, 0.9, 0.85);
        const double speedup = strike_speedup(db, settings, clip, contact);
        const std::string semantics(db.string(c.semantics));
        INFO(db.string(c.name) << " (" << semantics << "): " << speedup);
        CHECK(speedup >= 1.0);
        CHECK(speedup <= settings.max_speedup + 1e-9);
        if (semantics != "punch" && semantics != "kick") CHECK(speedup == 1.0);
        const float* before = db.poses[c.first_pose + contact - 1].hit_point;
        const float* at = db.poses[c.first_pose + contact].hit_point;
        const double captured = Eigen::Vector3d(at[0] - before[0], at[1] - before[1], at[2] - before[2]).norm() / db.meta.frame_time_s;
        const double real = semantics == "punch" ? settings.punch_speed_mps : settings.kick_speed_mps;
        if (speedup > 1.0) CHECK(captured * speedup <= real + 1e-6); // up to a real strike's speed, not beyond
        if (captured >= real) CHECK(speedup == 1.0);
        sped_up += speedup > 1.0;
        FighterSettings captured_speed = settings;
        captured_speed.max_speedup = 1.0;
        CHECK(strike_speedup(db, captured_speed, clip, contact) == 1.0);
    }
    // The kata's and CMU 02's punches are captured at 2-4 m/s: many are sped up, not all.
    CHECK(sped_up > strikes / 10);
    CHECK(sped_up < strikes);
}

TEST_CASE("strike speedup: against a still user the punches land faster, each when it would have landed as captured", "[runtime][corpus]") {
    const MotionDatabaseContent* content = reference_database();
    if (!content) return;
    // One punch at a time from the guard, at still heads around the fighter, with and without the speedup: the same
    // clip lands at the same time either way, and when it is sped up, faster (by about its speedup; the adaptation
    // adds its own motion).
    struct Contact {
        double t_s = 0.0, speed_mps = 0.0, speedup = 1.0;
        int clip = -1;
        bool hit = false;
    };
    auto first_punch = [&](double max_speedup, const Eigen::Vector3d& user, Side side) {
        FighterSettings settings;
        settings.max_speedup = max_speedup;
        Bout b(content->view(), "scout", settings);
        Contact contact;
        for (int frame = 0; frame < 60 * 5 && contact.clip < 0; ++frame) {
            const double t = frame / 60.0;
            if (frame == 120) b.fighter->order(b.retriever->semantics_id("punch"), side);
            b.fighter->step(t, &user);
            for (const FighterEvent& e : b.fighter->events()) {
                if (e.type == FighterEvent::Type::strike) contact = {e.t_s, e.effector_speed_mps, e.speedup, e.clip, e.hit};
            }
            b.fighter->clear_events();
        }
        return contact;
    };
    int trials = 0, compared = 0, faster = 0, hits = 0;
    for (const double x : {-0.2, 0.0, 0.2}) {
        for (const double height : {1.45, 1.65}) {
            for (const Side side : {Side::left, Side::right}) {
                const Eigen::Vector3d user(x, height, 0.95);
                const Contact sped = first_punch(FighterSettings{}.max_speedup, user, side), captured = first_punch(1.0, user, side);
                REQUIRE(sped.clip >= 0);
                REQUIRE(captured.clip >= 0);
                ++trials;
                hits += sped.hit;
                CHECK(captured.speedup == 1.0);
                INFO("at " << user.transpose() << ": clips " << sped.clip << " / " << captured.clip << ", speedup " << sped.speedup << ", "
                           << sped.speed_mps << " against " << captured.speed_mps << " m/s");
                CHECK(sped.clip == captured.clip); // the speedup does not choose the strike
                CHECK(sped.t_s == Approx(captured.t_s).margin(1e-6));
                if (sped.speedup <= 1.05) continue;
                ++compared;
                faster += sped.speed_mps > 1.05 * captured.speed_mps;
            }
        }
    }
    INFO(compared << " of " << trials << " punches sped up, " << faster << " faster; " << hits << " hit");
    CHECK(compared >= 2);
    CHECK(faster == compared);
    CHECK(hits >= trials - 1);
}
