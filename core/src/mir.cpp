#include "kumite/core/mir.h"

#include "kumite/core/forward_kinematics.h"
#include "kumite/core/two_bone_ik.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace kumite {
namespace {

Eigen::Quaterniond chain_frame_at(const MirChainFrames& chain, double fraction) {
    if (chain.count == 0) return Eigen::Quaterniond::Identity();
    if (fraction <= chain.fractions[0]) return chain.frames[0];
    for (int k = 1; k < chain.count; ++k) {
        if (fraction <= chain.fractions[k]) {
            const double span = chain.fractions[k] - chain.fractions[k - 1];
            const double t = span > 1e-12 ? (fraction - chain.fractions[k - 1]) / span : 1.0;
            return chain.frames[k - 1].slerp(t, chain.frames[k]);
        }
    }
    return chain.frames[chain.count - 1];
}

void encode_chain(MirChainFrames& out, const TrunkChain& chain, std::span<const Eigen::Quaterniond> rotations,
                  const RestAnatomy& anatomy) {
    out.count = chain.count;
    for (int k = 0; k < chain.count; ++k) {
        out.frames[k] = rotations[chain.joints[k]] * anatomy.rest_frames[chain.joints[k]];
        out.fractions[k] = chain.fractions[k];
    }
}

} // namespace

double limb_swivel(const Eigen::Vector3d& root, const Eigen::Vector3d& middle, const Eigen::Vector3d& extremity,
                   const Eigen::Vector3d& reference) {
    const Eigen::Vector3d line = extremity - root;
    if (line.norm() < 1e-12) return 0.0;
    const Eigen::Vector3d axis = line.normalized();
    const Eigen::Vector3d zero_swivel = orthogonal_reference(axis, reference);
    const Eigen::Vector3d bend = (middle - root) - (middle - root).dot(axis) * axis;
    if (bend.norm() < 1e-9) return 0.0; // a straight limb has no swivel
    return std::atan2(zero_swivel.cross(bend).dot(axis), zero_swivel.dot(bend));
}

Eigen::Vector3d limb_swivel_reference(const MirFrame& frame, int limb) {
    if (limb < 2) return -(frame.part_frames[static_cast<int>(BodyPart::chest)] * Eigen::Vector3d::UnitY());
    return frame.part_frames[static_cast<int>(BodyPart::pelvis)] * Eigen::Vector3d::UnitZ();
}

namespace {

// Mirror of a world anatomical frame: M G D, with D flipping the axis that mirroring reverses in the rest frame
// (the lateral axis of a trunk frame, the third axis of a limb frame).
Eigen::Quaterniond mirror_frame(const Eigen::Quaterniond& frame, const Eigen::Matrix3d& reflection, bool trunk) {
    const Eigen::Vector3d flip = trunk ? Eigen::Vector3d(-1, 1, 1) : Eigen::Vector3d(1, 1, -1);
    return Eigen::Quaterniond(Eigen::Matrix3d(reflection * frame.toRotationMatrix() * flip.asDiagonal())).normalized();
}

int mirrored_limb(int limb) { return limb ^ 1; } // arm_l <-> arm_r, leg_l <-> leg_r

} // namespace

void mir_frame_mirror(MirFrame& out, const MirFrame& frame, const MirrorSymmetry& symmetry, std::span<const int> parents) {
    const Eigen::Matrix3d& m = symmetry.reflection;
    out.hip_centre = m * frame.hip_centre; // the reflection keeps y: it only mixes the horizontal axes
    for (int part = 0; part < k_body_part_count; ++part) {
        const int source = static_cast<int>(body_part_mirrored(static_cast<BodyPart>(part)));
        out.has_part[part] = frame.has_part[source];
        out.part_frames[part] = mirror_frame(frame.part_frames[source], m, is_trunk_part(part));
    }
    for (auto [to, from] : {std::pair{&out.spine, &frame.spine}, std::pair{&out.neck, &frame.neck}}) {
        to->count = from->count;
        for (int k = 0; k < from->count; ++k) {
            to->frames[k] = mirror_frame(from->frames[k], m, true);
            to->fractions[k] = from->fractions[k];
        }
    }
    for (int limb = 0; limb < k_limb_count; ++limb) {
        const int source = mirrored_limb(limb);
        // The extremity is expressed in the parent part's frame, whose flipped axis is known from its kind.
        const bool parent_is_trunk = limb >= 2 || !frame.has_part[static_cast<int>(limb == 0 ? BodyPart::clavicle_r : BodyPart::clavicle_l)];
        Eigen::Vector3d extremity = frame.extremity[source];
        if (parent_is_trunk) extremity.x() = -extremity.x();
        else extremity.z() = -extremity.z();
        out.extremity[limb] = extremity;
        out.swivel[limb] = -frame.swivel[source];
    }
    out.source_local_rotations.resize(frame.source_local_rotations.size());
    for (size_t joint = 0; joint < frame.source_local_rotations.size(); ++joint) {
        out.source_local_rotations[joint] = symmetry.mirror_local_rotation(
            static_cast<int>(joint), frame.source_local_rotations[symmetry.partner[joint]], parents[joint]);
    }
}

