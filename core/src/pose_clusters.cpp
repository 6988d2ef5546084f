#include "kumite/core/pose_clusters.h"

#include "kumite/core/pose_features.h"

#include <cassert>

namespace kumite {

PoseClusters pose_clusters_compute(std::span<const float> features, int k, std::uint64_t seed, int max_iterations, int threads,
                                   const std::function<void(int)>& progress) {
    constexpr int dims = k_feature_dimensions;
    const int n = static_cast<int>(features.size() / dims);
    assert(n >= 1);
    PoseClusters clusters;
    clusters.k = std::clamp(k, 1, n);
    clusters.centroids.assign(std::size_t(clusters.k) * dims, 0.0f);
    auto pose = [&](int i) { return features.subspan(std::size_t(i) * dims, dims); };
    auto centroid = [&](int c) { return std::span<float>(clusters.centroids).subspan(std::size_t(c) * dims, dims); };

    KMeansSpace space;
    space.point_count = n;
    space.seed_centroid = [&](int c, int i) { std::copy_n(pose(i).begin(), dims, centroid(c).begin()); };
    space.distance = [&](int i, int c) { return pose_feature_distance(centroid(c), pose(i)); };
    std::vector<Eigen::Vector3d> sum(k_feature_cloud_size);
    space.update_centroid = [&](int c, std::span<const int> members) {
        std::fill(sum.begin(), sum.end(), Eigen::Vector3d::Zero());
        const std::span<float> centre = centroid(c);
        for (int i : members) {
            const FloorAlignment onto_centre = pose_feature_alignment(centre, pose(i));
            for (int p = 0; p < k_feature_cloud_size; ++p) sum[p] += onto_centre.apply(pose_feature_point(pose(i), p));
        }
        for (int p = 0; p < k_feature_cloud_size; ++p) pose_feature_set_point(centre, p, sum[p] / static_cast<double>(members.size()));
    };
    KMeansAssignment result = kmeans_run(space, clusters.k, seed, max_iterations, threads, progress);
    clusters.assignment = std::move(result.assignment);
    clusters.distance = std::move(result.distance);
    clusters.inertia = result.inertia;
    clusters.iterations = result.iterations;
    return clusters;
}

} // namespace kumite
