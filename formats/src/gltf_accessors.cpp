#include "gltf_accessors.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>

namespace kumite::gltf {
namespace {

// A joint id as read (any number a hostile accessor holds: huge, fractional, not finite), for a message.
std::string joint_id_text(double id) {
    if (std::isfinite(id) && std::abs(id) < 1e15 && id == std::floor(id)) return std::to_string(static_cast<long long>(id));
    char text[32];
    std::snprintf(text, sizeof text, "%g", id);
    return text;
}

// Images are not decoded: a character's look is its base colour.
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) { return true; }

template <class T>
T read_le(const std::uint8_t* at) {
    T value;
    std::memcpy(&value, at, sizeof value);
    return value;
}

// Why a .gltf that tinygltf refused without a word is not glTF 2.0: files written while 2.0 was a draft
// (COLLADA2GLTF 2017) name a skin's joints in `jointNames` and each joint in its node's `jointName`.
std::string draft_reason(std::span<const std::uint8_t> bytes) {
    const nlohmann::json json = nlohmann::json::parse(bytes.begin(), bytes.end(), nullptr, false);
    if (!json.is_object() || !json.contains("skins") || !json["skins"].is_array()) return {};
    for (std::size_t s = 0; s < json["skins"].size(); ++s) {
        const nlohmann::json& skin = json["skins"][s];
        if (skin.is_object() && !skin.contains("joints") && skin.contains("jointNames")) {
            return "skin " + std::to_string(s) + " lists \"jointNames\" instead of \"joints\": a file from glTF 2.0's draft, before its release; "
                   "export it again with a current exporter";
        }
    }
    return {};
}

} // namespace

Result<tinygltf::Model> load_model(std::span<const std::uint8_t> bytes, const std::filesystem::path& base_dir) {
    if (bytes.empty()) return fail("empty file");
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(skip_image, nullptr);
    tinygltf::Model model;
    std::string error, warning;
    const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    bool ok = false;
    const std::string base = base_dir.string();
    if (binary) {
        ok = loader.LoadBinaryFromMemory(&model, &error, &warning, bytes.data(), static_cast<unsigned int>(bytes.size()), base);
    } else {
        ok = loader.LoadASCIIFromString(&model, &error, &warning, reinterpret_cast<const char*>(bytes.data()), static_cast<unsigned int>(bytes.size()), base);
    }
    if (!ok) {
        while (!error.empty() && (error.back() == '\n' || error.back() == ' ')) error.pop_back();
        if (error.empty() && !binary) error = draft_reason(bytes);
        return fail(std::string(binary ? "not a valid .glb" : "not a valid glTF file") + (error.empty() ? "" : ": " + error));
    }
    return model;
}

Result<AccessorReader> AccessorReader::open(const tinygltf::Model& model, int index, const std::string& what) {
    const std::string where = what + ": accessor " + std::to_string(index);
    if (index < 0 || index >= static_cast<int>(model.accessors.size())) return fail(what + ": accessor " + std::to_string(index) + " does not exist");
    const tinygltf::Accessor& accessor = model.accessors[index];
    if (accessor.sparse.isSparse) return fail(where + ": sparse accessors are not supported");
    if (accessor.bufferView < 0 || accessor.bufferView >= static_cast<int>(model.bufferViews.size())) return fail(where + ": no buffer view");
    const tinygltf::BufferView& view = model.bufferViews[accessor.bufferView];
    if (view.buffer < 0 || view.buffer >= static_cast<int>(model.buffers.size())) return fail(where + ": its buffer view has no buffer");
    const tinygltf::Buffer& buffer = model.buffers[view.buffer];
    AccessorReader reader;
    reader.m_components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type));
    reader.m_component_size = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(accessor.componentType));
    reader.m_component_type = accessor.componentType;
    if (reader.m_components <= 0 || reader.m_component_size <= 0) return fail(where + ": unknown type or component type");
    const std::size_t element = std::size_t(reader.m_components) * std::size_t(reader.m_component_size);
    reader.m_stride = view.byteStride ? view.byteStride : element;
    reader.m_count = accessor.count;
    reader.m_normalised = accessor.normalized;
    if (reader.m_stride < element) return fail(where + ": stride " + std::to_string(reader.m_stride) + " is shorter than an element");
    // Every byte read must lie inside the view and the view inside the buffer (no overflow in the sums).
    if (view.byteOffset > buffer.data.size() || view.byteLength > buffer.data.size() - view.byteOffset) {
        return fail(where + ": buffer view " + std::to_string(accessor.bufferView) + " runs past its buffer (" + std::to_string(buffer.data.size()) + " bytes)");
    }
    if (reader.m_count == 0) return fail(where + ": no elements");
    if (reader.m_count > k_gltf_max_vertices * 4) return fail(where + ": " + std::to_string(reader.m_count) + " elements, more than a character may have");
    const std::size_t last_start = accessor.byteOffset + (reader.m_count - 1) * reader.m_stride;
    if (accessor.byteOffset > view.byteLength || last_start > view.byteLength || element > view.byteLength - last_start) {
        return fail(where + ": its " + std::to_string(reader.m_count) + " elements run past buffer view " + std::to_string(accessor.bufferView) + " (" +
                    std::to_string(view.byteLength) + " bytes)");
    }
    reader.m_data = buffer.data.data() + view.byteOffset + accessor.byteOffset;
    return reader;
}

