// Step 7 of the strike's adaptation (strike_adaptation.h): a limb whose extremity is moved keeps bending the way
// the clip bends it, and the joints that still break their limits are reported.
#include "kumite/core/strike_adaptation.h"

#include "kumite/core/two_bone_ik.h"

#include <cmath>

namespace kumite {

bool StrikeAdapter::keep_clip_bends(const LimbPins& pins) {
    if (!m_settings.keep_clip_bends) return false;
    bool changed = false;
    const RestAnatomy& anatomy = m_rig.anatomy();
    const auto positions = m_decoder.model_positions();
    for (int limb = 0; limb < k_limb_count; ++limb) {
        if (m_middle && limb == m_limb) continue; // place_middle gives it the clip's bend, turned
        const LimbChain& chain = anatomy.limbs[limb];
        const Eigen::Vector3d& root = positions[chain.root];
        const Eigen::Vector3d own = root + clip_reach(limb);
        Eigen::Vector3d asked = pins.pinned[limb] ? pins.extremity_world[limb] : Eigen::Vector3d(own + pins.extremity_offset_world[limb]);
        if ((asked - own).norm() < 1e-3 || (asked - root).norm() < 1e-6) continue;
        // The clip's bend carried to the new line: its component across that line, when it keeps one.
        Eigen::Vector3d bend = clip_bend(limb);
        const Eigen::Vector3d axis = (asked - root).normalized();
        bend -= bend.dot(axis) * axis;
        if (bend.norm() < 1e-3) continue; // the new line runs along the old bend: any swivel is as far from it
        const double swivel = limb_swivel(root, root + bend, asked, limb_swivel_reference(m_frame, limb));
        if (std::abs(std::remainder(swivel - m_frame.swivel[limb], 2.0 * 3.14159265358979)) > 1e-4) {
            m_frame.swivel[limb] = swivel;
            changed = true;
        }
    }
    return changed;
}

Eigen::Vector3d StrikeAdapter::clip_reach(int limb) const {
    const LimbChain& chain = m_rig.anatomy().limbs[limb];
    return m_frame.part_frames[chain.parent_part] * m_frame.extremity[limb] * chain.length();
}

Eigen::Vector3d StrikeAdapter::clip_bend(int limb) const {
    const LimbChain& chain = m_rig.anatomy().limbs[limb];
    const Eigen::Vector3d& root = m_decoder.model_positions()[chain.root];
    const Eigen::Vector3d own = root + clip_reach(limb);
    const TwoBoneSolution clip = two_bone_ik(root, own, chain.upper_length, chain.lower_length, m_clip_swivels[limb],
                                             limb_swivel_reference(m_frame, limb));
    return limb_bend_direction(root, clip.middle, clip.extremity, m_settings.limits.bent_rad);
}

unsigned StrikeAdapter::violations() const {
    const RestAnatomy& anatomy = m_rig.anatomy();
    const auto positions = m_decoder.model_positions();
    unsigned mask = 0;
    for (int limb = 0; limb < k_limb_count; ++limb) {
        const LimbChain& chain = anatomy.limbs[limb];
        const Eigen::Vector3d bend =
            limb_bend_direction(positions[chain.root], positions[chain.middle], positions[chain.extremity], m_settings.limits.bent_rad);
        if (limb_bend_flipped(bend, clip_bend(limb), m_settings.limits)) mask |= 1u << limb;
    }
    if (trunk_turn(anatomy, m_decoder.model_rotations()) > m_settings.limits.trunk_turn_rad) mask |= k_trunk_violation;
    return mask;
}

} // namespace kumite
