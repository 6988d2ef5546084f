#pragma once
// Clusters of poses under Kovar's alignment-invariant distance: k-means (kmeans.h) whose distance is
// pose_feature_distance and whose centroid is the mean of its members each aligned onto the previous centroid
// (Kovar's closed form), so a centroid is itself a pose feature.

#include "kumite/core/kmeans.h"
#include "kumite/core/motion_database.h"

namespace kumite {

struct PoseClusters {
    int k = 0;
    std::vector<float> centroids;  // [cluster * k_feature_dimensions]
    std::vector<int> assignment;   // [pose]
    std::vector<double> distance;  // [pose] Kovar distance to its centroid
    double inertia = 0.0;
    int iterations = 0;
};

// features: [pose * k_feature_dimensions], at least one pose.
PoseClusters pose_clusters_compute(std::span<const float> features, int k, std::uint64_t seed = k_kmeans_default_seed,
                                   int max_iterations = 50, int threads = 1, const std::function<void(int)>& progress = {});

} // namespace kumite