double AccessorReader::value(std::size_t element, int component) const {
    const std::uint8_t* at = m_data + element * m_stride + std::size_t(component) * m_component_size;
    switch (m_component_type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return read_le<float>(at);
    case TINYGLTF_COMPONENT_TYPE_DOUBLE: return read_le<double>(at);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return m_normalised ? read_le<std::uint8_t>(at) / 255.0 : read_le<std::uint8_t>(at);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return m_normalised ? read_le<std::uint16_t>(at) / 65535.0 : read_le<std::uint16_t>(at);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return read_le<std::uint32_t>(at);
    case TINYGLTF_COMPONENT_TYPE_BYTE: return m_normalised ? std::max(read_le<std::int8_t>(at) / 127.0, -1.0) : read_le<std::int8_t>(at);
    case TINYGLTF_COMPONENT_TYPE_SHORT: return m_normalised ? std::max(read_le<std::int16_t>(at) / 32767.0, -1.0) : read_le<std::int16_t>(at);
    case TINYGLTF_COMPONENT_TYPE_INT: return read_le<std::int32_t>(at);
    default: return 0.0;
    }
}

std::uint32_t AccessorReader::index_value(std::size_t element) const {
    const std::uint8_t* at = m_data + element * m_stride;
    switch (m_component_type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return read_le<std::uint8_t>(at);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return read_le<std::uint16_t>(at);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return read_le<std::uint32_t>(at);
    default: return 0xffffffffu;
    }
}

Result<std::vector<Eigen::Matrix4d>> inverse_bind_matrices(const tinygltf::Model& model, int skin_index) {
    const tinygltf::Skin& skin = model.skins[std::size_t(skin_index)];
    const std::string name = "skin " + std::to_string(skin_index);
    std::vector<Eigen::Matrix4d> matrices(skin.joints.size(), Eigen::Matrix4d::Identity());
    if (skin.inverseBindMatrices < 0) return matrices;
    Result<AccessorReader> reader = AccessorReader::open(model, skin.inverseBindMatrices, name + " inverse bind matrices");
    if (!reader) return reader.error();
    if (reader->components() != 16 || reader->count() < skin.joints.size()) {
        return fail(name + " inverse bind matrices: accessor " + std::to_string(skin.inverseBindMatrices) + " holds " + std::to_string(reader->count()) +
                    " elements of " + std::to_string(reader->components()) + " numbers, not one 4x4 matrix per joint");
    }
    for (std::size_t k = 0; k < matrices.size(); ++k) {
        for (int c = 0; c < 16; ++c) {
            const double v = reader->value(k, c);
            if (!std::isfinite(v)) return fail(name + " inverse bind matrix " + std::to_string(k) + " holds a number that is not finite");
            matrices[k](c % 4, c / 4) = v;
        }
    }
    return matrices;
}

