#include "kumite/formats/gltf_reader.h"

#include "gltf_accessors.h"
#include "kumite/core/standing_height.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

namespace kumite {
namespace {

using gltf::fail;

// A node's local transform (TRS or matrix), checked finite.
Result<Eigen::Matrix4d> node_local(const tinygltf::Node& node, int index) {
    Eigen::Matrix4d local = Eigen::Matrix4d::Identity();
    const auto finite = [](const std::vector<double>& values) { return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); }); };
    if (!finite(node.matrix) || !finite(node.translation) || !finite(node.rotation) || !finite(node.scale)) {
        return fail("node " + std::to_string(index) + " (" + node.name + "): a transform value is not a finite number");
    }
    if (node.matrix.size() == 16) {
        for (int column = 0; column < 4; ++column) {
            for (int row = 0; row < 4; ++row) local(row, column) = node.matrix[column * 4 + row];
        }
        return local;
    }
    if (node.translation.size() == 3) local.block<3, 1>(0, 3) = Eigen::Vector3d(node.translation[0], node.translation[1], node.translation[2]);
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
    if (node.rotation.size() == 4) {
        Eigen::Quaterniond q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        if (q.norm() < 1e-9) return fail("node " + std::to_string(index) + " (" + node.name + "): its rotation is a zero quaternion");
        rotation = q.normalized().toRotationMatrix();
    }
    Eigen::Vector3d scale(1.0, 1.0, 1.0);
    if (node.scale.size() == 3) scale = Eigen::Vector3d(node.scale[0], node.scale[1], node.scale[2]);
    local.block<3, 3>(0, 0) = rotation * scale.asDiagonal();
    return local;
}

// World transforms of every node at rest, and each node's parent (-1 for roots); a cycle or a node with two
// parents is refused.
Result<std::vector<Eigen::Matrix4d>> node_worlds(const tinygltf::Model& model, std::vector<int>& parents) {
    const int nodes = static_cast<int>(model.nodes.size());
    parents.assign(nodes, -1);
    for (int n = 0; n < nodes; ++n) {
        for (int child : model.nodes[n].children) {
            if (child < 0 || child >= nodes) return fail("node " + std::to_string(n) + ": child " + std::to_string(child) + " is not a node");
            if (parents[child] >= 0 || child == n) return fail("node " + std::to_string(child) + " has two parents (or is its own child)");
            parents[child] = n;
        }
    }
    std::vector<Eigen::Matrix4d> local(nodes), world(nodes);
    for (int n = 0; n < nodes; ++n) {
        Result<Eigen::Matrix4d> matrix = node_local(model.nodes[n], n);
        if (!matrix) return matrix.error();
        local[n] = *matrix;
    }
    std::vector<int> state(nodes, 0); // 0 unvisited, 1 in progress, 2 done
    for (int n = 0; n < nodes; ++n) {
        // Walk up to a done ancestor or a root, then come back down.
        std::vector<int> chain;
        for (int at = n; at >= 0 && state[at] != 2; at = parents[at]) {
            if (state[at] == 1) return fail("node " + std::to_string(at) + " is its own ancestor");
            state[at] = 1;
            chain.push_back(at);
        }
        for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
            world[*it] = parents[*it] >= 0 ? Eigen::Matrix4d(world[parents[*it]] * local[*it]) : local[*it];
            state[*it] = 2;
        }
    }
    return world;
}

BvhLayout rotation_layout(int joints) {
    BvhLayout layout;
    layout.joints.resize(joints);
    for (int j = 0; j < joints; ++j) {
        BvhJointChannels& channels = layout.joints[j];
        const bool root = j == 0;
        int k = 0;
        if (root) {
            channels.channels[k++] = BvhChannel::x_position;
            channels.channels[k++] = BvhChannel::y_position;
            channels.channels[k++] = BvhChannel::z_position;
        }
        channels.channels[k++] = BvhChannel::z_rotation;
        channels.channels[k++] = BvhChannel::x_rotation;
        channels.channels[k++] = BvhChannel::y_rotation;
        channels.count = k;
        channels.rotation_order = EulerOrder{}; // ZXY
    }
    return layout;
}

