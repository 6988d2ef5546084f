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
    std::vector<double> sum(dims);
    space.update_centroid = [&](int c, std::span<const int> members) {
        std::fill(sum.begin(), sum.end(), 0.0);
        const std::span<float> centre = centroid(c);
        for (int i : members) {
            const FloorAlignment onto_centre = pose_feature_alignment(centre, pose(i));
            const std::span<const float> member = pose(i);
            for (int p = 0; p < dims; p += 3) {
                const Eigen::Vector3d aligned = onto_centre.apply(Eigen::Vector3d(member[p], member[p + 1], member[p + 2]));
                for (int axis = 0; axis < 3; ++axis) sum[p + axis] += aligned[axis];
            }
        }
        for (int d = 0; d < dims; ++d) centre[d] = static_cast<float>(sum[d] / static_cast<double>(members.size()));
    };
    KMeansAssignment result = kmeans_run(space, clusters.k, seed, max_iterations, threads, progress);
    clusters.assignment = std::move(result.assignment);
    clusters.distance = std::move(result.distance);
    clusters.inertia = result.inertia;
    clusters.iterations = result.iterations;
    return clusters;
}

} // namespace kumite
