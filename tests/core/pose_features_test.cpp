// Pose features and their clusters: the float closed form agrees with kovar_distance, ignores a turn about Y and
// a floor move, and the clusters are the same for any thread count.

#include "kumite/core/pose_clusters.h"
#include "kumite/core/pose_features.h"
#include "kumite/core/split_mix.h"

#include <catch2/catch.hpp>

#include <set>

using namespace kumite;

namespace {

std::vector<float> random_feature(SplitMix64& random, double spread = 1.0) {
    std::vector<float> feature(k_feature_dimensions, 0.0f); // the padding slots stay 0
    for (int p = 0; p < k_feature_cloud_size; ++p) {
        pose_feature_set_point(feature, p, Eigen::Vector3d(random.uniform(-spread, spread), random.uniform(-spread, spread),
                                                           random.uniform(-spread, spread)));
    }
    return feature;
}

std::vector<Eigen::Vector3d> points_of(const std::vector<float>& feature) {
    std::vector<Eigen::Vector3d> points;
    for (int p = 0; p < k_feature_cloud_size; ++p) points.push_back(pose_feature_point(feature, p));
    return points;
}

std::vector<float> moved(const std::vector<float>& feature, const FloorAlignment& motion) {
    std::vector<float> out(k_feature_dimensions, 0.0f);
    for (int p = 0; p < k_feature_cloud_size; ++p) pose_feature_set_point(out, p, motion.apply(pose_feature_point(feature, p)));
    return out;
}

} // namespace

TEST_CASE("pose_features: the float closed form equals kovar_distance", "[core]") {
    SplitMix64 random{7};
    for (int trial = 0; trial < 50; ++trial) {
        const std::vector<float> a = random_feature(random), b = random_feature(random);
        const double expected = kovar_distance(points_of(a), points_of(b));
        CHECK(pose_feature_distance(a, b) == Approx(expected).epsilon(1e-6)); // float sums
        const FloorAlignment alignment = pose_feature_alignment(a, b);
        const FloorAlignment reference = kovar_alignment(points_of(a), points_of(b));
        CHECK(alignment.angle_rad == Approx(reference.angle_rad).margin(1e-6));
        CHECK(pose_feature_distance(a, moved(b, alignment)) == Approx(expected).epsilon(1e-5).margin(1e-6));
    }
}

TEST_CASE("pose_features: zero for the same pose, blind to a turn and a floor move, symmetric", "[core]") {
    SplitMix64 random{11};
    const std::vector<float> a = random_feature(random);
    CHECK(pose_feature_distance(a, a) == Approx(0.0).margin(1e-9));
    const std::vector<float> turned = moved(a, FloorAlignment{2.1, 0.7, -3.0});
    CHECK(pose_feature_distance(a, turned) == Approx(0.0).margin(1e-4)); // float sums of 39 points
    const std::vector<float> b = random_feature(random);
    CHECK(pose_feature_distance(a, b) == Approx(pose_feature_distance(b, a)).epsilon(1e-12));
    CHECK(pose_feature_distance(a, b) > 1.0);
    // Lifting a pose is not free: the floor alignment has no vertical part.
    std::vector<float> lifted = a;
    for (int p = 0; p < k_feature_cloud_size; ++p) lifted[k_feature_axis_stride + p] += 0.5f;
    CHECK(pose_feature_distance(a, lifted) == Approx(k_feature_cloud_size * 0.25).epsilon(1e-5));
}

TEST_CASE("pose_clusters: turned and moved copies of three poses fall in three clusters, the same on any thread count", "[core]") {
    SplitMix64 random{3};
    std::vector<std::vector<float>> bases;
    for (int base = 0; base < 3; ++base) bases.push_back(random_feature(random));
    std::vector<float> features;
    for (int copy = 0; copy < 60; ++copy) {
        const FloorAlignment motion{random.uniform(-3.1, 3.1), random.uniform(-2, 2), random.uniform(-2, 2)};
        std::vector<float> pose = moved(bases[copy % 3], motion);
        for (int p = 0; p < k_feature_cloud_size; ++p) {
            pose_feature_set_point(pose, p, pose_feature_point(pose, p) + Eigen::Vector3d::Constant(random.uniform(-0.01, 0.01)));
        }
        features.insert(features.end(), pose.begin(), pose.end());
    }
    const PoseClusters one_thread = pose_clusters_compute(features, 3, 99, 50, 1);
    const PoseClusters two_threads = pose_clusters_compute(features, 3, 99, 50, 2);
    CHECK(one_thread.assignment == two_threads.assignment);
    CHECK(one_thread.centroids == two_threads.centroids);
    CHECK(pose_clusters_compute(features, 3, 99, 50, 2).centroids == two_threads.centroids);
    for (int base = 0; base < 3; ++base) {
        std::set<int> labels;
        for (int copy = base; copy < 60; copy += 3) labels.insert(one_thread.assignment[copy]);
        CHECK(labels.size() == 1);
    }
    CHECK(std::set<int>(one_thread.assignment.begin(), one_thread.assignment.end()).size() == 3);
    // Each pose is nearest (under Kovar's distance) to its own centroid.
    for (int pose = 0; pose < 60; ++pose) {
        const std::span<const float> feature = std::span(features).subspan(std::size_t(pose) * k_feature_dimensions, k_feature_dimensions);
        for (int c = 0; c < 3; ++c) {
            const std::span<const float> centroid = std::span(one_thread.centroids).subspan(std::size_t(c) * k_feature_dimensions, k_feature_dimensions);
            CHECK(pose_feature_distance(centroid, feature) >= one_thread.distance[pose] - 1e-9);
        }
    }
}
