#include "kumite/core/foot_contacts.h"

#include <catch2/catch.hpp>

using namespace kumite;

namespace {
// An ankle at 30 fps: planted at x = 0, lifted and carried to x = 0.6, planted again.
std::vector<Eigen::Vector3d> step(double slide_per_frame = 0.0) {
    std::vector<Eigen::Vector3d> ankle;
    for (int frame = 0; frame < 20; ++frame) ankle.emplace_back(frame * slide_per_frame, 0.08, 0.0);
    for (int frame = 0; frame < 15; ++frame) {
        const double t = (frame + 1) / 16.0;
        ankle.emplace_back(0.6 * t, 0.08 + 0.15 * std::sin(3.14159 * t), 0.0);
    }
    for (int frame = 0; frame < 20; ++frame) ankle.emplace_back(0.6, 0.08, 0.0);
    return ankle;
}
} // namespace

TEST_CASE("foot_contacts: a step has two planted phases", "[core]") {
    const std::vector<ContactInterval> contacts = foot_contacts_detect(step(), 1.0 / 30.0, 0.85, 0.08);
    REQUIRE(contacts.size() == 2);
    CHECK(contacts[0].first_frame == 0);
    CHECK(contacts[0].last_frame >= 18);
    CHECK(contacts[0].last_frame <= 21);
    CHECK(contacts[1].first_frame >= 33);
    CHECK(contacts[1].last_frame == 54);
}

TEST_CASE("foot_contacts: a slowly sliding foot starts new contacts instead of one long slide", "[core]") {
    // 4 mm per frame (12 cm/s, under the speed threshold) for 20 frames: 8 cm in all.
    const std::vector<ContactInterval> contacts = foot_contacts_detect(step(0.004), 1.0 / 30.0, 0.85, 0.08);
    REQUIRE(contacts.size() >= 3);
    const int first_length = contacts[0].last_frame - contacts[0].first_frame;
    CHECK(first_length * 0.004 <= 0.008 * 0.85 + 0.004);
}
