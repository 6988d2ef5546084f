#include "kumite/core/mir_edit.h"

#include <array>
#include <cmath>
#include <numbers>

namespace kumite {
namespace {

Eigen::Quaterniond chain_sample(const MirChainFrames& chain, double fraction) {
    if (chain.count == 0) return Eigen::Quaterniond::Identity();
    if (fraction <= chain.fractions[0]) return chain.frames[0];
    for (int k = 1; k < chain.count; ++k) {
        if (fraction <= chain.fractions[k]) {
            const double span = chain.fractions[k] - chain.fractions[k - 1];
            return chain.frames[k - 1].slerp(span > 1e-12 ? (fraction - chain.fractions[k - 1]) / span : 1.0, chain.frames[k]);
        }
    }
    return chain.frames[chain.count - 1];
}

void turn_parts(MirFrame& frame, const Eigen::Quaterniond& rotation, std::initializer_list<BodyPart> parts) {
    for (BodyPart part : parts) frame.part_frames[static_cast<int>(part)] = rotation * frame.part_frames[static_cast<int>(part)];
}

void turn_arm(MirFrame& frame, const Eigen::Quaterniond& rotation, bool left) {
    if (left) turn_parts(frame, rotation, {BodyPart::clavicle_l, BodyPart::upper_arm_l, BodyPart::forearm_l, BodyPart::hand_l});
    else turn_parts(frame, rotation, {BodyPart::clavicle_r, BodyPart::upper_arm_r, BodyPart::forearm_r, BodyPart::hand_r});
}

void turn_above_chest(MirFrame& frame, const Eigen::Quaterniond& rotation) {
    turn_parts(frame, rotation, {BodyPart::chest, BodyPart::neck, BodyPart::head});
    for (int k = 0; k < frame.neck.count; ++k) frame.neck.frames[k] = rotation * frame.neck.frames[k];
    if (frame.spine.count > 0) frame.spine.frames[frame.spine.count - 1] = rotation * frame.spine.frames[frame.spine.count - 1];
    turn_arm(frame, rotation, true);
    turn_arm(frame, rotation, false);
}

// The part whose frame a limb's extremity is expressed in (RestAnatomy's LimbChain::parent_part): an arm's clavicle
// (the chest without one), a leg's pelvis.
int limb_parent_part(const MirFrame& frame, int limb) {
    if (limb >= 2) return static_cast<int>(BodyPart::pelvis);
    const int clavicle = static_cast<int>(limb == 0 ? BodyPart::clavicle_l : BodyPart::clavicle_r);
    return frame.has_part[clavicle] ? clavicle : static_cast<int>(BodyPart::chest);
}

// A limb part's frame part of the way from `a` to `b`: its bone (the frame's y axis) along the great circle between
// the two, and the turn about the bone alone. How a limb frame turns about its bone is a convention of the skeleton
// it was encoded from (the rest pose's secondary axis): between a capture's frame and a character's the two can be
// half a turn apart about the bone, and a plain slerp between such frames swings the bone itself far off both —
// a shoulder thrown up and back in the middle of a blend. Swing and twist apart, the bone only swings as far as
// the two bones are apart.
Eigen::Quaterniond limb_part_blend(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b, double w) {
    const Eigen::Vector3d bone_a = a * Eigen::Vector3d::UnitY();
    Eigen::Quaterniond delta = b * a.conjugate();
    if (delta.w() < 0.0) delta.coeffs() = -delta.coeffs();
    const Eigen::Vector3d along = delta.vec().dot(bone_a) * bone_a;
    Eigen::Quaterniond twist(delta.w(), along.x(), along.y(), along.z());
    if (twist.norm() < 1e-9) twist = Eigen::Quaterniond::Identity(); // a half turn across the bone: all swing
    else twist.normalize();
    const Eigen::Quaterniond swing = delta * twist.conjugate();
    const Eigen::Quaterniond identity = Eigen::Quaterniond::Identity();
    return (identity.slerp(w, swing) * identity.slerp(w, twist) * a).normalized();
}

// A limb's reach (root to extremity, limb lengths) part of the way from `a` to `b`: its direction along the great
// circle, its length in between. A straight line between the two would shorten the limb on the way (the elbow
// bending and straightening again in every blend between two straight arms).
Eigen::Vector3d blend_reach(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double w) {
    const double length_a = a.norm(), length_b = b.norm();
    const double length = (1.0 - w) * length_a + w * length_b;
    if (length_a < 1e-9 || length_b < 1e-9) return (1.0 - w) * a + w * b;
    const Eigen::Quaterniond turn = Eigen::Quaterniond::Identity().slerp(w, Eigen::Quaterniond::FromTwoVectors(a, b));
    return length * (turn * (a / length_a));
}

} // namespace

void mir_frame_move_on_floor(MirFrame& frame, const FloorAlignment& motion, double leg_length) {
    const Eigen::Quaterniond turn(Eigen::AngleAxisd(motion.angle_rad, Eigen::Vector3d::UnitY()));
    const FloorAlignment normalised{motion.angle_rad, motion.x / leg_length, motion.z / leg_length};
    const Eigen::Vector3d moved = normalised.apply(Eigen::Vector3d(frame.hip_centre.x(), 0.0, frame.hip_centre.z()));
    frame.hip_centre.x() = moved.x();
    frame.hip_centre.z() = moved.z();
    for (Eigen::Quaterniond& part : frame.part_frames) part = turn * part;
    for (int k = 0; k < frame.spine.count; ++k) frame.spine.frames[k] = turn * frame.spine.frames[k];
    for (int k = 0; k < frame.neck.count; ++k) frame.neck.frames[k] = turn * frame.neck.frames[k];
}

void mir_frame_blend(MirFrame& out, const MirFrame& a, const MirFrame& b, double w) {
    out.hip_centre = (1.0 - w) * a.hip_centre + w * b.hip_centre;
    // The extremities first, in world directions (their parent frames are about to change; `out` may be `a`).
    std::array<Eigen::Vector3d, k_limb_count> extremity_world;
    for (int limb = 0; limb < k_limb_count; ++limb) {
        const int parent = limb_parent_part(b, limb);
        extremity_world[limb] = blend_reach(a.part_frames[parent] * a.extremity[limb], b.part_frames[parent] * b.extremity[limb], w);
    }
    for (int part = 0; part < k_body_part_count; ++part) {
        out.has_part[part] = b.has_part[part];
        out.part_frames[part] = is_trunk_part(part) ? a.part_frames[part].slerp(w, b.part_frames[part])
                                                    : limb_part_blend(a.part_frames[part], b.part_frames[part], w);
    }
    for (auto [to, from_a, from_b] : {std::tuple{&out.spine, &a.spine, &b.spine}, std::tuple{&out.neck, &a.neck, &b.neck}}) {
        to->count = from_b->count;
        for (int k = 0; k < from_b->count; ++k) {
            to->fractions[k] = from_b->fractions[k];
            to->frames[k] = chain_sample(*from_a, from_b->fractions[k]).slerp(w, from_b->frames[k]);
        }
    }
    for (int limb = 0; limb < k_limb_count; ++limb) {
        out.extremity[limb] = out.part_frames[limb_parent_part(out, limb)].conjugate() * extremity_world[limb];
        const double turn = std::remainder(b.swivel[limb] - a.swivel[limb], 2.0 * std::numbers::pi); // the short way round
        out.swivel[limb] = a.swivel[limb] + w * turn;
    }
    out.source_local_rotations.clear();
}

void mir_frame_offset(MirFrame& offset, const MirFrame& from, const MirFrame& to) {
    offset.hip_centre = from.hip_centre - to.hip_centre;
    for (int part = 0; part < k_body_part_count; ++part) {
        offset.has_part[part] = to.has_part[part];
        offset.part_frames[part] = from.part_frames[part] * to.part_frames[part].conjugate();
    }
    for (auto [out, a, b] : {std::tuple{&offset.spine, &from.spine, &to.spine}, std::tuple{&offset.neck, &from.neck, &to.neck}}) {
        out->count = b->count;
        for (int k = 0; k < b->count; ++k) {
            out->fractions[k] = b->fractions[k];
            out->frames[k] = chain_sample(*a, b->fractions[k]) * b->frames[k].conjugate();
        }
    }
    for (int limb = 0; limb < k_limb_count; ++limb) {
        offset.extremity[limb] = from.extremity[limb] - to.extremity[limb];
        offset.swivel[limb] = std::remainder(from.swivel[limb] - to.swivel[limb], 2.0 * std::numbers::pi);
    }
    offset.source_local_rotations.clear();
}

void mir_frame_add_offset(MirFrame& frame, const MirFrame& offset, double weight) {
    const Eigen::Quaterniond identity = Eigen::Quaterniond::Identity();
    frame.hip_centre += weight * offset.hip_centre;
    for (int part = 0; part < k_body_part_count; ++part) frame.part_frames[part] = identity.slerp(weight, offset.part_frames[part]) * frame.part_frames[part];
    for (auto [chain, delta] : {std::pair{&frame.spine, &offset.spine}, std::pair{&frame.neck, &offset.neck}}) {
        for (int k = 0; k < chain->count; ++k) chain->frames[k] = identity.slerp(weight, chain_sample(*delta, chain->fractions[k])) * chain->frames[k];
    }
    for (int limb = 0; limb < k_limb_count; ++limb) {
        frame.extremity[limb] += weight * offset.extremity[limb];
        frame.swivel[limb] += weight * offset.swivel[limb];
    }
}

void mir_frame_take_arms(MirFrame& frame, const MirFrame& from) {
    const int chest = int(BodyPart::chest);
    const Eigen::Quaterniond turn = (frame.part_frames[chest] * from.part_frames[chest].conjugate()).normalized();
    for (const Limb arm : {Limb::arm_l, Limb::arm_r}) {
        const int limb = int(arm);
        const BodyPart clavicle = arm == Limb::arm_l ? BodyPart::clavicle_l : BodyPart::clavicle_r;
        for (const BodyPart part : {clavicle, limb_parts(arm)[0], limb_parts(arm)[1], limb_parts(arm)[2]}) {
            if (from.has_part[int(part)]) frame.part_frames[int(part)] = (turn * from.part_frames[int(part)]).normalized();
        }
        frame.extremity[limb] = from.extremity[limb];
        frame.swivel[limb] = from.swivel[limb];
    }
}

void mir_frame_turn(MirFrame& frame, TrunkPivot pivot, const Eigen::Quaterniond& rotation, const Eigen::Vector3d& pivot_point,
                    double leg_length, double ankle_height) {
    switch (pivot) {
    case TrunkPivot::clavicle_l: turn_arm(frame, rotation, true); break;
    case TrunkPivot::clavicle_r: turn_arm(frame, rotation, false); break;
    case TrunkPivot::chest: turn_above_chest(frame, rotation); break;
    case TrunkPivot::spine_base:
        for (int k = 1; k + 1 < frame.spine.count; ++k) frame.spine.frames[k] = rotation * frame.spine.frames[k];
        turn_parts(frame, rotation, {BodyPart::spine});
        turn_above_chest(frame, rotation);
        break;
    case TrunkPivot::pelvis: {
        const Eigen::Vector3d hip(frame.hip_centre.x() * leg_length, ankle_height + frame.hip_centre.y() * leg_length,
                                  frame.hip_centre.z() * leg_length);
        const Eigen::Vector3d moved = pivot_point + rotation * (hip - pivot_point);
        frame.hip_centre = Eigen::Vector3d(moved.x() / leg_length, (moved.y() - ankle_height) / leg_length, moved.z() / leg_length);
        for (Eigen::Quaterniond& part : frame.part_frames) part = rotation * part;
        for (int k = 0; k < frame.spine.count; ++k) frame.spine.frames[k] = rotation * frame.spine.frames[k];
        for (int k = 0; k < frame.neck.count; ++k) frame.neck.frames[k] = rotation * frame.neck.frames[k];
        break;
    }
    }
}

} // namespace kumite
