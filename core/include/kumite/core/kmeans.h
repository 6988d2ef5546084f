#pragma once
// Deterministic k-means: k-means++ seeding from a fixed seed, then Lloyd iterations until no point changes
// cluster (or an iteration cap). Same input and seed, same clusters, on any machine: the random numbers come from
// a small generator of our own, not from std:: distributions whose algorithms differ between libraries.

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace kumite {

struct KMeansResult {
    Eigen::MatrixXd centroids;         // [k x dimensions]
    std::vector<int> assignment;       // [point] cluster index
    double inertia = 0.0;              // sum of squared distances to the assigned centroid
    int iterations = 0;
};

// points: [n x dimensions], n >= 1; k is clamped to [1, n].
KMeansResult kmeans_cluster(const Eigen::MatrixXd& points, int k, std::uint64_t seed = 0x6b756d697465ull, int max_iterations = 100);

} // namespace kumite
