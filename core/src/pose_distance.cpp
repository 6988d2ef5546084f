#include "kumite/core/pose_distance.h"

#include <cassert>
#include <cmath>

namespace kumite {

Eigen::Vector3d FloorAlignment::apply(const Eigen::Vector3d& p) const {
    const double c = std::cos(angle_rad), s = std::sin(angle_rad);
    return {c * p.x() + s * p.z() + x, p.y(), -s * p.x() + c * p.z() + z};
}

FloorAlignment kovar_alignment(std::span<const Eigen::Vector3d> a, std::span<const Eigen::Vector3d> b, std::span<const double> weights) {
    assert(a.size() == b.size());
    assert(weights.empty() || weights.size() == a.size());
    // For a fixed rotation the best translation matches the weighted centroids on the floor; what remains is to
    // maximise sum w (a - a_mean) . R (b - b_mean) over the angle, which is atan2 of two weighted sums.
    double total = 0.0, ax = 0.0, az = 0.0, bx = 0.0, bz = 0.0, sum_cos = 0.0, sum_sin = 0.0;
    for (size_t i = 0; i < a.size(); ++i) {
        const double w = weights.empty() ? 1.0 : weights[i];
        total += w;
        ax += w * a[i].x();
        az += w * a[i].z();
        bx += w * b[i].x();
        bz += w * b[i].z();
        sum_cos += w * (a[i].x() * b[i].x() + a[i].z() * b[i].z());
        sum_sin += w * (a[i].x() * b[i].z() - a[i].z() * b[i].x());
    }
    assert(total > 0.0);
    const double centred_cos = sum_cos - (ax * bx + az * bz) / total;
    const double centred_sin = sum_sin - (ax * bz - az * bx) / total;
    FloorAlignment alignment;
    alignment.angle_rad = std::atan2(centred_sin, centred_cos);
    const double c = std::cos(alignment.angle_rad), s = std::sin(alignment.angle_rad);
    alignment.x = (ax - (c * bx + s * bz)) / total;
    alignment.z = (az - (-s * bx + c * bz)) / total;
    return alignment;
}

double kovar_distance(std::span<const Eigen::Vector3d> a, std::span<const Eigen::Vector3d> b, std::span<const double> weights,
                      FloorAlignment* alignment_out) {
    const FloorAlignment alignment = kovar_alignment(a, b, weights);
    double distance = 0.0;
    for (size_t i = 0; i < a.size(); ++i) {
        const double w = weights.empty() ? 1.0 : weights[i];
        distance += w * (a[i] - alignment.apply(b[i])).squaredNorm();
    }
    if (alignment_out) *alignment_out = alignment;
    return distance;
}

} // namespace kumite
