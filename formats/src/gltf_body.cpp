#include "gltf_body.h"

#include <algorithm>
#include <numeric>

namespace kumite::gltf {
namespace {

struct Built {
    Skeleton skeleton;
    std::vector<int> skeleton_of_skin;
    std::vector<int> skin_of_skeleton;
};

int tree_depth(const std::vector<int>& parent, int k) {
    int depth = 0;
    for (int at = parent[std::size_t(k)]; at >= 0 && depth <= int(parent.size()); at = parent[std::size_t(at)]) ++depth;
    return depth;
}

// The kept joints, parents first (by depth in the body tree, then in the node tree, then skin order).
Built build(const SkinJoints& joints, const RigJoints& rig) {
    const int n = int(joints.parent.size());
    std::vector<int> order;
    std::vector<int> depth(std::size_t(n), 0);
    for (int k = 0; k < n; ++k) {
        if (!rig.kept[std::size_t(k)]) continue;
        order.push_back(k);
        depth[std::size_t(k)] = tree_depth(rig.parent, k);
    }
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        if (depth[std::size_t(a)] != depth[std::size_t(b)]) return depth[std::size_t(a)] < depth[std::size_t(b)];
        return joints.node_depth[std::size_t(a)] < joints.node_depth[std::size_t(b)];
    });
    Built built;
    built.skeleton_of_skin.assign(std::size_t(n), -1);
    for (int k : order) {
        built.skeleton_of_skin[std::size_t(k)] = built.skeleton.joint_count();
        built.skin_of_skeleton.push_back(k);
        const int parent_skin = rig.parent[std::size_t(k)];
        const int parent = parent_skin >= 0 ? built.skeleton_of_skin[std::size_t(parent_skin)] : -1;
        const Eigen::Vector3d parent_position = parent_skin >= 0 ? joints.positions[std::size_t(parent_skin)] : Eigen::Vector3d::Zero();
        built.skeleton.names.push_back(joints.names[std::size_t(k)]);
        built.skeleton.parents.push_back(parent);
        built.skeleton.rest_offsets.push_back(joints.positions[std::size_t(k)] - parent_position);
    }
    for (int j = 0; j < built.skeleton.joint_count(); ++j) { // End Sites on the leaves that move mesh
        const Eigen::Vector3d& tip = joints.tips[std::size_t(built.skin_of_skeleton[std::size_t(j)])];
        if (tip.squaredNorm() > 0.0 && built.skeleton.children(j).empty()) built.skeleton.end_sites.push_back({j, tip});
    }
    return built;
}

int strike_parts_found(const BodyMap& map) {
    return int(std::count_if(std::begin(k_strike_parts), std::end(k_strike_parts), [&](BodyPart part) { return map.has(part); }));
}

// A needed part played by a joint that deforms nothing (an IK or FK copy of the arm the mesh follows).
bool uses_control_joint(const BodyMap& map, const Built& built, const std::vector<double>& weights) {
    for (BodyPart part : k_strike_parts) {
        if (part == BodyPart::pelvis || part == BodyPart::chest || !map.has(part)) continue;
        if (weights[std::size_t(built.skin_of_skeleton[std::size_t(map.joint(part))])] <= 0.0) return true;
    }
    return false;
}

// The joint where the legs meet hung under the one where the arms meet (a control rig's torso above its hips):
// the legs' joint as the trunk's parent, so the trunk follows the pelvis as a body does. Returns true when done.
bool rehang_hips(const Skeleton& skeleton, const BodyMap& map, const Built& built, RigJoints& rig) {
    if (map.has(BodyPart::chest) || !map.has(BodyPart::thigh_l) || !map.has(BodyPart::thigh_r) || !map.has(BodyPart::upper_arm_l) ||
        !map.has(BodyPart::upper_arm_r)) {
        return false;
    }
    auto common = [&](int a, int b) {
        for (int at = a; at >= 0; at = skeleton.parents[std::size_t(at)]) {
            if (skeleton.is_ancestor(at, b)) return at;
        }
        return -1;
    };
    const int legs = common(map.joint(BodyPart::thigh_l), map.joint(BodyPart::thigh_r));
    const int arms = common(map.joint(BodyPart::upper_arm_l), map.joint(BodyPart::upper_arm_r));
    if (legs < 0 || arms < 0 || skeleton.parents[std::size_t(legs)] != arms) return false;
    const int legs_skin = built.skin_of_skeleton[std::size_t(legs)], arms_skin = built.skin_of_skeleton[std::size_t(arms)];
    rig.parent[std::size_t(legs_skin)] = rig.parent[std::size_t(arms_skin)];
    rig.parent[std::size_t(arms_skin)] = legs_skin;
    rig.warnings.push_back("joint " + skeleton.names[std::size_t(legs)] + " (where the legs meet) hangs under " + skeleton.names[std::size_t(arms)] +
                           " (where the arms meet); re-hung above it, so the trunk follows the pelvis");
    return true;
}

