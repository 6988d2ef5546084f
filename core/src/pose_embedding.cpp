#include "kumite/core/pose_embedding.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cassert>
#include <cmath>

namespace kumite {

void pose_invariants(std::span<const float> feature, std::span<double> out) {
    assert(feature.size() == std::size_t(k_feature_dimensions) && out.size() == std::size_t(k_pose_invariant_dimensions));
    constexpr int n = k_feature_cloud_size;
    constexpr int stride = k_feature_axis_stride;
    double mean_x = 0.0, mean_z = 0.0;
    for (int i = 0; i < n; ++i) {
        mean_x += feature[i];
        mean_z += feature[2 * stride + i];
    }
    mean_x /= n;
    mean_z /= n;
    const double to_rms = 1.0 / std::sqrt(static_cast<double>(n));
    for (int i = 0; i < n; ++i) {
        out[i] = feature[stride + i] * to_rms;
        const double dx = feature[i] - mean_x, dz = feature[2 * stride + i] - mean_z;
        out[n + i] = std::sqrt(dx * dx + dz * dz) * to_rms; // leg lengths: no overflow for hypot to guard against
    }
}

PoseKeyProjection PoseKeyProjection::learn(std::span<const float> features, std::span<const std::uint32_t> poses, int max_samples) {
    constexpr int d = k_pose_invariant_dimensions;
    using Matrix = Eigen::Matrix<double, d, d>;
    using Vector = Eigen::Matrix<double, d, 1>;
    PoseKeyProjection projection;
    projection.m_axes.assign(std::size_t(k_pose_key_axes) * d, 0.0);
    const std::size_t count = poses.size();
    if (count == 0) {
        for (int axis = 0; axis < k_pose_key_axes; ++axis) projection.m_axes[std::size_t(axis) * d + axis] = 1.0;
        return projection;
    }
    const std::size_t samples = std::min<std::size_t>(count, static_cast<std::size_t>(std::max(1, max_samples)));
    std::vector<Vector> invariants(samples);
    Vector mean = Vector::Zero();
    for (std::size_t s = 0; s < samples; ++s) {
        const std::uint32_t pose = poses[s * count / samples];
        pose_invariants(features.subspan(std::size_t(pose) * k_feature_dimensions, k_feature_dimensions),
                        std::span<double>(invariants[s].data(), d));
        mean += invariants[s];
    }
    mean /= static_cast<double>(samples);
    Matrix covariance = Matrix::Zero();
    for (const Vector& v : invariants) covariance.selfadjointView<Eigen::Lower>().rankUpdate(v - mean);
    const Eigen::SelfAdjointEigenSolver<Matrix> solver(covariance.selfadjointView<Eigen::Lower>());
    for (int i = 0; i < d; ++i) projection.m_mean[i] = mean[i];
    for (int axis = 0; axis < k_pose_key_axes; ++axis) { // eigenvalues ascend: the largest last
        const Vector direction = solver.eigenvectors().col(d - 1 - axis);
        for (int i = 0; i < d; ++i) projection.m_axes[std::size_t(axis) * d + i] = direction[i];
    }
    return projection;
}

void PoseKeyProjection::project(std::span<const float> feature, std::span<float> key) const {
    assert(key.size() == std::size_t(k_pose_key_dimensions));
    constexpr int d = k_pose_invariant_dimensions;
    std::array<double, d> centred;
    pose_invariants(feature, centred);
    for (int i = 0; i < d; ++i) centred[i] -= m_mean[i];
    // Eigen's fixed-size dot products vectorise (a scalar loop's double sum cannot be reordered): 1.5 us of a
    // 17 us retrieval before (retrieval_bench).
    using Values = Eigen::Matrix<double, d, 1>;
    const Eigen::Map<const Values> centred_values(centred.data());
    Values residual = centred_values;
    for (int axis = 0; axis < k_pose_key_axes; ++axis) {
        const Eigen::Map<const Values> direction(m_axes.data() + std::size_t(axis) * d);
        const double along = direction.dot(centred_values);
        residual -= along * direction;
        key[axis] = static_cast<float>(along);
    }
    key[k_pose_key_axes] = static_cast<float>(residual.norm());
}

} // namespace kumite
