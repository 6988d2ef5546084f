#pragma once
// Deterministic k-means: k-means++ seeding from a fixed seed, then Lloyd iterations until no point changes
// cluster (or an iteration cap). Same input and seed, same clusters, on any machine and with any thread count:
// the random numbers come from SplitMix64 (not std:: distributions, whose algorithms differ between libraries),
// threads only split the assignment step, and centroids are recomputed from members in point order.
//
// The space is abstract (`KMeansSpace`) so that the same loop clusters plain vectors (kmeans_cluster) and pose
// point clouds under Kovar's alignment-invariant distance (pose_clusters.h).

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace kumite {

inline constexpr std::uint64_t k_kmeans_default_seed = 0x6b756d697465ull; // "kumite"

struct KMeansSpace {
    int point_count = 0;
    std::function<void(int centroid, int point)> seed_centroid;                       // centroid := point
    std::function<double(int point, int centroid)> distance;                          // thread-safe (read-only)
    std::function<void(int centroid, std::span<const int> members)> update_centroid; // members in point order, never empty
};

struct KMeansAssignment {
    std::vector<int> assignment; // [point] cluster index
    std::vector<double> distance; // [point] distance to its centroid
    double inertia = 0.0;        // sum of those distances
    int iterations = 0;
    int k = 0;
};

// k is clamped to [1, point_count]; point_count >= 1. `progress`, if given, is called after each iteration.
KMeansAssignment kmeans_run(const KMeansSpace& space, int k, std::uint64_t seed, int max_iterations, int threads = 1,
                            const std::function<void(int iteration)>& progress = {});

struct KMeansResult {
    Eigen::MatrixXd centroids;         // [k x dimensions]
    std::vector<int> assignment;       // [point] cluster index
    double inertia = 0.0;              // sum of squared distances to the assigned centroid
    int iterations = 0;
};

// Euclidean k-means. points: [n x dimensions], n >= 1.
KMeansResult kmeans_cluster(const Eigen::MatrixXd& points, int k, std::uint64_t seed = k_kmeans_default_seed, int max_iterations = 100);

} // namespace kumite