// The body map by names and structure, overridden by the VRM humanoid's own bones where they are joints of the body.
BodyMap vrm_body_map(const VrmHumanoid& vrm, const Built& built, const std::vector<int>& skin_nodes, std::vector<std::string>& warnings) {
    BodyMap map = detect_body_map(built.skeleton);
    for (const VrmBone& bone : vrm.bones) {
        const auto at = std::find(skin_nodes.begin(), skin_nodes.end(), bone.node);
        const int skin = at == skin_nodes.end() ? -1 : int(at - skin_nodes.begin());
        const int joint = skin >= 0 ? built.skeleton_of_skin[std::size_t(skin)] : -1;
        if (joint < 0) {
            warnings.push_back("VRM " + vrm.version + " humanoid bone for " + std::string(body_part_name(bone.part)) + " is node " +
                               std::to_string(bone.node) + ", not a joint of the body; left to names and structure");
            continue;
        }
        map.set(bone.part, joint, BodyMapSource::vrm);
    }
    return map;
}

} // namespace

BodySkeleton body_skeleton(const SkinJoints& joints, const std::vector<double>& weights, const VrmHumanoid* vrm, const std::vector<int>& skin_nodes) {
    RigJoints rig = body_tree(joints.parent, joints.positions, weights, joints.names, false);
    Built built = build(joints, rig);
    BodyMap map = detect_body_map(built.skeleton);
    if (strike_parts_found(map) < int(std::size(k_strike_parts)) || uses_control_joint(map, built, weights)) {
        RigJoints pruned = body_tree(joints.parent, joints.positions, weights, joints.names, true);
        Built pruned_built = build(joints, pruned);
        const BodyMap pruned_map = detect_body_map(pruned_built.skeleton);
        if (strike_parts_found(pruned_map) >= strike_parts_found(map)) rig = std::move(pruned), built = std::move(pruned_built), map = pruned_map;
    }
    if (rehang_hips(built.skeleton, map, built, rig)) {
        built = build(joints, rig);
        map = detect_body_map(built.skeleton);
    }
    BodySkeleton body;
    body.warnings = std::move(rig.warnings);
    if (vrm) map = vrm_body_map(*vrm, built, skin_nodes, body.warnings);
    body.skeleton = std::move(built.skeleton);
    body.skeleton_of_skin = std::move(built.skeleton_of_skin);
    body.body_map = map;
    return body;
}

Result<void> check_strike_parts(const BodyMap& body_map, const std::filesystem::path& sidecar) {
    std::string missing;
    for (BodyPart part : k_strike_parts) {
        if (!body_map.has(part)) missing += (missing.empty() ? "" : ", ") + std::string(body_part_name(part));
    }
    if (missing.empty()) return {};
    return make_error(ErrorCode::invalid,
                      "not a whole humanoid: no joint found for " + missing +
                          " (a strike needs the pelvis, chest, head, both arms to the wrist and both legs to the ankle; joints were looked for by "
                          "name and by the skeleton's shape). If the joints are there, name them in " +
                          sidecar.filename().string() + " beside the file, e.g. {\"body_map\": {\"" +
                          std::string(body_part_name(*std::find_if(std::begin(k_strike_parts), std::end(k_strike_parts),
                                                                   [&](BodyPart part) { return !body_map.has(part); }))) +
                          "\": \"JointName\"}}");
}

} // namespace kumite::gltf
