#include "kumite/formats/gltf_reader.h"

#include "gltf_accessors.h"
#include "gltf_body.h"
#include "gltf_vrm.h"
#include "kumite/formats/body_map_file.h"
#include "kumite/core/standing_height.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

namespace kumite {
namespace {

using gltf::BodySkeleton;
using gltf::fail;
using gltf::SkinJoints;

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
// standing height, the viewer's capsules and the structural body map use. Each skin joint's tip is the farthest
// rest point of the mesh it moves most (a world vector from the joint: identity rest rotations); the skeleton
// gives one to each leaf joint that moves mesh (gltf_body.cpp).
void mesh_tips(SkinJoints& joints, const SkinnedMesh& mesh, const std::vector<Eigen::Matrix4d>& inverse_binds) {
    std::vector<double> farthest(joints.positions.size(), 0.0);
    joints.tips.assign(joints.positions.size(), Eigen::Vector3d::Zero());
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
        const int k = static_cast<int>(std::max_element(mesh.weights[v].begin(), mesh.weights[v].end()) - mesh.weights[v].begin());
        const std::size_t joint = mesh.joints[v][std::size_t(k)];
        // At rest the skin matrix of a joint is G(rest) * IBM.
        const Eigen::Vector4d rest = joints.rest[joint] * inverse_binds[joint] * mesh.positions[v].cast<double>().homogeneous();
        const Eigen::Vector3d tip = rest.head<3>() - joints.positions[joint];
        if (tip.norm() > farthest[joint]) farthest[joint] = tip.norm(), joints.tips[joint] = tip;
    }
}

// A skin whose bind matrices differ from the joints' (its mesh bound in another pose, or placed otherwise): its
// vertices [first_vertex, end) are moved into the common bind space, where the joints' bind matrices put them at
// their rest place (G * IBM is one matrix M for every joint at rest, rest_pose makes sure: v' = M^-1 * sum w G IBM_skin v).
void to_common_bind(SkinnedMesh& mesh, std::size_t first_vertex, const SkinJoints& joints, const std::vector<Eigen::Matrix4d>& binds,
                    const std::vector<int>& joint_of_skin, const std::vector<Eigen::Matrix4d>& skin_binds) {
    std::vector<Eigen::Matrix4d> skin_bind_of_joint(binds);
    bool same = true;
    for (std::size_t k = 0; k < joint_of_skin.size(); ++k) {
        skin_bind_of_joint[std::size_t(joint_of_skin[k])] = skin_binds[k];
        same = same && (skin_binds[k] - binds[std::size_t(joint_of_skin[k])]).cwiseAbs().maxCoeff() <= 1e-6 * std::max(1.0, binds[std::size_t(joint_of_skin[k])].cwiseAbs().maxCoeff());
    }
    if (same || binds.empty()) return;
    const Eigen::Matrix4d common_inverse = (joints.rest[0] * binds[0]).inverse();
    for (std::size_t v = first_vertex; v < mesh.vertex_count(); ++v) {
        Eigen::Matrix4d blend = Eigen::Matrix4d::Zero();
        for (int i = 0; i < 4; ++i) {
            const std::size_t j = mesh.joints[v][std::size_t(i)];
            blend += double(mesh.weights[v][std::size_t(i)]) * joints.rest[j] * skin_bind_of_joint[j];
        }
        const Eigen::Matrix4d to_common = common_inverse * blend;
        mesh.positions[v] = (to_common * mesh.positions[v].cast<double>().homogeneous()).head<3>().cast<float>();
        const Eigen::Vector3d normal = to_common.block<3, 3>(0, 0) * mesh.normals[v].cast<double>();
        if (normal.norm() > 1e-12) mesh.normals[v] = normal.normalized().cast<float>();
    }
}

// The rest pose of each skin joint as world transforms: the nodes' own when the mesh was bound in it (every
// joint's G * IBM is one matrix: identity, or an armature's scale and turn); else the bind pose the inverse bind
// matrices hold, G = M * IBM^-1 with M the skinned mesh node's world transform (a file saved in an animation's
// pose), said in a warning.
std::vector<Eigen::Matrix4d> rest_pose(const tinygltf::Model& model, const std::vector<int>& joint_nodes, const std::vector<Eigen::Matrix4d>& worlds,
                                       const std::vector<Eigen::Matrix4d>& inverse_binds, bool bound, std::vector<std::string>& warnings) {
    std::vector<Eigen::Matrix4d> nodes;
    for (int node : joint_nodes) nodes.push_back(worlds[std::size_t(node)]);
    if (!bound) return nodes; // no bind pose but the nodes'
    const Eigen::Matrix4d first = nodes[0] * inverse_binds[0];
    const double tolerance = 1e-3 * std::max(1.0, first.cwiseAbs().maxCoeff());
    double worst = 0.0;
    for (std::size_t k = 0; k < nodes.size(); ++k) worst = std::max(worst, (nodes[k] * inverse_binds[k] - first).cwiseAbs().maxCoeff());
    if (worst <= tolerance) return nodes;
    Eigen::Matrix4d mesh_world = Eigen::Matrix4d::Identity();
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        if (model.nodes[n].skin >= 0 && model.nodes[n].mesh >= 0) {
            mesh_world = worlds[n];
            break;
        }
    }
    std::vector<Eigen::Matrix4d> bind(nodes.size());
    for (std::size_t k = 0; k < nodes.size(); ++k) {
        const double determinant = inverse_binds[k].determinant();
        if (!(std::abs(determinant) > 1e-12)) {
            warnings.push_back("joint " + std::to_string(k) + "'s inverse bind matrix cannot be inverted; the rest pose is the nodes' own");
            return nodes;
        }
        bind[k] = mesh_world * inverse_binds[k].inverse();
    }
    warnings.push_back("the nodes are not in the pose the mesh was bound in (joints up to " + std::to_string(worst) +
                       " off); the rest pose is the bind pose from the inverse bind matrices");
    return bind;
}

} // namespace

