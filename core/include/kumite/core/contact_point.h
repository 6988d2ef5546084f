#pragma once
// Where a strike or a block meets what it is aimed at: the hit segment's joint (the wrist of a fist, the ankle of
// a foot, the elbow of an elbow strike), or, for a block, the forearm a third of the way from the wrist to the
// elbow, where a karateka's forearm takes the attacking limb.

#include "kumite/core/body_map.h"

#include <Eigen/Core>

#include <span>
#include <string_view>

namespace kumite {

inline constexpr double k_block_contact_fraction = 1.0 / 3.0; // from the wrist towards the elbow

struct ContactPoint {
    int joint = -1;        // the point is this joint's position...
    int toward = -1;       // ...moved towards this joint's (-1: not moved)
    double fraction = 0.0; // by this fraction of the way

    bool valid() const { return joint >= 0; }
    Eigen::Vector3d at(std::span<const Eigen::Vector3d> positions) const {
        const Eigen::Vector3d& point = positions[joint];
        return toward < 0 ? point : Eigen::Vector3d(point + fraction * (positions[toward] - point));
    }
};

// The contact point of a clip of `semantics` whose hit segment is `segment`; invalid when the body map lacks a joint
// it needs. A block's segment is its forearm (forearm_l / forearm_r).
ContactPoint contact_point_of(std::string_view semantics, BodyPart segment, const BodyMap& map);

// Whether a semantics is a block (the defence's moves), not a strike the fighter can be ordered to throw.
inline bool semantics_is_block(std::string_view semantics) { return semantics == "block"; }

} // namespace kumite
