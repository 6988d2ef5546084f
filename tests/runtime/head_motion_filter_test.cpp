// The head's motion filter: a steady walk is followed and extrapolated, a turn unsettles it for a moment, noise of
// a real tracker is smoothed, predictions stay within a walking speed, a second and the room.

#include "kumite/runtime/head_motion_filter.h"
#include "kumite/core/split_mix.h"

#include <catch2/catch.hpp>

using namespace kumite;

TEST_CASE("head motion: a steady walk is followed and extrapolated, a turn unsettles it for a moment", "[runtime]") {
    HeadMotionFilter filter;
    CHECK(!filter.ready());
    const Eigen::Vector3d start(0.0, 1.65, 1.5), velocity(0.9, 0.0, -0.4);
    auto walked = [&](double t) { return Eigen::Vector3d(start + velocity * t); };
    int settled_from = -1;
    for (int frame = 0; frame <= 60; ++frame) {
        filter.update(frame / 60.0, walked(frame / 60.0));
        if (settled_from < 0 && filter.settled()) settled_from = frame;
    }
    CHECK(settled_from >= 0);
    CHECK(settled_from <= 12);
    CHECK((filter.velocity() - velocity).norm() < 0.01);
    CHECK((filter.predict(0.5) - walked(1.5)).norm() < 0.01);
    // A turn back: residuals rise at once, then settle again within a quarter second.
    const Eigen::Vector3d turn_point = walked(1.0);
    int unsettled = 0, settled_again = -1;
    for (int frame = 1; frame <= 60; ++frame) {
        filter.update(1.0 + frame / 60.0, turn_point - velocity * (frame / 60.0));
        unsettled += !filter.settled();
        if (settled_again < 0 && unsettled > 0 && filter.settled()) settled_again = frame;
    }
    CHECK(unsettled >= 3);
    CHECK(settled_again > 0);
    CHECK(settled_again <= 15);
    CHECK((filter.velocity() + velocity).norm() < 0.02);
}

TEST_CASE("head motion: tracker noise is smoothed, predictions are bounded", "[runtime]") {
    HeadMotionSettings settings;
    settings.room_max = Eigen::Vector2d(2.0, 2.0);
    HeadMotionFilter filter(settings);
    SplitMix64 random{3};
    const Eigen::Vector3d velocity(0.0, 0.0, 0.6);
    for (int frame = 0; frame <= 120; ++frame) {
        const double t = frame / 60.0;
        const Eigen::Vector3d noise(random.uniform(-0.002, 0.002), random.uniform(-0.002, 0.002), random.uniform(-0.002, 0.002));
        filter.update(t, Eigen::Vector3d(0.0, 1.7, 0.0) + velocity * t + noise);
    }
    CHECK((filter.velocity() - velocity).norm() < 0.15);
    CHECK(filter.settled());
    CHECK(filter.predict(0.4).z() == Approx(1.2 + 0.24).margin(0.06));
    CHECK(filter.predict(0.4).y() == Approx(1.7).margin(0.01)); // heights are not extrapolated
    CHECK(filter.predict(5.0).z() <= 2.0);                         // the room
    // A jump across the room in one sample is not a walk: the speed is bounded.
    filter.update(2.0 + 1.0 / 60.0, Eigen::Vector3d(-3.0, 1.7, 1.2));
    CHECK(filter.velocity().norm() <= settings.max_speed_mps + 1e-9);
    CHECK(!filter.settled());
    // A gap in the samples restarts the filter.
    filter.update(10.0, Eigen::Vector3d(1.0, 1.6, 1.0));
    CHECK(!filter.ready());
    CHECK(filter.predict(0.5).isApprox(Eigen::Vector3d(1.0, 1.6, 1.0)));
}
