#include "kumite/core/kmeans.h"

#include <algorithm>
#include <cassert>
#include <limits>

namespace kumite {
namespace {

// splitmix64: tiny, fast, and the same everywhere.
struct SplitMix {
    std::uint64_t state;
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    double uniform() { return (next() >> 11) * (1.0 / 9007199254740992.0); } // [0, 1)
};

} // namespace

KMeansResult kmeans_cluster(const Eigen::MatrixXd& points, int k, std::uint64_t seed, int max_iterations) {
    const int n = static_cast<int>(points.rows());
    assert(n >= 1);
    k = std::clamp(k, 1, n);
    SplitMix random{seed};
    KMeansResult result;
    result.centroids.resize(k, points.cols());

    // k-means++: the first centre uniformly, each next one with probability proportional to the squared distance
    // to the nearest centre so far.
    std::vector<double> nearest(n, std::numeric_limits<double>::infinity());
    int chosen = static_cast<int>(random.uniform() * n);
    for (int c = 0; c < k; ++c) {
        result.centroids.row(c) = points.row(chosen);
        double total = 0.0;
        for (int i = 0; i < n; ++i) {
            nearest[i] = std::min(nearest[i], (points.row(i) - result.centroids.row(c)).squaredNorm());
            total += nearest[i];
        }
        if (c + 1 == k) break;
        if (total <= 0.0) { // every point sits on a centre already: take the next unused index
            chosen = (chosen + 1) % n;
            continue;
        }
        double pick = random.uniform() * total;
        chosen = n - 1;
        for (int i = 0; i < n; ++i) {
            pick -= nearest[i];
            if (pick < 0.0) {
                chosen = i;
                break;
            }
        }
    }

    result.assignment.assign(n, -1);
    for (result.iterations = 0; result.iterations < max_iterations; ++result.iterations) {
        bool changed = false;
        result.inertia = 0.0;
        for (int i = 0; i < n; ++i) {
            int best = 0;
            double best_distance = std::numeric_limits<double>::infinity();
            for (int c = 0; c < k; ++c) {
                const double distance = (points.row(i) - result.centroids.row(c)).squaredNorm();
                if (distance < best_distance) { // strict: ties go to the lower index, deterministically
                    best_distance = distance;
                    best = c;
                }
            }
            changed |= result.assignment[i] != best;
            result.assignment[i] = best;
            result.inertia += best_distance;
        }
        if (!changed) break;
        Eigen::MatrixXd sums = Eigen::MatrixXd::Zero(k, points.cols());
        std::vector<int> counts(k, 0);
        for (int i = 0; i < n; ++i) {
            sums.row(result.assignment[i]) += points.row(i);
            ++counts[result.assignment[i]];
        }
        for (int c = 0; c < k; ++c) {
            if (counts[c] > 0) result.centroids.row(c) = sums.row(c) / counts[c]; // an empty cluster keeps its centre
        }
    }
    return result;
}

} // namespace kumite
