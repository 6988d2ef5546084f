#pragma once
// RestAnatomy: what the morphology-independent representation needs to know about one skeleton, computed once
// from its rest pose (identity rotations) and body map: anatomical frames per part, limb and leg lengths, the
// trunk chains, the hip centre and the ankle height; and the fingers' fist, which the decoder gives fingers no
// capture drives.
//
// An anatomical frame is a rotation whose columns are axes of a body part in the rest pose: for the pelvis the
// hips' trunk frame [left, up, forward] (left from the right hip to the left one); for the spine and neck chains
// and the head the shoulders' trunk frame (left from shoulder to shoulder); for a limb part its bone direction as
// the second column with its region's forward (arms, legs) or up (feet, toes) made orthogonal to it as the first.
// Because they are defined from positions, two skeletons with different rest conventions (Bandai's bones along +X,
// a T-pose) agree on them, so `model_rotation * rest_frame` transfers between skeletons.

#include "kumite/core/body_map.h"
#include "kumite/core/clip.h"
#include "kumite/core/result.h"

#include <array>
#include <vector>

namespace kumite {

inline constexpr int k_max_chain_joints = 12;

enum class Limb : int { arm_l, arm_r, leg_l, leg_r };
inline constexpr int k_limb_count = 4;

struct LimbChain {
    int root = -1;        // shoulder (upper_arm) or hip (thigh) joint
    int middle = -1;      // elbow (forearm) or knee (shin)
    int extremity = -1;   // wrist (hand) or ankle (foot)
    int parent_part = -1; // the BodyPart whose frame expresses the extremity: clavicle or chest, pelvis
    double upper_length = 0.0; // metres, root -> middle
    double lower_length = 0.0; // metres, middle -> extremity
    Eigen::Vector3d upper_rest_vector = Eigen::Vector3d::Zero(); // root -> middle in the root's frame (rest)
    Eigen::Vector3d lower_rest_vector = Eigen::Vector3d::Zero(); // middle -> extremity in the middle's frame
    double length() const { return upper_length + lower_length; }
};

// A trunk chain from `first` up to `last` (both ends included), with the fraction of the chain's rest length
// at which each joint sits (0 at first, 1 at last).
struct TrunkChain {
    std::array<int, k_max_chain_joints> joints{};
    std::array<double, k_max_chain_joints> fractions{};
    int count = 0;
};

struct RestAnatomy {
    BodyMap body_map;
    std::vector<Eigen::Vector3d> rest_positions;                 // [joint] model positions, identity rotations
    std::vector<Eigen::Quaterniond> rest_frames;                 // [joint] anatomical frame (identity if none)
    std::vector<bool> has_frame;                                 // [joint] true for mapped parts and trunk chains
    std::vector<Eigen::Quaterniond> fist_local_rotations;        // [joint] fingers closed (fist_pose.h), identity elsewhere
    std::array<LimbChain, k_limb_count> limbs;
    TrunkChain spine;                                            // pelvis .. chest
    TrunkChain neck;                                             // chest .. head
    Eigen::Matrix3d trunk_frame = Eigen::Matrix3d::Identity();   // [left, up, forward] of the hips, rest pose
    Eigen::Matrix3d shoulders_frame = Eigen::Matrix3d::Identity(); // [left, up, forward] of the shoulders
    double leg_length = 0.0;                                     // metres, mean thigh + shin of both legs
    double floor_y = 0.0;                                        // metres, the floor of the clip's frames
    double ankle_height = 0.0;                                   // metres, flat-footed ankle above that floor
    Eigen::Vector3d hip_centre_in_pelvis = Eigen::Vector3d::Zero(); // rest, pelvis frame (identity at rest)
};

// Needs pelvis, chest, head, both upper arms, forearms, hands, thighs, shins and feet in the body map.
// `clip` supplies frames for the ankle height when the rest pose is not upright (may have no frames otherwise).
Result<RestAnatomy> rest_anatomy_build(const Clip& clip, const BodyMap& body_map);

// The part chain that a limb's joints belong to, for naming: arm_l -> upper_arm_l, forearm_l, hand_l.
std::array<BodyPart, 3> limb_parts(Limb limb);

} // namespace kumite
