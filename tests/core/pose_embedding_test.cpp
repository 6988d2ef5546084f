// Pose keys: their Euclidean distance never exceeds the RMS Kovar distance (the retrieval's bound depends on it),
// for far poses, near poses, turned and moved copies, and with axes learnt from the poses themselves; the
// invariants ignore a turn and a floor move.

#include "kumite/core/pose_embedding.h"
#include "kumite/core/pose_features.h"
#include "kumite/core/split_mix.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <numeric>

using namespace kumite;

namespace {

std::vector<float> random_feature(SplitMix64& random) {
    std::vector<float> feature(k_feature_dimensions, 0.0f);
    for (int p = 0; p < k_feature_cloud_size; ++p) {
        pose_feature_set_point(feature, p, Eigen::Vector3d(random.uniform(-1, 1), random.uniform(0, 2), random.uniform(-1, 1)));
    }
    return feature;
}

std::vector<float> moved(const std::vector<float>& feature, const FloorAlignment& motion) {
    std::vector<float> out(k_feature_dimensions, 0.0f);
    for (int p = 0; p < k_feature_cloud_size; ++p) pose_feature_set_point(out, p, motion.apply(pose_feature_point(feature, p)));
    return out;
}

std::vector<float> jittered(const std::vector<float>& feature, SplitMix64& random, double amount) {
    std::vector<float> out = feature;
    for (int p = 0; p < k_feature_cloud_size; ++p) {
        pose_feature_set_point(out, p, pose_feature_point(feature, p) + Eigen::Vector3d(random.uniform(-amount, amount),
                                                                                       random.uniform(-amount, amount),
                                                                                       random.uniform(-amount, amount)));
    }
    return out;
}

double rms(const std::vector<float>& a, const std::vector<float>& b) { return std::sqrt(pose_feature_distance(a, b) / k_feature_cloud_size); }

double key_distance(const PoseKeyProjection& projection, const std::vector<float>& a, const std::vector<float>& b) {
    std::array<float, k_pose_key_dimensions> key_a, key_b;
    projection.project(a, key_a);
    projection.project(b, key_b);
    double squared = 0.0;
    for (int d = 0; d < k_pose_key_dimensions; ++d) squared += (double(key_a[d]) - key_b[d]) * (double(key_a[d]) - key_b[d]);
    return std::sqrt(squared);
}

} // namespace

TEST_CASE("pose_embedding: invariants ignore a turn and a floor move", "[core]") {
    SplitMix64 random{21};
    const std::vector<float> pose = random_feature(random);
    const std::vector<float> turned = moved(pose, FloorAlignment{1.3, -0.4, 2.2});
    std::array<double, k_pose_invariant_dimensions> a, b;
    pose_invariants(pose, a);
    pose_invariants(turned, b);
    for (int i = 0; i < k_pose_invariant_dimensions; ++i) CHECK(a[i] == Approx(b[i]).margin(1e-5));
}

TEST_CASE("pose_embedding: key distances never exceed the RMS Kovar distance", "[core]") {
    SplitMix64 random{8};
    // A family of poses around a few bases, as a database has: the axes are learnt from them.
    std::vector<std::vector<float>> poses;
    for (int base = 0; base < 6; ++base) {
        const std::vector<float> seed = random_feature(random);
        for (int copy = 0; copy < 40; ++copy) {
            poses.push_back(moved(jittered(seed, random, 0.02 * (1 + copy % 5)), FloorAlignment{random.uniform(-3, 3), random.uniform(-1, 1), 0.3}));
        }
    }
    std::vector<float> flat;
    for (const auto& pose : poses) flat.insert(flat.end(), pose.begin(), pose.end());
    std::vector<std::uint32_t> indices(poses.size());
    std::iota(indices.begin(), indices.end(), 0u);
    const PoseKeyProjection learnt = PoseKeyProjection::learn(flat, indices, 100);
    const PoseKeyProjection identity = PoseKeyProjection::learn(flat, {});

    int pairs = 0, tight = 0;
    double worst_excess = -1.0;
    for (std::size_t i = 0; i < poses.size(); i += 3) {
        for (std::size_t j = 0; j < poses.size(); j += 7) {
            const double exact = rms(poses[i], poses[j]);
            for (const PoseKeyProjection* projection : {&learnt, &identity}) {
                const double bound = key_distance(*projection, poses[i], poses[j]);
                worst_excess = std::max(worst_excess, bound - exact);
                ++pairs;
                tight += projection == &learnt && bound > 0.5 * exact;
            }
        }
    }
    CHECK(worst_excess <= 1e-5); // float keys
    // Not a vacuous bound: with learnt axes most pairs get more than half of their distance.
    CHECK(tight > pairs / 4);
    // Near poses too, and a turned copy is at key distance 0.
    for (int trial = 0; trial < 200; ++trial) {
        const std::vector<float>& pose = poses[random.next() % poses.size()];
        const std::vector<float> near = jittered(pose, random, 0.001 * (1 + trial % 10));
        CHECK(key_distance(learnt, pose, near) <= rms(pose, near) + 1e-5);
    }
    CHECK(key_distance(learnt, poses[0], moved(poses[0], FloorAlignment{2.0, 0.5, -1.0})) == Approx(0.0).margin(1e-5));
}
