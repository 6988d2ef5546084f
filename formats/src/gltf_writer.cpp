#include "kumite/formats/gltf_writer.h"

#include "kumite/formats/atomic_file.h"

#include <tiny_gltf.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

namespace kumite {
namespace {

// One buffer that grows as accessors are appended, each 4-byte aligned in a buffer view of its own.
class GlbBuilder {
public:
    explicit GlbBuilder(tinygltf::Model& model) : m_model(model) { m_model.buffers.emplace_back(); }

    // Appends `count` elements of `type` (TINYGLTF_TYPE_*) made of `component_type` values; returns the accessor.
    int add(const void* data, std::size_t bytes, std::size_t count, int type, int component_type, int target = 0) {
        std::vector<unsigned char>& buffer = m_model.buffers[0].data;
        while (buffer.size() % 4 != 0) buffer.push_back(0);
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = buffer.size();
        view.byteLength = bytes;
        view.target = target;
        const auto* begin = static_cast<const unsigned char*>(data);
        buffer.insert(buffer.end(), begin, begin + bytes);
        m_model.bufferViews.push_back(view);
        tinygltf::Accessor accessor;
        accessor.bufferView = static_cast<int>(m_model.bufferViews.size()) - 1;
        accessor.count = count;
        accessor.type = type;
        accessor.componentType = component_type;
        m_model.accessors.push_back(accessor);
        return static_cast<int>(m_model.accessors.size()) - 1;
    }

    int add_floats(const std::vector<float>& values, int type, int components, int target = 0) {
        return add(values.data(), values.size() * sizeof(float), values.size() / components, type, TINYGLTF_COMPONENT_TYPE_FLOAT, target);
    }

