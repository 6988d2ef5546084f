#include "kumite/core/halfspace_projection.h"

#include <Eigen/LU>

#include <algorithm>
#include <cassert>
#include <limits>

namespace kumite {
namespace {

bool inside(const Eigen::Vector3d& x, std::span<const Eigen::Vector3d> normals, std::span<const double> bounds) {
    for (std::size_t k = 0; k < normals.size(); ++k) {
        if (normals[k].dot(x) > bounds[k] + 1e-12) return false;
    }
    return true;
}

} // namespace

Eigen::Vector3d nearest_within_halfspaces(const Eigen::Vector3d& point, std::span<const Eigen::Vector3d> normals,
                                          std::span<const double> bounds, const Eigen::Vector3d& fallback) {
    assert(normals.size() == bounds.size() && normals.size() <= std::size_t(k_halfspace_max));
    if (inside(point, normals, bounds)) return point;
    const int n = static_cast<int>(normals.size());
    Eigen::Vector3d best = fallback;
    double best_squared = std::numeric_limits<double>::infinity();
    // x = point - sum_j mu_j n_j over an active set, with n_i . x = b_i on it and mu >= 0 (KKT).
    auto try_set = [&](const int* set, int size) {
        Eigen::Matrix3d gram = Eigen::Matrix3d::Identity();
        Eigen::Vector3d excess = Eigen::Vector3d::Zero();
        for (int i = 0; i < size; ++i) {
            excess[i] = normals[set[i]].dot(point) - bounds[set[i]];
            for (int j = 0; j < size; ++j) gram(i, j) = normals[set[i]].dot(normals[set[j]]);
        }
        Eigen::Vector3d mu = Eigen::Vector3d::Zero();
        if (size == 1) {
            mu[0] = excess[0] / gram(0, 0);
        } else if (size == 2) {
            const Eigen::Matrix2d g = gram.topLeftCorner<2, 2>();
            if (std::abs(g.determinant()) < 1e-12) return;
            mu.head<2>() = g.inverse() * excess.head<2>();
        } else {
            if (std::abs(gram.determinant()) < 1e-12) return;
            mu = gram.inverse() * excess;
        }
        for (int i = 0; i < size; ++i) {
            if (mu[i] < -1e-12) return;
        }
        Eigen::Vector3d x = point;
        for (int i = 0; i < size; ++i) x -= mu[i] * normals[set[i]];
        const double squared = (x - point).squaredNorm();
        if (squared < best_squared && inside(x, normals, bounds)) {
            best_squared = squared;
            best = x;
        }
    };
    for (int a = 0; a < n; ++a) {
        const int one[1] = {a};
        try_set(one, 1);
        for (int b = a + 1; b < n; ++b) {
            const int two[2] = {a, b};
            try_set(two, 2);
            for (int c = b + 1; c < n; ++c) {
                const int three[3] = {a, b, c};
                try_set(three, 3);
            }
        }
    }
    return best;
}

} // namespace kumite
