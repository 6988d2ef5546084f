#include "kumite/core/contact_point.h"

namespace kumite {

ContactPoint contact_point_of(std::string_view semantics, BodyPart segment, const BodyMap& map) {
    ContactPoint point;
    if (semantics_is_block(semantics) && (segment == BodyPart::forearm_l || segment == BodyPart::forearm_r)) {
        const int wrist = map.joint(segment == BodyPart::forearm_l ? BodyPart::hand_l : BodyPart::hand_r);
        const int elbow = map.joint(segment);
        if (wrist < 0 || elbow < 0) return point;
        point.joint = wrist;
        point.toward = elbow;
        point.fraction = k_block_contact_fraction;
        return point;
    }
    point.joint = map.joint(segment);
    return point;
}

} // namespace kumite
