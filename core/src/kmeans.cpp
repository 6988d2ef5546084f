#include "kumite/core/kmeans.h"

#include "kumite/core/split_mix.h"

#include <algorithm>
#include <cassert>
#include <limits>
#include <thread>

namespace kumite {
namespace {

// k-means++: the first centre uniformly, each next one with probability proportional to the distance to the
// nearest centre so far.
void seed_centroids(const KMeansSpace& space, int k, std::uint64_t seed) {
    const int n = space.point_count;
    SplitMix64 random{seed};
    std::vector<double> nearest(n, std::numeric_limits<double>::infinity());
    int chosen = static_cast<int>(random.uniform() * n);
    for (int c = 0; c < k; ++c) {
        space.seed_centroid(c, chosen);
        double total = 0.0;
        for (int i = 0; i < n; ++i) {
            nearest[i] = std::min(nearest[i], space.distance(i, c));
            total += nearest[i];
        }
        if (c + 1 == k) break;
        if (total <= 0.0) { // every point sits on a centre already: take the next index
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
}

// Nearest centroid of points [begin, end); ties go to the lower index.
void assign_range(const KMeansSpace& space, int k, int begin, int end, std::vector<int>& assignment, std::vector<double>& distance) {
    for (int i = begin; i < end; ++i) {
        int best = 0;
        double best_distance = std::numeric_limits<double>::infinity();
        for (int c = 0; c < k; ++c) {
            const double d = space.distance(i, c);
            if (d < best_distance) {
                best_distance = d;
                best = c;
            }
        }
        assignment[i] = best;
        distance[i] = best_distance;
    }
}

} // namespace

KMeansAssignment kmeans_run(const KMeansSpace& space, int k, std::uint64_t seed, int max_iterations, int threads,
                            const std::function<void(int)>& progress) {
    const int n = space.point_count;
    assert(n >= 1);
    k = std::clamp(k, 1, n);
    threads = std::clamp(threads, 1, 64);
    seed_centroids(space, k, seed);

    KMeansAssignment result;
    result.k = k;
    result.assignment.assign(n, -1);
    result.distance.assign(n, 0.0);
    std::vector<int> previous;
    std::vector<std::vector<int>> members(k);
    for (result.iterations = 1;; ++result.iterations) {
        previous = result.assignment;
        std::vector<std::thread> workers;
        const int chunk = (n + threads - 1) / threads;
        for (int t = 1; t < threads; ++t) {
            const int begin = std::min(n, t * chunk), end = std::min(n, (t + 1) * chunk);
            if (begin < end) workers.emplace_back([&, begin, end] { assign_range(space, k, begin, end, result.assignment, result.distance); });
        }
        assign_range(space, k, 0, std::min(n, chunk), result.assignment, result.distance);
        for (std::thread& worker : workers) worker.join();
        result.inertia = 0.0;
        for (int i = 0; i < n; ++i) result.inertia += result.distance[i];
        if (progress) progress(result.iterations);
        if (result.assignment == previous || result.iterations >= max_iterations) break;
        for (auto& list : members) list.clear();
        for (int i = 0; i < n; ++i) members[result.assignment[i]].push_back(i);
        for (int c = 0; c < k; ++c) {
            if (!members[c].empty()) space.update_centroid(c, members[c]); // an empty cluster keeps its centre
        }
    }
    return result;
}

KMeansResult kmeans_cluster(const Eigen::MatrixXd& points, int k, std::uint64_t seed, int max_iterations) {
    const int n = static_cast<int>(points.rows());
    assert(n >= 1);
    KMeansResult result;
    result.centroids.resize(std::clamp(k, 1, n), points.cols());
    KMeansSpace space;
    space.point_count = n;
    space.seed_centroid = [&](int c, int i) { result.centroids.row(c) = points.row(i); };
    space.distance = [&](int i, int c) { return (points.row(i) - result.centroids.row(c)).squaredNorm(); };
    space.update_centroid = [&](int c, std::span<const int> members) {
        Eigen::RowVectorXd sum = Eigen::RowVectorXd::Zero(points.cols());
        for (int i : members) sum += points.row(i);
        result.centroids.row(c) = sum / static_cast<double>(members.size());
    };
    KMeansAssignment assignment = kmeans_run(space, k, seed, max_iterations);
    result.assignment = std::move(assignment.assignment);
    result.inertia = assignment.inertia;
    result.iterations = assignment.iterations;
    return result;
}

} // namespace kumite