MirEncoder::MirEncoder(const Skeleton& skeleton, const RestAnatomy& anatomy)
    : m_skeleton(skeleton), m_anatomy(anatomy), m_positions(skeleton.joint_count()), m_rotations(skeleton.joint_count()) {}

void MirEncoder::encode(MirFrame& frame, const PoseView& pose) {
    forward_kinematics(m_positions, m_rotations, m_skeleton, pose);
    const BodyMap& map = m_anatomy.body_map;

    for (int part = 0; part < k_body_part_count; ++part) {
        const int joint = map.joints[part];
        frame.has_part[part] = joint >= 0 && m_anatomy.has_frame[joint];
        frame.part_frames[part] = frame.has_part[part] ? Eigen::Quaterniond(m_rotations[joint] * m_anatomy.rest_frames[joint])
                                                       : Eigen::Quaterniond::Identity();
    }
    encode_chain(frame.spine, m_anatomy.spine, m_rotations, m_anatomy);
    encode_chain(frame.neck, m_anatomy.neck, m_rotations, m_anatomy);

    const int pelvis = map.joint(BodyPart::pelvis);
    const Eigen::Vector3d hip_centre = m_positions[pelvis] + m_rotations[pelvis] * m_anatomy.hip_centre_in_pelvis;
    const double leg = m_anatomy.leg_length;
    frame.hip_centre = Eigen::Vector3d(hip_centre.x() / leg, (hip_centre.y() - m_anatomy.floor_y - m_anatomy.ankle_height) / leg,
                                       hip_centre.z() / leg);

    for (int limb = 0; limb < k_limb_count; ++limb) {
        const LimbChain& chain = m_anatomy.limbs[limb];
        const Eigen::Vector3d& root = m_positions[chain.root];
        const Eigen::Vector3d& extremity = m_positions[chain.extremity];
        frame.extremity[limb] = frame.part_frames[chain.parent_part].conjugate() * (extremity - root) / chain.length();
        frame.swivel[limb] = limb_swivel(root, m_positions[chain.middle], extremity, limb_swivel_reference(frame, limb));
    }
    frame.source_local_rotations.assign(pose.local_rotations.begin(), pose.local_rotations.end());
}

MirDecoder::MirDecoder(const Skeleton& skeleton, const RestAnatomy& anatomy, std::span<const std::string> source_joint_names)
    : m_skeleton(skeleton), m_anatomy(anatomy) {
    const int joints = skeleton.joint_count();
    const BodyMap& map = anatomy.body_map;
    m_roles.assign(joints, Role::other);
    m_source_joint.assign(joints, -1);
    m_limb_of_root.assign(joints, -1);
    m_part_of.assign(joints, -1);
    m_positions.resize(joints);
    m_rotations.resize(joints);
    m_solved.assign(joints, false);

    for (int joint = 0; joint < joints; ++joint) {
        for (size_t source = 0; source < source_joint_names.size(); ++source) {
            if (source_joint_names[source] == skeleton.names[joint]) m_source_joint[joint] = static_cast<int>(source);
        }
        if (const std::optional<BodyPart> part = map.part_of(joint)) m_part_of[joint] = static_cast<int>(*part);
    }
    const int pelvis = map.joint(BodyPart::pelvis);
    for (int joint = skeleton.parents[pelvis]; joint >= 0; joint = skeleton.parents[joint]) m_roles[joint] = Role::above_pelvis;
    m_roles[pelvis] = Role::pelvis;
    m_chain_index.assign(joints, 0);
    m_rest_frames_inverse.resize(joints);
    for (int joint = 0; joint < joints; ++joint) m_rest_frames_inverse[joint] = anatomy.rest_frames[joint].conjugate();
    // Captures carry no fingers: the body's fingers close into fists rather than hold their bind pose's open hands.
    if (anatomy.fist_local_rotations.size() == std::size_t(joints)) m_undriven_local_rotations = anatomy.fist_local_rotations;
    else m_undriven_local_rotations.assign(joints, Eigen::Quaterniond::Identity());
    for (int k = 1; k + 1 < anatomy.spine.count; ++k) {
        m_roles[anatomy.spine.joints[k]] = Role::spine;
        m_chain_index[anatomy.spine.joints[k]] = k;
    }
    for (int k = 1; k + 1 < anatomy.neck.count; ++k) {
        m_roles[anatomy.neck.joints[k]] = Role::neck;
        m_chain_index[anatomy.neck.joints[k]] = k;
    }
    for (int joint = 0; joint < joints; ++joint) {
        if (m_roles[joint] == Role::other && m_part_of[joint] >= 0 && anatomy.has_frame[joint]) m_roles[joint] = Role::part;
    }
    for (int foot = 0; foot < 2; ++foot) {
        const int ankle = anatomy.limbs[2 + foot].extremity;
        for (int joint = ankle; joint < joints; ++joint) {
            if (skeleton.is_ancestor(ankle, joint)) m_foot_joints[foot].push_back(joint);
        }
        for (size_t i = 0; i < skeleton.end_sites.size(); ++i) {
            if (skeleton.is_ancestor(ankle, skeleton.end_sites[i].joint)) m_foot_end_sites[foot].push_back(static_cast<int>(i));
        }
    }
    for (int limb = 0; limb < k_limb_count; ++limb) {
        const LimbChain& chain = anatomy.limbs[limb];
        m_roles[chain.root] = Role::limb_root;
        m_limb_of_root[chain.root] = limb;
        for (int joint = chain.extremity; joint != chain.root; joint = skeleton.parents[joint]) m_roles[joint] = Role::limb_inner;
    }
}

