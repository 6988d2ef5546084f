#include "kumite/core/pose_features.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace kumite {
namespace {

using AxisValues = Eigen::Map<const Eigen::Array<float, k_feature_axis_stride, 1>>;

// The sums Kovar's closed form needs, over all points of two planar features (x, z horizontal; y vertical). The
// padding slots hold zeros in both and add nothing. Fixed-size Eigen arrays of 40 floats vectorise.
struct AlignmentSums {
    double ax = 0, az = 0, bx = 0, bz = 0;
    double a_squared = 0, b_squared = 0; // horizontal
    double vertical = 0;                 // sum (a_y - b_y)^2
    double cos_term = 0, sin_term = 0;
    static constexpr int count = k_feature_cloud_size;

    AlignmentSums(std::span<const float> a, std::span<const float> b) {
        assert(a.size() == std::size_t(k_feature_dimensions) && b.size() == a.size());
        constexpr int n = k_feature_axis_stride;
        const AxisValues pax(a.data()), pay(a.data() + n), paz(a.data() + 2 * n);
        const AxisValues pbx(b.data()), pby(b.data() + n), pbz(b.data() + 2 * n);
        ax = pax.sum();
        az = paz.sum();
        bx = pbx.sum();
        bz = pbz.sum();
        a_squared = (pax.square() + paz.square()).sum();
        b_squared = (pbx.square() + pbz.square()).sum();
        vertical = (pay - pby).square().sum();
        cos_term = (pax * pbx + paz * pbz).sum();
        sin_term = (pax * pbz - paz * pbx).sum();
    }
    double centred_cos() const { return cos_term - (ax * bx + az * bz) / count; }
    double centred_sin() const { return sin_term - (ax * bz - az * bx) / count; }
};

} // namespace

void pose_feature_points(std::span<Eigen::Vector3d> out, const BodyMap& body_map, std::span<const Eigen::Vector3d> positions) {
    assert(out.size() == k_feature_parts.size());
    for (std::size_t k = 0; k < k_feature_parts.size(); ++k) out[k] = positions[body_map.joint(k_feature_parts[k])];
}

void pose_feature_build(std::span<float> out, std::span<const Eigen::Vector3d> window_points, const HeadingFrame& heading,
                        double leg_length) {
    assert(out.size() == std::size_t(k_feature_dimensions) && window_points.size() == std::size_t(k_feature_cloud_size));
    std::fill(out.begin(), out.end(), 0.0f);
    const double scale = 1.0 / leg_length;
    for (int i = 0; i < k_feature_cloud_size; ++i) {
        const Eigen::Vector3d local = heading.to_heading(window_points[i]) * scale;
        for (int axis = 0; axis < 3; ++axis) out[axis * k_feature_axis_stride + i] = static_cast<float>(local[axis]);
    }
}

Eigen::Vector3d pose_feature_point(std::span<const float> feature, int point) {
    return {feature[point], feature[k_feature_axis_stride + point], feature[2 * k_feature_axis_stride + point]};
}

void pose_feature_set_point(std::span<float> feature, int point, const Eigen::Vector3d& value) {
    for (int axis = 0; axis < 3; ++axis) feature[axis * k_feature_axis_stride + point] = static_cast<float>(value[axis]);
}

double pose_feature_distance(std::span<const float> a, std::span<const float> b) {
    const AlignmentSums sums(a, b);
    // With the best floor translation the clouds' horizontal centroids meet; what remains is
    // |a~|^2 + |b~|^2 - 2 max_angle sum a~ . R b~, and that maximum is the length of (centred_cos, centred_sin).
    const double a_centred = sums.a_squared - (sums.ax * sums.ax + sums.az * sums.az) / sums.count;
    const double b_centred = sums.b_squared - (sums.bx * sums.bx + sums.bz * sums.bz) / sums.count;
    // sqrt rather than std::hypot: the sums are of a few dozen coordinates in leg lengths, far from overflow, and
    // hypot's guards cost an eighth of a retrieval (retrieval_bench).
    const double cos_part = sums.centred_cos(), sin_part = sums.centred_sin();
    const double best = std::sqrt(cos_part * cos_part + sin_part * sin_part);
    return std::max(0.0, sums.vertical + a_centred + b_centred - 2.0 * best);
}

FloorAlignment pose_feature_alignment(std::span<const float> a, std::span<const float> b) {
    const AlignmentSums sums(a, b);
    FloorAlignment alignment;
    alignment.angle_rad = std::atan2(sums.centred_sin(), sums.centred_cos());
    const double c = std::cos(alignment.angle_rad), s = std::sin(alignment.angle_rad);
    alignment.x = (sums.ax - (c * sums.bx + s * sums.bz)) / sums.count;
    alignment.z = (sums.az - (-s * sums.bx + c * sums.bz)) / sums.count;
    return alignment;
}

} // namespace kumite