// glTF skeletons end at their last joints; BVH ones carry End Sites (the head's top, the toes' tips) that the
// standing height and the viewer's capsules use. A leaf joint gets one at the farthest point of the body it moves
// most (identity rest rotations: a world vector is the offset in the joint's frame).
void add_end_sites_from_mesh(Skeleton& skeleton, const SkinnedMesh& mesh) {
    const std::vector<Eigen::Vector3d> world = rest_model_positions(skeleton);
    std::vector<double> farthest(skeleton.joint_count(), 0.0);
    std::vector<Eigen::Vector3d> tip(skeleton.joint_count(), Eigen::Vector3d::Zero());
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
        const int k = static_cast<int>(std::max_element(mesh.weights[v].begin(), mesh.weights[v].end()) - mesh.weights[v].begin());
        const int joint = mesh.joints[v][k];
        // At rest the skin matrix of a joint is its rest translation times bind_to_rest.
        const Eigen::Vector4f bound = mesh.bind_to_rest[joint] * mesh.positions[v].homogeneous();
        const Eigen::Vector3d rest = world[joint] + bound.head<3>().cast<double>();
        const double distance = (rest - world[joint]).norm();
        if (distance > farthest[joint]) {
            farthest[joint] = distance;
            tip[joint] = rest - world[joint];
        }
    }
    for (int j = 0; j < skeleton.joint_count(); ++j) {
        if (skeleton.children(j).empty() && farthest[j] > 0.0) skeleton.end_sites.push_back({j, tip[j]});
    }
}

} // namespace

bool is_gltf_path(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension == ".glb" || extension == ".gltf";
}

