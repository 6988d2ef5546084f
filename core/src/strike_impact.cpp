// Step 6 of the strike's adaptation (strike_adaptation.h): after the contact the hit point may not pass the stop
// point along the strike's approach directions by more than a soft margin; how far past it a point is.
#include "kumite/core/strike_adaptation.h"

#include "kumite/core/halfspace_projection.h"

#include <algorithm>
#include <cmath>

namespace kumite {

double StrikeAdapter::past_stop(const Eigen::Vector3d& point) const {
    // Through the target only: within target_radius_m of the approach line. A kick whose last chords turn back
    // towards the kicker (a roundhouse's sweep) drops its foot to the floor beyond the stop point along them, but a
    // metre under the head, not through it.
    double past = 0.0;
    const Eigen::Vector3d displacement = point - m_stop_point;
    for (int k = 0; k < m_approach_count; ++k) {
        const double along = displacement.dot(m_approaches[k]);
        if ((displacement - along * m_approaches[k]).norm() <= m_settings.target_radius_m) past = std::max(past, along - m_plane_offsets[k]);
    }
    return past;
}

Eigen::Vector3d StrikeAdapter::impact_correction(const Eigen::Vector3d& point, double index) const {
    if (!m_impact || (index <= contact_index() && index < m_early_stop_index)) return Eigen::Vector3d::Zero();
    // Past the stop point along approach direction k by g_k: the least move of the hit point that brings each g_k
    // down to softness * (1 - exp(-g_k / softness)) (C1 at g_k = 0, below the softness), and keeps the others
    // within the softness. What goes back or aside from every approach direction (the retraction) is kept.
    const double softness = m_settings.overshoot_softness_m;
    if (softness <= 0.0) return Eigen::Vector3d::Zero();
    const Eigen::Vector3d displacement = point - m_stop_point;
    std::array<double, k_approach_chords + 1> bounds{};
    bool past = false;
    for (int k = 0; k < m_approach_count; ++k) {
        const double along = displacement.dot(m_approaches[k]) - m_plane_offsets[k];
        bounds[k] = m_plane_offsets[k] + (along > 0.0 ? softness * (1.0 - std::exp(-along / softness)) : softness);
        past = past || along > 0.0;
    }
    if (!past) return Eigen::Vector3d::Zero();
    const Eigen::Vector3d held = nearest_within_halfspaces(displacement, {m_approaches.data(), std::size_t(m_approach_count)},
                                                           {bounds.data(), std::size_t(m_approach_count)}, Eigen::Vector3d::Zero());
    return held - displacement;
}

void StrikeAdapter::stop_early(double index, const Eigen::Vector3d& stop_world, const Eigen::Vector3d& direction) {
    if (!stopped_early()) m_early_stop_index = index;
    m_stop_point = stop_world;
    m_approach = direction;
    m_approaches[0] = direction;
    m_plane_offsets[0] = 0.0;
    m_approach_count = 1;
    m_impact = true;
}

void StrikeAdapter::stop_early(double index, const Eigen::Vector3d& stop_world, const Eigen::Vector3d& direction, const Eigen::Vector3d& also_stop_world,
                               const Eigen::Vector3d& also_direction) {
    stop_early(index, stop_world, direction);
    m_approaches[1] = also_direction;
    m_plane_offsets[1] = (also_stop_world - stop_world).dot(also_direction);
    m_approach_count = 2;
}

bool StrikeAdapter::stop_at_target(LimbPins& pins, double index) const {
    const Eigen::Vector3d correction = impact_correction(m_decoder.limb_targets()[m_limb], index);
    if (correction.isZero()) return false;
    pins.extremity_offset_world[m_limb] += correction;
    return true;
}

} // namespace kumite
