#include "kumite/core/pose_distance.h"
#include "support/pose_matchers.h"

#include <random>

using namespace kumite;

namespace {
std::vector<Eigen::Vector3d> random_cloud(std::mt19937& random, int count) {
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
    std::vector<Eigen::Vector3d> cloud;
    for (int i = 0; i < count; ++i) cloud.emplace_back(coordinate(random), coordinate(random) + 1.0, coordinate(random));
    return cloud;
}
} // namespace

TEST_CASE("pose_distance: zero for identical clouds", "[core]") {
    std::mt19937 random(3);
    const auto cloud = random_cloud(random, 40);
    CHECK(kovar_distance(cloud, cloud) == Approx(0.0).margin(1e-20));
}

TEST_CASE("pose_distance: invariant to a turn about Y and a move on the floor, which it recovers", "[core]") {
    std::mt19937 random(5);
    const auto a = random_cloud(random, 40);
    for (double angle : {0.3, -2.5, 3.1}) {
        const FloorAlignment moved{angle, 0.7, -1.9};
        std::vector<Eigen::Vector3d> b;
        for (const auto& p : a) b.push_back(moved.apply(p)); // b = moved(a), so a = moved^-1(b)
        FloorAlignment found;
        CHECK(kovar_distance(a, b, {}, &found) == Approx(0.0).margin(1e-18));
        // The recovered alignment takes b back onto a.
        for (size_t i = 0; i < a.size(); ++i) CHECK_THAT(found.apply(b[i]), kumite::test::is_near(a[i], 1e-9));
    }
}

TEST_CASE("pose_distance: symmetric, weighted, and larger for different poses", "[core]") {
    std::mt19937 random(11);
    const auto a = random_cloud(random, 30);
    auto b = a;
    for (auto& p : b) p += Eigen::Vector3d(0.01, 0.0, -0.02);
    b[3].y() += 0.2; // one joint moved up: not removable by a floor motion
    const auto c = random_cloud(random, 30);
    const double ab = kovar_distance(a, b), ba = kovar_distance(b, a), ac = kovar_distance(a, c);
    CHECK(ab == Approx(ba).epsilon(1e-9));
    CHECK(ab == Approx(0.04).epsilon(0.05)); // the 0.2 m lift remains, the floor shift is removed
    CHECK(ac > 10 * ab);
    std::vector<double> weights(30, 1.0);
    weights[3] = 0.0;
    CHECK(kovar_distance(a, b, weights) == Approx(0.0).margin(1e-18)); // the lifted joint weighs nothing
}
