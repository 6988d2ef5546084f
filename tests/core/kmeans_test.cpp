#include "kumite/core/kmeans.h"

#include <catch2/catch.hpp>

#include <set>

using namespace kumite;

namespace {
// Three tight blobs far apart, 20 points each, in 4 dimensions.
Eigen::MatrixXd blobs() {
    Eigen::MatrixXd points(60, 4);
    for (int i = 0; i < 60; ++i) {
        const double centre = 10.0 * (i / 20);
        for (int d = 0; d < 4; ++d) points(i, d) = centre + 0.01 * std::sin(7.0 * i + d);
    }
    return points;
}
} // namespace

TEST_CASE("kmeans: finds well separated clusters", "[core]") {
    const KMeansResult result = kmeans_cluster(blobs(), 3);
    for (int blob = 0; blob < 3; ++blob) {
        std::set<int> labels;
        for (int i = 0; i < 20; ++i) labels.insert(result.assignment[blob * 20 + i]);
        CHECK(labels.size() == 1);
    }
    CHECK(std::set<int>(result.assignment.begin(), result.assignment.end()).size() == 3);
    CHECK(result.inertia < 0.1);
}

TEST_CASE("kmeans: the same input and seed give the same clusters", "[core]") {
    Eigen::MatrixXd points = Eigen::MatrixXd::Zero(200, 3);
    for (int i = 0; i < 200; ++i) {
        for (int d = 0; d < 3; ++d) points(i, d) = std::sin(0.37 * i * (d + 1)) + 0.1 * std::cos(1.3 * i);
    }
    const KMeansResult a = kmeans_cluster(points, 7, 42);
    const KMeansResult b = kmeans_cluster(points, 7, 42);
    CHECK(a.assignment == b.assignment);
    CHECK(a.centroids == b.centroids);
    const KMeansResult other_seed = kmeans_cluster(points, 7, 43);
    CHECK(other_seed.assignment.size() == a.assignment.size());
    CHECK(kmeans_cluster(points, 1).inertia >= a.inertia); // more clusters never fit worse
}

TEST_CASE("kmeans: k is clamped to the number of points", "[core]") {
    Eigen::MatrixXd points(2, 1);
    points << 0.0, 1.0;
    const KMeansResult result = kmeans_cluster(points, 5);
    CHECK(result.centroids.rows() == 2);
    CHECK(result.inertia == Approx(0.0));
}