Result<GltfCharacter> gltf_parse(std::span<const std::uint8_t> bytes, std::string_view source_name, const std::filesystem::path& base_dir) {
    const std::string source(source_name);
    auto with_source = [&](const Error& error) { return make_error(error.code, source + ": " + error.message); };
    Result<tinygltf::Model> loaded = gltf::load_model(bytes, base_dir);
    if (!loaded) return with_source(loaded.error());
    const tinygltf::Model& model = *loaded;

    if (model.skins.empty()) return with_source(fail("no skin: a character needs a skinned mesh with its skeleton's joints"));
    const tinygltf::Skin& skin = model.skins[0];
    const int node_count = static_cast<int>(model.nodes.size());
    if (skin.joints.empty()) return with_source(fail("skin 0 has no joints"));
    if (skin.joints.size() > std::size_t(k_gltf_max_joints)) {
        return with_source(fail("skin 0 claims " + std::to_string(skin.joints.size()) + " joints, more than the " + std::to_string(k_gltf_max_joints) + " a character may have"));
    }
    std::vector<int> node_parents;
    Result<std::vector<Eigen::Matrix4d>> worlds = node_worlds(model, node_parents);
    if (!worlds) return with_source(worlds.error());

    // Joints in parent-first order: the skin's joints sorted by depth, each parented to its nearest joint ancestor.
    const int joint_count = static_cast<int>(skin.joints.size());
    std::vector<int> joint_of_node(node_count, -1);
    for (int k = 0; k < joint_count; ++k) {
        const int node = skin.joints[k];
        if (node < 0 || node >= node_count) return with_source(fail("skin 0: joint " + std::to_string(k) + " is node " + std::to_string(node) + ", not a node"));
        if (joint_of_node[node] >= 0) return with_source(fail("skin 0: node " + std::to_string(node) + " is listed twice as a joint"));
        joint_of_node[node] = k;
    }
    auto joint_parent_node = [&](int node) {
        for (int at = node_parents[node]; at >= 0; at = node_parents[at]) {
            if (joint_of_node[at] >= 0) return at;
        }
        return -1;
    };
    auto depth = [&](int node) {
        int d = 0;
        for (int at = node_parents[node]; at >= 0; at = node_parents[at]) ++d;
        return d;
    };
    std::vector<int> order(skin.joints.begin(), skin.joints.end()); // nodes, parents first
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return depth(a) < depth(b); });
    int roots = 0;
    for (int node : order) roots += joint_parent_node(node) < 0;
    if (roots != 1) return with_source(fail("skin 0's joints form " + std::to_string(roots) + " separate trees; a character needs one skeleton root"));

    GltfCharacter result;
    result.node_count = node_count;
    Skeleton& skeleton = result.character.clip.skeleton;
    std::vector<int> skeleton_of_skin(joint_count, -1); // skin joint index -> skeleton joint
    std::vector<int> skeleton_of_node(node_count, -1);
    for (int node : order) {
        const int index = skeleton.joint_count();
        skeleton_of_node[node] = index;
        skeleton_of_skin[joint_of_node[node]] = index;
        const int parent_node = joint_parent_node(node);
        const int parent = parent_node >= 0 ? skeleton_of_node[parent_node] : -1;
        const Eigen::Vector3d position = (*worlds)[node].block<3, 1>(0, 3);
        const Eigen::Vector3d parent_position = parent_node >= 0 ? Eigen::Vector3d((*worlds)[parent_node].block<3, 1>(0, 3)) : Eigen::Vector3d::Zero();
        std::string name = model.nodes[node].name.empty() ? "joint" + std::to_string(node) : model.nodes[node].name;
        skeleton.names.push_back(std::move(name));
        skeleton.parents.push_back(parent);
        skeleton.rest_offsets.push_back(position - parent_position);
    }
    Clip& clip = result.character.clip;
    clip.frame_time_s = 1.0 / 30.0;
    clip.root_translations.assign(1, skeleton.rest_offsets[0]);
    clip.local_rotations.assign(joint_count, Eigen::Quaterniond::Identity());
    result.character.layout = rotation_layout(joint_count);
    result.character.unit = LengthUnit{"m", 1.0};
    result.character.unit_detected = false;
    result.character.body_map = detect_body_map(skeleton);
    for (BodyPart part : {BodyPart::pelvis, BodyPart::chest, BodyPart::head, BodyPart::upper_arm_l, BodyPart::forearm_l, BodyPart::hand_l,
                          BodyPart::upper_arm_r, BodyPart::forearm_r, BodyPart::hand_r, BodyPart::thigh_l, BodyPart::shin_l, BodyPart::foot_l,
                          BodyPart::thigh_r, BodyPart::shin_r, BodyPart::foot_r}) {
        if (result.character.body_map.joint(part) < 0) {
            return with_source(fail("no humanoid skeleton: no joint found for " + std::string(body_part_name(part)) +
                                    " (joint names such as Mixamo's, Unreal's, Rigify's or VRM's are recognised)"));
        }
    }
    // The skinned mesh: bind_to_rest[j] = T_j(rest)^-1 * G_j(rest) * IBM_j, T_j(rest) the joint's position only.
    Result<std::vector<Eigen::Matrix4d>> inverse_binds = gltf::inverse_bind_matrices(model, skin);
    if (!inverse_binds) return with_source(inverse_binds.error());
    result.mesh.bind_to_rest.resize(joint_count);
    for (int k = 0; k < joint_count; ++k) {
        const int node = skin.joints[k];
        Eigen::Matrix4d rest_inverse = Eigen::Matrix4d::Identity();
        rest_inverse.block<3, 1>(0, 3) = -(*worlds)[node].block<3, 1>(0, 3);
        result.mesh.bind_to_rest[skeleton_of_skin[k]] = (rest_inverse * (*worlds)[node] * (*inverse_binds)[k]).cast<float>();
    }
    if (Result<void> read = gltf::read_skinned_primitives(model, skeleton_of_skin, result.mesh); !read) return with_source(read.error());
    if (result.mesh.triangles.empty()) return with_source(fail("no triangles are skinned by skin 0"));
    add_end_sites_from_mesh(skeleton, result.mesh);
    result.character.height_m = standing_height(clip, result.character.body_map).height;
    if (!(result.character.height_m >= 0.3 && result.character.height_m <= 5.0)) {
        return with_source(fail("the skeleton stands " + std::to_string(result.character.height_m) + " m tall; a character is 0.3 to 5 m (glTF lengths are metres)"));
    }
    return result;
}

Result<GltfCharacter> gltf_read_file(const std::filesystem::path& path) {
    const std::string source = path.string();
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) return make_error(ErrorCode::io, source + ": is a directory, expected a .glb or .gltf file");
    std::ifstream stream(path, std::ios::binary);
    if (!stream) return make_error(ErrorCode::io, source + ": cannot open");
    stream.seekg(0, std::ios::end);
    const std::streamoff size = stream.tellg();
    if (size < 0 || std::size_t(size) > k_gltf_max_file_bytes) return make_error(ErrorCode::invalid, source + ": larger than the 512 MB a character file may be");
    stream.seekg(0);
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
    if (size > 0 && !stream.read(reinterpret_cast<char*>(bytes.data()), size)) return make_error(ErrorCode::io, source + ": cannot read");
    return gltf_parse(bytes, source, path.parent_path());
}

} // namespace kumite