bool is_gltf_path(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension == ".glb" || extension == ".gltf" || extension == ".vrm";
}

Result<GltfCharacter> gltf_parse(std::span<const std::uint8_t> bytes, std::string_view source_name, const std::filesystem::path& base_dir,
                                 const std::filesystem::path& body_map_file) {
    const std::string source(source_name);
    auto with_source = [&](const Error& error) { return make_error(error.code, source + ": " + error.message); };
    Result<tinygltf::Model> loaded = gltf::load_model(bytes, base_dir);
    if (!loaded) return with_source(loaded.error());
    const tinygltf::Model& model = *loaded;

    if (model.skins.empty()) return with_source(fail("no skin: a character needs a skinned mesh with its skeleton's joints"));
    if (model.skins[0].joints.empty()) return with_source(fail("skin 0 has no joints"));
    const int node_count = static_cast<int>(model.nodes.size());
    std::vector<int> node_parents;
    Result<std::vector<Eigen::Matrix4d>> worlds = node_worlds(model, node_parents);
    if (!worlds) return with_source(worlds.error());

    // Every skin's joints, skin 0's first: a file may give each mesh its own skin (a VRM's face, body and hair, a
    // pack's body parts), over the same joints or some of them. A joint's bind matrix is the first skin's.
    std::vector<int> joint_nodes, joint_of_node(node_count, -1);
    std::vector<Eigen::Matrix4d> binds;
    std::vector<std::vector<Eigen::Matrix4d>> skin_binds(model.skins.size());
    std::vector<std::vector<int>> joint_of_skin(model.skins.size());
    bool bound = true;
    for (std::size_t s = 0; s < model.skins.size(); ++s) {
        const tinygltf::Skin& skin = model.skins[s];
        const std::string name = "skin " + std::to_string(s);
        if (skin.joints.size() > std::size_t(k_gltf_max_joints)) {
            return with_source(fail(name + " claims " + std::to_string(skin.joints.size()) + " joints, more than the " + std::to_string(k_gltf_max_joints) + " a character may have"));
        }
        Result<std::vector<Eigen::Matrix4d>> inverse_binds = gltf::inverse_bind_matrices(model, int(s));
        if (!inverse_binds) return with_source(inverse_binds.error());
        skin_binds[s] = std::move(*inverse_binds);
        bound = bound && (skin.joints.empty() || skin.inverseBindMatrices >= 0);
        std::vector<int> listed;
        for (std::size_t k = 0; k < skin.joints.size(); ++k) {
            const int node = skin.joints[k];
            if (node < 0 || node >= node_count) return with_source(fail(name + ": joint " + std::to_string(k) + " is node " + std::to_string(node) + ", not a node"));
            if (std::find(listed.begin(), listed.end(), node) != listed.end()) return with_source(fail(name + ": node " + std::to_string(node) + " is listed twice as a joint"));
            listed.push_back(node);
            if (joint_of_node[node] < 0) {
                if (joint_nodes.size() == std::size_t(k_gltf_max_joints)) {
                    return with_source(fail("the skins hold more than the " + std::to_string(k_gltf_max_joints) + " joints a character may have"));
                }
                joint_of_node[node] = int(joint_nodes.size());
                joint_nodes.push_back(node);
                binds.push_back(skin_binds[s][k]);
            }
            joint_of_skin[s].push_back(joint_of_node[node]);
        }
    }
    const int joint_count = static_cast<int>(joint_nodes.size());
    SkinJoints joints;
    joints.parent.resize(joint_count, -1);
    joints.node_depth.resize(joint_count, 0);
    for (int k = 0; k < joint_count; ++k) {
        const int node = joint_nodes[std::size_t(k)];
        for (int at = node_parents[node]; at >= 0; at = node_parents[at]) {
            if (joints.parent[k] < 0 && joint_of_node[at] >= 0) joints.parent[k] = joint_of_node[at];
            ++joints.node_depth[k];
        }
        joints.names.push_back(model.nodes[node].name.empty() ? "joint" + std::to_string(node) : model.nodes[node].name);
    }
    GltfCharacter result;
    result.node_count = node_count;
    std::vector<std::string>& warnings = result.character.warnings;
    joints.rest = rest_pose(model, joint_nodes, *worlds, binds, bound, warnings);
    for (const Eigen::Matrix4d& rest : joints.rest) joints.positions.push_back(rest.block<3, 1>(0, 3));

    // The mesh first, on joint indices, for the weights that tell the body from the controls.
    for (std::size_t s = 0; s < model.skins.size(); ++s) {
        const std::size_t first_vertex = result.mesh.vertex_count();
        if (Result<void> read = gltf::read_skinned_primitives(model, int(s), joint_of_skin[s], result.mesh); !read) return with_source(read.error());
        to_common_bind(result.mesh, first_vertex, joints, binds, joint_of_skin[s], skin_binds[s]);
    }
    if (result.mesh.triangles.empty()) return with_source(fail("no triangles are skinned by the file's skins"));
    mesh_tips(joints, result.mesh, binds);
    std::vector<double> weights(joint_count, 0.0);
    for (std::size_t v = 0; v < result.mesh.vertex_count(); ++v) {
        for (int i = 0; i < 4; ++i) weights[result.mesh.joints[v][i]] += result.mesh.weights[v][i];
    }

    const std::optional<gltf::VrmHumanoid> vrm = gltf::vrm_humanoid(model);
    if (vrm) warnings.insert(warnings.end(), vrm->warnings.begin(), vrm->warnings.end());
    BodySkeleton body = body_skeleton(joints, weights, vrm ? &*vrm : nullptr, joint_nodes);
    warnings.insert(warnings.end(), body.warnings.begin(), body.warnings.end());
    Skeleton& skeleton = result.character.clip.skeleton;
    skeleton = std::move(body.skeleton);
    result.character.body_map = body.body_map;
    if (!body_map_file.empty() && std::filesystem::exists(body_map_file)) {
        Result<BodyMap> overridden = body_map_apply_override_file(result.character.body_map, skeleton, body_map_file);
        if (!overridden) return overridden.error();
        result.character.body_map = *overridden;
    }
    if (Result<void> complete = gltf::check_strike_parts(result.character.body_map, body_map_sidecar_path(source)); !complete) return with_source(complete.error());

    const int kept = skeleton.joint_count();
    Clip& clip = result.character.clip;
    clip.frame_time_s = 1.0 / 30.0;
    clip.root_translations.assign(1, skeleton.rest_offsets[0]);
    clip.local_rotations.assign(kept, Eigen::Quaterniond::Identity());
    result.character.layout = rotation_layout(kept);
    result.character.unit = LengthUnit{"m", 1.0};
    result.character.unit_detected = false;

    // The skinned mesh: bind_to_rest[j] = T_j(rest)^-1 * G_j(rest) * IBM_j, T_j(rest) the joint's position only.
    result.mesh.bind_to_rest.resize(kept);
    for (int k = 0; k < joint_count; ++k) {
        const int j = body.skeleton_of_skin[k];
        if (j < 0) continue;
        Eigen::Matrix4d rest_inverse = Eigen::Matrix4d::Identity();
        rest_inverse.block<3, 1>(0, 3) = -joints.positions[k];
        result.mesh.bind_to_rest[j] = (rest_inverse * joints.rest[k] * binds[std::size_t(k)]).cast<float>();
    }
    for (std::array<std::uint16_t, 4>& ids : result.mesh.joints) {
        for (std::uint16_t& id : ids) id = static_cast<std::uint16_t>(std::max(body.skeleton_of_skin[id], 0)); // left-out joints weigh nothing
    }
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
    return gltf_parse(bytes, source, path.parent_path(), body_map_sidecar_path(path));
}

} // namespace kumite