void MirDecoder::solve_limb(int limb, const MirFrame& frame, const LimbPins& pins) {
    const LimbChain& chain = m_anatomy.limbs[limb];
    const auto parts = limb_parts(static_cast<Limb>(limb));
    const Eigen::Vector3d& root = m_positions[chain.root];
    Eigen::Vector3d target = pins.pinned[limb] ? pins.extremity_world[limb]
                                               : Eigen::Vector3d(root + frame.part_frames[chain.parent_part] * frame.extremity[limb] * chain.length() +
                                                                 pins.extremity_offset_world[limb]);
    m_limb_targets[limb] = target;
    // An ankle kept at least half its standing height above the floor leaves room to pitch the foot onto it.
    if (limb >= 2) target.y() = std::max(target.y(), 0.5 * m_anatomy.ankle_height);
    const TwoBoneSolution solution = two_bone_ik(root, target, chain.upper_length, chain.lower_length, frame.swivel[limb],
                                                 limb_swivel_reference(frame, limb));

    // Start from the transferred anatomical frames (they carry the source's twist), then turn each bone onto
    // the solved direction by the smallest rotation.
    auto transferred = [&](BodyPart part, int joint) {
        return Eigen::Quaterniond(frame.part_frames[static_cast<int>(part)] * m_rest_frames_inverse[joint]);
    };
    const Eigen::Quaterniond upper_initial = transferred(parts[0], chain.root);
    const Eigen::Quaterniond lower_initial = transferred(parts[1], chain.middle);
    m_rotations[chain.root] = rotation_between(upper_initial * chain.upper_rest_vector, solution.middle - root) * upper_initial;
    m_rotations[chain.middle] =
        rotation_between(lower_initial * chain.lower_rest_vector, solution.extremity - solution.middle) * lower_initial;
    m_rotations[chain.extremity] = transferred(parts[2], chain.extremity);
    m_solved[chain.middle] = true;
    m_solved[chain.extremity] = true;
}

void MirDecoder::keep_feet_above_floor() {
    for (int foot = 0; foot < 2; ++foot) {
        const Eigen::Vector3d ankle = m_positions[m_foot_joints[foot].front()];
        for (int pass = 0; pass < 2; ++pass) {
            Eigen::Vector3d lowest = ankle;
            for (int joint : m_foot_joints[foot]) {
                if (m_positions[joint].y() < lowest.y()) lowest = m_positions[joint];
            }
            for (int end_site : m_foot_end_sites[foot]) {
                const EndSite& site = m_skeleton.end_sites[end_site];
                const Eigen::Vector3d point = m_positions[site.joint] + m_rotations[site.joint] * site.offset_in_joint;
                if (point.y() < lowest.y()) lowest = point;
            }
            const Eigen::Vector3d reach = lowest - ankle;
            const Eigen::Vector3d horizontal(reach.x(), 0.0, reach.z());
            if (lowest.y() >= 0.0 || ankle.y() <= 0.0 || horizontal.norm() < 1e-6) break;
            // Raise the lowest point onto the floor by turning the foot in the vertical plane through it.
            const double elevation = std::atan2(reach.y(), horizontal.norm());
            const double wanted = std::asin(std::clamp(-ankle.y() / reach.norm(), -1.0, 1.0));
            const Eigen::Quaterniond lift(Eigen::AngleAxisd(wanted - elevation, horizontal.cross(Eigen::Vector3d::UnitY()).normalized()));
            for (int joint : m_foot_joints[foot]) {
                m_rotations[joint] = lift * m_rotations[joint];
                m_positions[joint] = ankle + lift * (m_positions[joint] - ankle);
            }
        }
    }
}

