#include "kumite/core/rest_anatomy.h"

#include "kumite/core/fist_pose.h"
#include "kumite/core/forward_kinematics.h"
#include "kumite/core/standing_height.h"

#include <string>

namespace kumite {
namespace {

// A right-handed frame whose column `exact_column` (0 or 1) points along `exact` and whose other column of the
// first two is `other` made orthogonal to it; the third is the cross product of the first two.
Eigen::Matrix3d frame_with(int exact_column, const Eigen::Vector3d& exact, const Eigen::Vector3d& other) {
    const Eigen::Vector3d e = exact.normalized();
    const Eigen::Vector3d o = (other - other.dot(e) * e).normalized();
    Eigen::Matrix3d frame;
    frame.col(exact_column) = e;
    frame.col(1 - exact_column) = o;
    frame.col(2) = frame.col(0).cross(frame.col(1));
    return frame;
}

// Limb frame: the bone as second column, `secondary` (or `fallback` when nearly parallel) as the first.
Eigen::Matrix3d frame_from(const Eigen::Vector3d& bone, const Eigen::Vector3d& secondary, const Eigen::Vector3d& fallback) {
    const bool parallel = std::abs(bone.normalized().dot(secondary.normalized())) >= 0.95;
    return frame_with(1, bone, parallel ? fallback : secondary);
}

// Rest-pose vector from a joint to one of its descendants (identity rotations: offsets add up).
Eigen::Vector3d rest_vector(const std::vector<Eigen::Vector3d>& rest_positions, int from, int to) {
    return rest_positions[to] - rest_positions[from];
}

// The direction a joint's bone points in the rest pose: to `next` when given, else to its first child or End Site
// with a length, else `fallback`.
Eigen::Vector3d bone_direction(const Skeleton& skeleton, const std::vector<Eigen::Vector3d>& rest_positions, int joint,
                               int next, const Eigen::Vector3d& fallback) {
    if (next >= 0) {
        const Eigen::Vector3d v = rest_vector(rest_positions, joint, next);
        if (v.norm() > 1e-6) return v;
    }
    for (int child = joint + 1; child < skeleton.joint_count(); ++child) {
        if (skeleton.parents[child] == joint && skeleton.rest_offsets[child].norm() > 1e-6) return skeleton.rest_offsets[child];
    }
    for (const EndSite& end_site : skeleton.end_sites) {
        if (end_site.joint == joint && end_site.offset_in_joint.norm() > 1e-6) return end_site.offset_in_joint;
    }
    return fallback;
}

TrunkChain trunk_chain(const Skeleton& skeleton, const std::vector<Eigen::Vector3d>& rest_positions, int first, int last) {
    std::vector<int> reversed;
    for (int joint = last; joint >= 0 && joint != first; joint = skeleton.parents[joint]) reversed.push_back(joint);
    reversed.push_back(first);
    TrunkChain chain;
    // Long chains keep their ends and the joints nearest them; the middle ones are interpolated on decode.
    const int count = std::min<int>(static_cast<int>(reversed.size()), k_max_chain_joints);
    double total = 0.0;
    std::vector<double> cumulative(reversed.size(), 0.0);
    for (size_t i = reversed.size() - 1; i > 0; --i) {
        total += rest_vector(rest_positions, reversed[i], reversed[i - 1]).norm();
        cumulative[i - 1] = total;
    }
    for (int k = 0; k < count; ++k) {
        const size_t i = reversed.size() - 1 - static_cast<size_t>(k * (reversed.size() - 1) / std::max(1, count - 1));
        chain.joints[k] = reversed[i];
        chain.fractions[k] = total > 0.0 ? cumulative[i] / total : double(k) / std::max(1, count - 1);
    }
    chain.count = count;
    return chain;
}

} // namespace

std::array<BodyPart, 3> limb_parts(Limb limb) {
    switch (limb) {
    case Limb::arm_l: return {BodyPart::upper_arm_l, BodyPart::forearm_l, BodyPart::hand_l};
    case Limb::arm_r: return {BodyPart::upper_arm_r, BodyPart::forearm_r, BodyPart::hand_r};
    case Limb::leg_l: return {BodyPart::thigh_l, BodyPart::shin_l, BodyPart::foot_l};
    case Limb::leg_r: return {BodyPart::thigh_r, BodyPart::shin_r, BodyPart::foot_r};
    }
    return {};
}

Result<RestAnatomy> rest_anatomy_build(const Clip& clip, const BodyMap& map) {
    const Skeleton& skeleton = clip.skeleton;
    for (BodyPart part : {BodyPart::pelvis, BodyPart::chest, BodyPart::head, BodyPart::upper_arm_l, BodyPart::forearm_l,
                          BodyPart::hand_l, BodyPart::upper_arm_r, BodyPart::forearm_r, BodyPart::hand_r, BodyPart::thigh_l,
                          BodyPart::shin_l, BodyPart::foot_l, BodyPart::thigh_r, BodyPart::shin_r, BodyPart::foot_r}) {
        if (!map.has(part)) {
            return make_error(ErrorCode::invalid, "the body map has no " + std::string(body_part_name(part)) +
                                                      "; retargeting needs the trunk, both arms and both legs (add a body map override)");
        }
    }
    RestAnatomy anatomy;
    anatomy.body_map = map;
    const int joints = skeleton.joint_count();
    anatomy.rest_positions.resize(joints);
    std::vector<Eigen::Quaterniond> rest_rotations(joints);
    const Pose rest = clip.rest_pose();
    forward_kinematics(anatomy.rest_positions, rest_rotations, skeleton, rest.view());
    const std::vector<Eigen::Vector3d>& p = anatomy.rest_positions;
    auto at = [&](BodyPart part) { return p[map.joint(part)]; };

    // Trunk frames, one per body region, from the joints right at the branch: rest poses need not be physical
    // (Bandai's puts the hips' left-right axis along Y, the chest's along Z and each arm along X), so only the
    // offsets next to a joint say how its own axes sit. Left runs between the first joints of the two side
    // chains below the branch (the next pair when those coincide), up from the branch along the trunk; left is
    // kept exact and up made orthogonal to it, so the frame mirrors onto itself.
    auto side_axis = [&](int branch, int left_end, int right_end) {
        std::vector<int> left_chain, right_chain; // branch's descendants toward each end, nearest first
        for (int j = left_end; j >= 0 && j != branch; j = skeleton.parents[j]) left_chain.insert(left_chain.begin(), j);
        for (int j = right_end; j >= 0 && j != branch; j = skeleton.parents[j]) right_chain.insert(right_chain.begin(), j);
        for (size_t k = 0; k < std::min(left_chain.size(), right_chain.size()); ++k) {
            const Eigen::Vector3d across = p[left_chain[k]] - p[right_chain[k]];
            if (across.norm() > 0.01) return Eigen::Vector3d(across);
        }
        return Eigen::Vector3d(p[left_end] - p[right_end]);
    };
    auto trunk_direction = [&](int from, int toward) {
        int next = toward;
        for (int j = toward; j >= 0 && j != from; j = skeleton.parents[j]) {
            if ((p[j] - p[from]).norm() > 0.01) next = j; // the nearest joint along the way that is not on top of `from`
        }
        return Eigen::Vector3d(p[next] - p[from]);
    };
    auto trunk_frame_from = [](const Eigen::Vector3d& left, const Eigen::Vector3d& up) { return frame_with(0, left, up); };
    const int pelvis = map.joint(BodyPart::pelvis), chest = map.joint(BodyPart::chest), head = map.joint(BodyPart::head);
    const Eigen::Matrix3d hips_frame =
        trunk_frame_from(side_axis(pelvis, map.joint(BodyPart::thigh_l), map.joint(BodyPart::thigh_r)), trunk_direction(pelvis, chest));
    const Eigen::Matrix3d shoulders_frame =
        trunk_frame_from(side_axis(chest, map.joint(BodyPart::upper_arm_l), map.joint(BodyPart::upper_arm_r)), trunk_direction(chest, head));
    anatomy.trunk_frame = hips_frame;
    anatomy.shoulders_frame = shoulders_frame;
    anatomy.rest_frames.assign(joints, Eigen::Quaterniond::Identity());
    anatomy.has_frame.assign(joints, false);
    auto set_frame = [&](int joint, const Eigen::Matrix3d& frame) {
        anatomy.rest_frames[joint] = Eigen::Quaterniond(frame).normalized();
        anatomy.has_frame[joint] = true;
    };

    anatomy.spine = trunk_chain(skeleton, p, map.joint(BodyPart::pelvis), map.joint(BodyPart::chest));
    anatomy.neck = trunk_chain(skeleton, p, map.joint(BodyPart::chest), map.joint(BodyPart::head));
    for (const TrunkChain* chain : {&anatomy.spine, &anatomy.neck}) {
        for (int k = 0; k < chain->count; ++k) set_frame(chain->joints[k], shoulders_frame);
    }
    set_frame(map.joint(BodyPart::pelvis), hips_frame);

    // Limb parts: bone direction to the next part, secondary forward (arms, legs) or up (feet, toes).
    struct LimbPart { BodyPart part; BodyPart next; bool foot_like; };
    for (const LimbPart& limb_part : {LimbPart{BodyPart::clavicle_l, BodyPart::upper_arm_l, false},
                                      LimbPart{BodyPart::upper_arm_l, BodyPart::forearm_l, false},
                                      LimbPart{BodyPart::forearm_l, BodyPart::hand_l, false},
                                      LimbPart{BodyPart::hand_l, BodyPart::hand_l, false},
                                      LimbPart{BodyPart::clavicle_r, BodyPart::upper_arm_r, false},
                                      LimbPart{BodyPart::upper_arm_r, BodyPart::forearm_r, false},
                                      LimbPart{BodyPart::forearm_r, BodyPart::hand_r, false},
                                      LimbPart{BodyPart::hand_r, BodyPart::hand_r, false},
                                      LimbPart{BodyPart::thigh_l, BodyPart::shin_l, false},
                                      LimbPart{BodyPart::shin_l, BodyPart::foot_l, false},
                                      LimbPart{BodyPart::foot_l, BodyPart::toe_l, true},
                                      LimbPart{BodyPart::toe_l, BodyPart::toe_l, true},
                                      LimbPart{BodyPart::thigh_r, BodyPart::shin_r, false},
                                      LimbPart{BodyPart::shin_r, BodyPart::foot_r, false},
                                      LimbPart{BodyPart::foot_r, BodyPart::toe_r, true},
                                      LimbPart{BodyPart::toe_r, BodyPart::toe_r, true}}) {
        const int joint = map.joint(limb_part.part);
        if (joint < 0) continue;
        const int next = limb_part.next == limb_part.part ? -1 : map.joint(limb_part.next);
        // A hand or toe without children continues its parent's bone; a foot without toes points forward.
        const int parent = skeleton.parents[joint];
        const Eigen::Matrix3d& region = limb_part.part >= BodyPart::thigh_l ? hips_frame : shoulders_frame;
        const Eigen::Vector3d up = region.col(1), forward = region.col(2);
        const Eigen::Vector3d fallback = limb_part.foot_like && limb_part.part != BodyPart::toe_l && limb_part.part != BodyPart::toe_r
                                             ? forward
                                             : (parent >= 0 ? p[joint] - p[parent] : up);
        const Eigen::Vector3d bone = bone_direction(skeleton, p, joint, next, fallback);
        set_frame(joint, limb_part.foot_like ? frame_from(bone, up, forward) : frame_from(bone, forward, -up));
    }

    for (int limb = 0; limb < k_limb_count; ++limb) {
        const auto parts = limb_parts(static_cast<Limb>(limb));
        LimbChain& chain = anatomy.limbs[limb];
        chain.root = map.joint(parts[0]);
        chain.middle = map.joint(parts[1]);
        chain.extremity = map.joint(parts[2]);
        chain.upper_rest_vector = rest_vector(p, chain.root, chain.middle);
        chain.lower_rest_vector = rest_vector(p, chain.middle, chain.extremity);
        chain.upper_length = chain.upper_rest_vector.norm();
        chain.lower_length = chain.lower_rest_vector.norm();
        const bool arm = limb < 2;
        const BodyPart clavicle = limb == 0 ? BodyPart::clavicle_l : BodyPart::clavicle_r;
        chain.parent_part = static_cast<int>(arm ? (map.has(clavicle) ? clavicle : BodyPart::chest) : BodyPart::pelvis);
        if (chain.upper_length < 1e-6 || chain.lower_length < 1e-6) {
            return make_error(ErrorCode::invalid, "limb " + std::string(body_part_name(parts[0])) + " has a zero-length bone");
        }
    }
    anatomy.leg_length = 0.5 * (anatomy.limbs[2].length() + anatomy.limbs[3].length());
    anatomy.hip_centre_in_pelvis = 0.5 * (at(BodyPart::thigh_l) + at(BodyPart::thigh_r)) - at(BodyPart::pelvis);
    const FloorEstimate floor = floor_estimate(clip, map);
    anatomy.floor_y = floor.floor_y;
    anatomy.ankle_height = floor.ankle_height;
    anatomy.fist_local_rotations = fist_local_rotations(skeleton, map, anatomy.rest_positions);
    return anatomy;
}

} // namespace kumite
