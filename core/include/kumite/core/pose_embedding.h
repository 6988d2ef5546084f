#pragma once
// A short vector per pose whose Euclidean distances never exceed Kovar's distance: the key the retrieval's tree
// bounds pose distances with, before any exact distance is computed.
//
// Why it is a lower bound. Kovar's distance between clouds a and b is
//     sum_i (a_y,i - b_y,i)^2 + min_R sum_i |a~_i - R b~_i|^2
// (vertical part, then the horizontal part with both clouds centred on their floor centroids, which the best
// translation matches, and R a turn about Y). A turn keeps each point's distance to the centroid, so
// |a~_i - R b~_i| >= | |a~_i| - |b~_i| | for every R: the vector of heights and horizontal radii of the 39 points
// ("invariants", 78 numbers) is a map into Euclidean space that never lengthens a Kovar distance. Projecting onto
// orthonormal axes (the invariants' principal axes, learnt from the database's poses) shortens distances again, and
// the length of what the projection leaves out, kept as one more coordinate, adds back what it can
// (| |r_a| - |r_b| | <= |r_a - r_b|). All values are divided by sqrt(39), so key distances bound the RMS distance
// the retrieval scores (rms_distance = sqrt(Kovar / 39)).

#include "kumite/core/motion_database.h"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace kumite {

inline constexpr int k_pose_invariant_dimensions = 2 * k_feature_cloud_size; // heights, then horizontal radii
inline constexpr int k_pose_key_axes = 11;                                   // principal axes kept
inline constexpr int k_pose_key_dimensions = k_pose_key_axes + 1;            // + the residual's length

// The 78 invariants of a feature (heights, radii about the floor centroid), divided by sqrt(39).
void pose_invariants(std::span<const float> feature, std::span<double> out);

class PoseKeyProjection {
public:
    // Principal axes of the invariants of the features of `poses` (at most `max_samples` of them, evenly spaced);
    // `features` is the database's flat feature array. With no poses, the first axes of the invariants themselves.
    static PoseKeyProjection learn(std::span<const float> features, std::span<const std::uint32_t> poses, int max_samples = 20000);

    // key: k_pose_key_dimensions floats. For features a and b,
    // |key(a) - key(b)| <= sqrt(pose_feature_distance(a, b) / k_feature_cloud_size) up to float rounding.
    void project(std::span<const float> feature, std::span<float> key) const;

private:
    std::array<double, k_pose_invariant_dimensions> m_mean{};
    std::vector<double> m_axes; // [axis][invariant], orthonormal rows
};

} // namespace kumite
