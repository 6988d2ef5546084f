#pragma once
// The morphology-independent representation (MIR, after Kulpa, Multon & Arnaldi 2005) of one pose, and the
// encoder and decoder that move poses in and out of it. Decoding multiplies by the target skeleton's lengths and
// solves each limb analytically, so bone lengths are exactly the target's.
//
// - hip centre: x and z divided by the leg length (thigh + shin); y is its height above the standing ankle
//   height, divided by the leg length, so a straight standing leg lands the target's sole on the floor;
// - every body part and trunk-chain joint: its world anatomical frame (model rotation x rest frame, see
//   rest_anatomy.h), which means the same thing on any skeleton;
// - spine (pelvis..chest) and neck (chest..head) chains: frames at fractions of the chain's length, so chains with
//   different joint counts exchange them by interpolation;
// - limbs (shoulder->wrist, hip->ankle): the extremity relative to the limb root in the parent part's frame,
//   divided by the limb length, and the swivel angle of the elbow/knee around the root->extremity line;
// - other joints: their local rotations, applied to target joints of the same name.
//
// Encoder and decoder own their workspaces: encode() and decode() do not allocate.

#include "kumite/core/clip_mirror.h"
#include "kumite/core/rest_anatomy.h"

#include <span>
#include <string>

namespace kumite {

struct MirChainFrames {
    std::array<Eigen::Quaterniond, k_max_chain_joints> frames;
    std::array<double, k_max_chain_joints> fractions{};
    int count = 0;
};

struct MirFrame {
    Eigen::Vector3d hip_centre = Eigen::Vector3d::Zero();                // see above, dimensionless
    std::array<Eigen::Quaterniond, k_body_part_count> part_frames;       // world anatomical frames
    std::array<bool, k_body_part_count> has_part{};
    MirChainFrames spine;
    MirChainFrames neck;
    std::array<Eigen::Vector3d, k_limb_count> extremity;                 // in the parent part's frame / limb length
    std::array<double, k_limb_count> swivel{};                           // radians
    std::vector<Eigen::Quaterniond> source_local_rotations;              // [source joint], sized once
};

// World positions that override a limb's encoded extremity (foot locking), and a shift of the hip centre that
// lets pinned legs keep their encoded extension.
// A limb that is not pinned may instead have its encoded extremity moved by a world offset (the adaptation's
// d(t): the hit point driven towards the target).
struct LimbPins {
    std::array<bool, k_limb_count> pinned{};
    std::array<Eigen::Vector3d, k_limb_count> extremity_world;
    std::array<Eigen::Vector3d, k_limb_count> extremity_offset_world{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                                                                     Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    Eigen::Vector3d hip_shift_world = Eigen::Vector3d::Zero(); // metres
};

class MirEncoder {
public:
    MirEncoder(const Skeleton& skeleton, const RestAnatomy& anatomy);

    // `frame` is sized on first use and reused. Also leaves the pose's model transforms in model_positions().
    void encode(MirFrame& frame, const PoseView& pose);

    std::span<const Eigen::Vector3d> model_positions() const { return m_positions; }

private:
    const Skeleton& m_skeleton;
    const RestAnatomy& m_anatomy;
    std::vector<Eigen::Vector3d> m_positions;
    std::vector<Eigen::Quaterniond> m_rotations;
};

class MirDecoder {
public:
    // `source_joint_names` names the joints of MirFrame::source_local_rotations.
    MirDecoder(const Skeleton& skeleton, const RestAnatomy& anatomy, std::span<const std::string> source_joint_names);

    // Writes the pose on the target skeleton: root translation, local rotations and, when the pelvis is not the
    // root, local translations. A foot that would pass below the floor (y = 0) is pitched about its ankle until
    // its lowest point touches it. Joints the MIR has no part for take the source's local rotation when it has a
    // joint of their name, else the anatomy's fist for fingers (fist_pose.h) and identity for the rest. `pose` is
    // sized on first use and reused.
    void decode(Pose& pose, const MirFrame& frame, const LimbPins& pins = {});

    // Model transforms of the last decoded pose.
    std::span<const Eigen::Vector3d> model_positions() const { return m_positions; }
    // Where each limb's extremity was asked to go in the last decode (pinned, or encoded plus offset), before the
    // limb's reach and the floor clamped it.
    std::span<const Eigen::Vector3d> limb_targets() const { return m_limb_targets; }
    std::span<const Eigen::Quaterniond> model_rotations() const { return m_rotations; }

private:
    enum class Role : std::uint8_t { above_pelvis, pelvis, spine, neck, part, limb_root, limb_inner, other };
    void solve_limb(int limb, const MirFrame& frame, const LimbPins& pins);
    void keep_feet_above_floor();

    const Skeleton& m_skeleton;
    const RestAnatomy& m_anatomy;
    std::vector<Role> m_roles;               // [joint]
    std::vector<int> m_source_joint;         // [joint] same-name source joint, or -1
    std::vector<int> m_limb_of_root;         // [joint] limb index when the joint is a limb root, else -1
    std::vector<int> m_part_of;              // [joint] BodyPart index, or -1
    std::vector<int> m_chain_index;          // [joint] index in its trunk chain (spine/neck roles)
    std::vector<Eigen::Quaterniond> m_rest_frames_inverse; // [joint] conjugated anatomical rest frames
    std::vector<Eigen::Quaterniond> m_undriven_local_rotations; // [joint] what a joint no source drives gets: fingers a fist
    std::vector<Eigen::Vector3d> m_positions;
    std::vector<Eigen::Quaterniond> m_rotations;
    std::vector<bool> m_solved;              // [joint] rotation set by a limb solve
    std::array<std::vector<int>, 2> m_foot_joints;     // [foot] the ankle and the joints below it
    std::array<std::vector<int>, 2> m_foot_end_sites;  // [foot] End Sites below the ankle
    std::array<Eigen::Vector3d, k_limb_count> m_limb_targets;
};

// The MIR of the mirrored pose (see clip_mirror.h): parts and limbs trade sides, world quantities are reflected,
// swivels change sign. Encoding a mirrored clip gives the mirror of its encoding; `out` is sized on first use.
// `parents` are the source skeleton's (for its local rotations).
void mir_frame_mirror(MirFrame& out, const MirFrame& frame, const MirrorSymmetry& symmetry, std::span<const int> parents);

// The swivel angle of `middle` around the line root->extremity, measured from `reference` projected on the
// plane normal to that line; positive counter-clockwise looking down the line. Shared by encoder and decoder.
double limb_swivel(const Eigen::Vector3d& root, const Eigen::Vector3d& middle, const Eigen::Vector3d& extremity,
                   const Eigen::Vector3d& reference);

// The reference direction for a limb's swivel: down from the chest for arms, forward from the pelvis for legs.
Eigen::Vector3d limb_swivel_reference(const MirFrame& frame, int limb);

// Whether a body part's MIR frame is a trunk frame (pelvis to head: its lateral axis is the one a mirror reverses)
// rather than a limb frame (the bone as its y axis, its turn about the bone a convention of the skeleton).
inline bool is_trunk_part(int part) { return part <= static_cast<int>(BodyPart::head); }

} // namespace kumite
