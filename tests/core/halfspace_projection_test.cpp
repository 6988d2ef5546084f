// The nearest point inside a few half-spaces (the impact's hold of the hit point): checked against a brute-force
// search on random problems, inside points untouched, and continuity.

#include "kumite/core/halfspace_projection.h"

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <random>

using namespace kumite;

TEST_CASE("halfspace projection: a point inside stays, one outside a single plane lands on it", "[core]") {
    const std::vector<Eigen::Vector3d> normals = {Eigen::Vector3d::UnitZ()};
    const std::vector<double> bounds = {0.01};
    const Eigen::Vector3d inside(0.3, -0.2, -0.5);
    CHECK(nearest_within_halfspaces(inside, normals, bounds, Eigen::Vector3d::Zero()) == inside);
    const Eigen::Vector3d held = nearest_within_halfspaces(Eigen::Vector3d(0.3, -0.2, 0.5), normals, bounds, Eigen::Vector3d::Zero());
    CHECK(held.isApprox(Eigen::Vector3d(0.3, -0.2, 0.01)));
}

TEST_CASE("halfspace projection: matches a brute-force nearest feasible point on random cones", "[core]") {
    std::mt19937 random(7);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int problem = 0; problem < 200; ++problem) {
        const int count = 1 + problem % 5;
        std::vector<Eigen::Vector3d> normals;
        std::vector<double> bounds;
        // Directions in a cone around +Z, as the chords of a path arriving at a target.
        for (int k = 0; k < count; ++k) {
            normals.push_back(Eigen::Vector3d(0.6 * normal(random), 0.6 * normal(random), 1.0).normalized());
            bounds.push_back(0.005 * unit(random));
        }
        const Eigen::Vector3d point(0.2 * normal(random), 0.2 * normal(random), 0.2 * normal(random));
        const Eigen::Vector3d held = nearest_within_halfspaces(point, normals, bounds, Eigen::Vector3d::Zero());
        for (int k = 0; k < count; ++k) CHECK(normals[k].dot(held) <= bounds[k] + 1e-9);
        // No feasible point of a fine random sample around it is nearer.
        double nearest = std::numeric_limits<double>::infinity();
        for (int sample = 0; sample < 20000; ++sample) {
            const Eigen::Vector3d x = held + 0.05 * Eigen::Vector3d(normal(random), normal(random), normal(random));
            bool feasible = true;
            for (int k = 0; k < count && feasible; ++k) feasible = normals[k].dot(x) <= bounds[k];
            if (feasible) nearest = std::min(nearest, (x - point).norm());
        }
        CHECK((held - point).norm() <= nearest + 1e-9);
    }
}

TEST_CASE("halfspace projection: a small move of the point moves the result little (no jump)", "[core]") {
    const std::vector<Eigen::Vector3d> normals = {Eigen::Vector3d(0.2, 0.0, 1.0).normalized(), Eigen::Vector3d(-0.3, 0.1, 1.0).normalized(),
                                                  Eigen::Vector3d(0.0, -0.4, 1.0).normalized()};
    const std::vector<double> bounds = {0.005, 0.004, 0.005};
    Eigen::Vector3d previous = nearest_within_halfspaces(Eigen::Vector3d(-0.2, -0.2, 0.3), normals, bounds, Eigen::Vector3d::Zero());
    for (int step = 1; step <= 400; ++step) {
        const double t = step / 400.0;
        const Eigen::Vector3d point(-0.2 + 0.4 * t, -0.2 + 0.4 * t, 0.3 - 0.6 * t);
        const Eigen::Vector3d held = nearest_within_halfspaces(point, normals, bounds, Eigen::Vector3d::Zero());
        CHECK((held - previous).norm() <= 0.003); // the point moves ~1.9 mm a step; the projection is 1-Lipschitz
        previous = held;
    }
}