Result<void> read_skinned_primitives(const tinygltf::Model& model, int skin_index, const std::vector<int>& skeleton_of_skin, SkinnedMesh& mesh) {
    bool colour_set = false;
    const int joints = static_cast<int>(skeleton_of_skin.size());
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        const tinygltf::Node& node = model.nodes[n];
        if (node.skin != skin_index || node.mesh < 0) continue;
        if (node.mesh >= static_cast<int>(model.meshes.size())) return fail("node " + std::to_string(n) + ": mesh " + std::to_string(node.mesh) + " does not exist");
        const tinygltf::Mesh& source = model.meshes[node.mesh];
        for (std::size_t p = 0; p < source.primitives.size(); ++p) {
            const tinygltf::Primitive& primitive = source.primitives[p];
            const std::string where = "mesh " + std::to_string(node.mesh) + " primitive " + std::to_string(p);
            if (primitive.mode != TINYGLTF_MODE_TRIANGLES && primitive.mode != -1) continue; // points and lines are not a body
            auto attribute = [&](const char* name) { const auto found = primitive.attributes.find(name); return found == primitive.attributes.end() ? -1 : found->second; };
            if (attribute("POSITION") < 0 || attribute("JOINTS_0") < 0 || attribute("WEIGHTS_0") < 0) {
                return fail(where + ": a skinned primitive needs POSITION, JOINTS_0 and WEIGHTS_0");
            }
            Result<AccessorReader> positions = AccessorReader::open(model, attribute("POSITION"), where + " POSITION");
            if (!positions) return positions.error();
            Result<AccessorReader> joint_ids = AccessorReader::open(model, attribute("JOINTS_0"), where + " JOINTS_0");
            if (!joint_ids) return joint_ids.error();
            Result<AccessorReader> weights = AccessorReader::open(model, attribute("WEIGHTS_0"), where + " WEIGHTS_0");
            if (!weights) return weights.error();
            const std::size_t vertices = positions->count();
            if (positions->components() != 3 || joint_ids->components() != 4 || weights->components() != 4 || joint_ids->count() != vertices ||
                weights->count() != vertices) {
                return fail(where + ": POSITION, JOINTS_0 and WEIGHTS_0 must hold one VEC3, VEC4 and VEC4 per vertex");
            }
            if (mesh.positions.size() + vertices > k_gltf_max_vertices) return fail(where + ": more than " + std::to_string(k_gltf_max_vertices) + " vertices");
            std::optional<AccessorReader> normals;
            if (attribute("NORMAL") >= 0) {
                Result<AccessorReader> read = AccessorReader::open(model, attribute("NORMAL"), where + " NORMAL");
                if (!read) return read.error();
                if (read->components() != 3 || read->count() != vertices) return fail(where + ": NORMAL must hold one VEC3 per vertex");
                normals = *read;
            }
            const std::size_t first_vertex = mesh.positions.size();
            for (std::size_t v = 0; v < vertices; ++v) {
                const Eigen::Vector3d position(positions->value(v, 0), positions->value(v, 1), positions->value(v, 2));
                if (!position.allFinite()) return fail(where + " POSITION: vertex " + std::to_string(v) + " is not a finite point");
                mesh.positions.push_back(position.cast<float>());
                Eigen::Vector3d normal = normals ? Eigen::Vector3d(normals->value(v, 0), normals->value(v, 1), normals->value(v, 2)) : Eigen::Vector3d::UnitY();
                if (!normal.allFinite() || normal.norm() < 1e-12) normal = Eigen::Vector3d::UnitY();
                mesh.normals.push_back(normal.normalized().cast<float>());
                std::array<std::uint16_t, 4> ids{};
                std::array<float, 4> w{};
                double total = 0.0;
                for (int k = 0; k < 4; ++k) {
                    const double weight = weights->value(v, k);
                    if (!std::isfinite(weight) || weight < 0.0) return fail(where + " WEIGHTS_0: vertex " + std::to_string(v) + " has a weight that is negative or not finite");
                    const double raw = joint_ids->value(v, k);
                    // (Not finite or not below the joint count: refused before any cast, which would be undefined.)
                    if (weight > 0.0 && !(raw >= 0.0 && raw < joints)) {
                        return fail(where + " JOINTS_0: vertex " + std::to_string(v) + " names joint " + joint_id_text(raw) + " of a skin with " +
                                    std::to_string(joints));
                    }
                    ids[k] = weight > 0.0 ? static_cast<std::uint16_t>(skeleton_of_skin[static_cast<int>(raw)]) : 0;
                    w[k] = static_cast<float>(weight);
                    total += weight;
                }
                if (total <= 1e-9) return fail(where + " WEIGHTS_0: vertex " + std::to_string(v) + " has no weight");
                for (float& weight : w) weight = static_cast<float>(weight / total);
                mesh.joints.push_back(ids);
                mesh.weights.push_back(w);
            }
            if (primitive.indices >= 0) {
                Result<AccessorReader> indices = AccessorReader::open(model, primitive.indices, where + " indices");
                if (!indices) return indices.error();
                if (indices->components() != 1 || indices->count() % 3 != 0) return fail(where + " indices: not a list of triangles");
                for (std::size_t i = 0; i < indices->count(); ++i) {
                    const std::uint32_t index = indices->index_value(i);
                    if (index >= vertices) {
                        return fail(where + " indices: index " + std::to_string(i) + " is vertex " + std::to_string(index) + " of " + std::to_string(vertices));
                    }
                    mesh.triangles.push_back(static_cast<std::uint32_t>(first_vertex + index));
                }
            } else {
                if (vertices % 3 != 0) return fail(where + ": not a list of triangles");
                for (std::size_t v = 0; v < vertices; ++v) mesh.triangles.push_back(static_cast<std::uint32_t>(first_vertex + v));
            }
            // Each primitive's material colour on its vertices (a body of several materials: skin, clothes, hair).
            std::array<float, 4> colour = {0.8f, 0.8f, 0.8f, 1.0f};
            if (primitive.material >= 0 && primitive.material < static_cast<int>(model.materials.size())) {
                const std::vector<double>& factor = model.materials[primitive.material].pbrMetallicRoughness.baseColorFactor;
                if (factor.size() == 4 && std::all_of(factor.begin(), factor.end(), [](double v) { return std::isfinite(v); })) {
                    for (int c = 0; c < 4; ++c) colour[c] = static_cast<float>(std::clamp(factor[c], 0.0, 1.0));
                    if (!colour_set) mesh.base_colour = colour;
                    colour_set = true;
                }
            }
            mesh.colours.resize(mesh.positions.size(), {colour[0], colour[1], colour[2]});
        }
    }
    return {};
}

} // namespace kumite::gltf