    // min/max per component, required on POSITION and animation inputs.
    void set_bounds(int accessor, const std::vector<float>& values, int components) {
        std::vector<double> low(components, std::numeric_limits<double>::infinity()), high(components, -std::numeric_limits<double>::infinity());
        for (std::size_t i = 0; i < values.size(); ++i) {
            low[i % components] = std::min<double>(low[i % components], values[i]);
            high[i % components] = std::max<double>(high[i % components], values[i]);
        }
        m_model.accessors[accessor].minValues = low;
        m_model.accessors[accessor].maxValues = high;
    }

private:
    tinygltf::Model& m_model;
};

void add_mesh(tinygltf::Model& model, GlbBuilder& builder, const SkinnedMesh& body, const std::vector<int>& joint_nodes) {
    std::vector<float> positions, normals, weights, inverse_binds;
    std::vector<std::uint16_t> joints;
    for (std::size_t v = 0; v < body.vertex_count(); ++v) {
        for (int c = 0; c < 3; ++c) positions.push_back(body.positions[v][c]);
        for (int c = 0; c < 3; ++c) normals.push_back(body.normals[v][c]);
        for (int k = 0; k < 4; ++k) joints.push_back(body.joints[v][k]);
        for (int k = 0; k < 4; ++k) weights.push_back(body.weights[v][k]);
    }
    for (const Eigen::Matrix4f& matrix : body.bind_to_rest) {
        for (int i = 0; i < 16; ++i) inverse_binds.push_back(matrix.data()[i]); // Eigen and glTF are both column-major
    }
    tinygltf::Primitive primitive;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.attributes["POSITION"] = builder.add_floats(positions, TINYGLTF_TYPE_VEC3, 3, TINYGLTF_TARGET_ARRAY_BUFFER);
    builder.set_bounds(primitive.attributes["POSITION"], positions, 3);
    primitive.attributes["NORMAL"] = builder.add_floats(normals, TINYGLTF_TYPE_VEC3, 3, TINYGLTF_TARGET_ARRAY_BUFFER);
    primitive.attributes["JOINTS_0"] = builder.add(joints.data(), joints.size() * sizeof(std::uint16_t), body.vertex_count(), TINYGLTF_TYPE_VEC4,
                                                   TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TARGET_ARRAY_BUFFER);
    primitive.attributes["WEIGHTS_0"] = builder.add_floats(weights, TINYGLTF_TYPE_VEC4, 4, TINYGLTF_TARGET_ARRAY_BUFFER);
    primitive.indices = builder.add(body.triangles.data(), body.triangles.size() * sizeof(std::uint32_t), body.triangles.size(), TINYGLTF_TYPE_SCALAR,
                                    TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    primitive.material = 0;

    tinygltf::Material material;
    material.name = "body";
    material.pbrMetallicRoughness.baseColorFactor.assign(body.base_colour.begin(), body.base_colour.end());
    material.pbrMetallicRoughness.metallicFactor = 0.0;
    material.pbrMetallicRoughness.roughnessFactor = 0.7;
    model.materials.push_back(material);

    tinygltf::Mesh mesh;
    mesh.name = "body";
    mesh.primitives.push_back(primitive);
    model.meshes.push_back(mesh);

    tinygltf::Skin skin;
    skin.name = "skeleton";
    skin.joints = joint_nodes;
    skin.skeleton = joint_nodes[0];
    skin.inverseBindMatrices = builder.add_floats(inverse_binds, TINYGLTF_TYPE_MAT4, 16);
    model.skins.push_back(skin);

    tinygltf::Node node;
    node.name = "body";
    node.mesh = 0;
    node.skin = 0;
    model.nodes.push_back(node);
    model.scenes[0].nodes.push_back(static_cast<int>(model.nodes.size()) - 1);
}

void add_animation(tinygltf::Model& model, GlbBuilder& builder, const Clip& motion, std::string_view name) {
    const Skeleton& skeleton = motion.skeleton;
    const int frames = motion.frame_count();
    const int joints = skeleton.joint_count();
    std::vector<float> times(frames);
    for (int f = 0; f < frames; ++f) times[f] = static_cast<float>(f * motion.frame_time_s);
    const int input = builder.add_floats(times, TINYGLTF_TYPE_SCALAR, 1);
    builder.set_bounds(input, times, 1);

    tinygltf::Animation animation;
    animation.name = std::string(name);
    auto channel = [&](int node, const char* path, const std::vector<float>& values, int type, int components) {
        tinygltf::AnimationSampler sampler;
        sampler.input = input;
        sampler.output = builder.add_floats(values, type, components);
        sampler.interpolation = "LINEAR";
        animation.samplers.push_back(sampler);
        tinygltf::AnimationChannel target;
        target.sampler = static_cast<int>(animation.samplers.size()) - 1;
        target.target_node = node;
        target.target_path = path;
        animation.channels.push_back(target);
    };
    for (int j = 0; j < joints; ++j) {
        std::vector<float> rotations;
        rotations.reserve(std::size_t(frames) * 4);
        Eigen::Quaterniond previous = Eigen::Quaterniond::Identity();
        for (int f = 0; f < frames; ++f) {
            Eigen::Quaterniond q = motion.local_rotations[std::size_t(f) * joints + j].normalized();
            if (f > 0 && q.dot(previous) < 0.0) q.coeffs() = -q.coeffs(); // the short way between frames
            previous = q;
            rotations.insert(rotations.end(), {float(q.x()), float(q.y()), float(q.z()), float(q.w())});
        }
        channel(j, "rotation", rotations, TINYGLTF_TYPE_VEC4, 4);
        if (j == 0 || motion.has_local_translations()) {
            std::vector<float> translations;
            translations.reserve(std::size_t(frames) * 3);
            for (int f = 0; f < frames; ++f) {
                const Eigen::Vector3d t = j == 0 ? motion.root_translations[f] : motion.local_translations[std::size_t(f) * joints + j];
                translations.insert(translations.end(), {float(t.x()), float(t.y()), float(t.z())});
            }
            channel(j, "translation", translations, TINYGLTF_TYPE_VEC3, 3);
        }
    }
    model.animations.push_back(animation);
}

} // namespace

Result<std::string> gltf_animation_glb(const Clip& motion, const SkinnedMesh* body, std::string_view animation_name) {
    const Skeleton& skeleton = motion.skeleton;
    const int joints = skeleton.joint_count();
    if (joints == 0) return make_error(ErrorCode::invalid, "a glTF animation needs a skeleton with joints");
    if (motion.frame_count() == 0) return make_error(ErrorCode::invalid, "a glTF animation needs at least one frame");
    if (motion.local_rotations.size() != std::size_t(motion.frame_count()) * joints) return make_error(ErrorCode::invalid, "the motion's rotations do not match its skeleton");
    if (body != nullptr) {
        if (body->bind_to_rest.size() != std::size_t(joints)) return make_error(ErrorCode::invalid, "the body is bound to another skeleton (joint counts differ)");
        for (const auto& vertex_joints : body->joints) {
            for (std::uint16_t j : vertex_joints) {
                if (j >= joints) return make_error(ErrorCode::invalid, "the body names a joint the skeleton does not have");
            }
        }
    }

    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = "kumite";
    model.scenes.emplace_back();
    model.defaultScene = 0;
    GlbBuilder builder(model);

    // The joints as nodes, parents before children (the skeleton's order), node index = joint index.
    std::vector<int> joint_nodes(joints);
    for (int j = 0; j < joints; ++j) {
        tinygltf::Node node;
        node.name = skeleton.names[j];
        const Eigen::Vector3d& offset = skeleton.rest_offsets[j]; // the rest pose the body is bound in
        node.translation = {offset.x(), offset.y(), offset.z()};
        model.nodes.push_back(node);
        joint_nodes[j] = j;
        if (skeleton.parents[j] >= 0) model.nodes[skeleton.parents[j]].children.push_back(j);
    }
    model.scenes[0].nodes.push_back(0);
    if (body != nullptr) add_mesh(model, builder, *body, joint_nodes);
    add_animation(model, builder, motion, animation_name);

    tinygltf::TinyGLTF writer;
    std::ostringstream stream;
    if (!writer.WriteGltfSceneToStream(&model, stream, false, true)) return make_error(ErrorCode::io, "tinygltf could not write the scene");
    return stream.str();
}

Result<void> gltf_write_animation_file(const std::filesystem::path& path, const Clip& motion, const SkinnedMesh* body, std::string_view animation_name) {
    Result<std::string> bytes = gltf_animation_glb(motion, body, animation_name);
    if (!bytes) return make_error(bytes.error().code, path.string() + ": " + bytes.error().message);
    return write_file_atomically(path, *bytes);
}

} // namespace kumite