void MirDecoder::decode(Pose& pose, const MirFrame& frame, const LimbPins& pins) {
    const Skeleton& skeleton = m_skeleton;
    const int joints = skeleton.joint_count();
    std::fill(m_solved.begin(), m_solved.end(), false);
    const double leg = m_anatomy.leg_length;

    for (int joint = 0; joint < joints; ++joint) {
        const int parent = skeleton.parents[joint];
        const Eigen::Quaterniond parent_rotation = parent >= 0 ? m_rotations[parent] : Eigen::Quaterniond::Identity();
        const Eigen::Vector3d parent_position = parent >= 0 ? m_positions[parent] : Eigen::Vector3d::Zero();
        Eigen::Vector3d position = parent_position + parent_rotation * skeleton.rest_offsets[joint];
        switch (m_roles[joint]) {
        case Role::above_pelvis: m_rotations[joint] = parent_rotation; break;
        case Role::pelvis: {
            m_rotations[joint] = frame.part_frames[static_cast<int>(BodyPart::pelvis)] * m_rest_frames_inverse[joint];
            // The target stands on y = 0.
            const Eigen::Vector3d hip_centre = Eigen::Vector3d(frame.hip_centre.x() * leg, m_anatomy.ankle_height + frame.hip_centre.y() * leg,
                                                               frame.hip_centre.z() * leg) + pins.hip_shift_world;
            position = hip_centre - m_rotations[joint] * m_anatomy.hip_centre_in_pelvis;
            break;
        }
        case Role::spine:
        case Role::neck: {
            const TrunkChain& chain = m_roles[joint] == Role::spine ? m_anatomy.spine : m_anatomy.neck;
            const int index = m_chain_index[joint];
            const double fraction = chain.fractions[index];
            const MirChainFrames& frames = m_roles[joint] == Role::spine ? frame.spine : frame.neck;
            // Chains of the same length pair joint for joint (zero-length links make fractions tie); others
            // interpolate by fraction of the chain's length.
            const Eigen::Quaterniond chain_frame = frames.count == chain.count ? frames.frames[index]
                                                                             : chain_frame_at(frames, fraction);
            m_rotations[joint] = chain_frame * m_rest_frames_inverse[joint];
            break;
        }
        case Role::part:
            m_rotations[joint] = frame.part_frames[m_part_of[joint]] * m_rest_frames_inverse[joint];
            break;
        case Role::limb_root:
            m_positions[joint] = position;
            solve_limb(m_limb_of_root[joint], frame, pins);
            break;
        case Role::limb_inner:
            if (!m_solved[joint]) m_rotations[joint] = parent_rotation; // helpers between limb joints stay straight
            break;
        case Role::other: {
            const int source = m_source_joint[joint];
            const bool known = source >= 0 && source < static_cast<int>(frame.source_local_rotations.size());
            m_rotations[joint] = parent_rotation * (known ? frame.source_local_rotations[source] : m_undriven_local_rotations[joint]);
            break;
        }
        }
        m_positions[joint] = position;
    }

    keep_feet_above_floor();

    // Back to local rotations; the pelvis gets a local translation when joints sit above it.
    pose.local_rotations.resize(joints);
    for (int joint = 0; joint < joints; ++joint) {
        const int parent = skeleton.parents[joint];
        pose.local_rotations[joint] = parent >= 0 ? (m_rotations[parent].conjugate() * m_rotations[joint]).normalized()
                                                  : m_rotations[joint].normalized();
    }
    pose.root_translation = m_positions[0];
    const int pelvis = m_anatomy.body_map.joint(BodyPart::pelvis);
    const int pelvis_parent = skeleton.parents[pelvis];
    if (pelvis_parent >= 0) {
        pose.local_translations.assign(skeleton.rest_offsets.begin(), skeleton.rest_offsets.end());
        pose.local_translations[pelvis] = m_rotations[pelvis_parent].conjugate() * (m_positions[pelvis] - m_positions[pelvis_parent]);
    } else {
        pose.local_translations.clear();
    }
}

} // namespace kumite
