#pragma once
// A .glb taken apart (JSON and BIN chunks) and put back together, to make odd and hostile variants of a good
// file in tests: nodes renamed, moved, added, joints added to or removed from the skin.

#include <nlohmann/json.hpp>

#include <Eigen/Geometry>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

namespace kumite::test {

inline std::vector<std::uint8_t> read_bytes(const std::filesystem::path& path) {
    std::ifstream stream(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
}

struct Glb {
    nlohmann::json json;
    std::vector<std::uint8_t> bin;

    explicit Glb(const std::vector<std::uint8_t>& bytes) {
        std::uint32_t json_length = 0, bin_length = 0;
        std::memcpy(&json_length, bytes.data() + 12, 4);
        json = nlohmann::json::parse(bytes.begin() + 20, bytes.begin() + 20 + json_length);
        std::memcpy(&bin_length, bytes.data() + 20 + json_length, 4);
        bin.assign(bytes.begin() + 28 + json_length, bytes.begin() + 28 + json_length + bin_length);
    }
    std::vector<std::uint8_t> bytes() const {
        std::string text = json.dump();
        while (text.size() % 4) text += ' ';
        std::vector<std::uint8_t> out;
        auto u32 = [&](std::uint32_t value) {
            for (int k = 0; k < 4; ++k) out.push_back(static_cast<std::uint8_t>(value >> (8 * k)));
        };
        out.insert(out.end(), {'g', 'l', 'T', 'F'});
        u32(2);
        u32(static_cast<std::uint32_t>(12 + 8 + text.size() + 8 + bin.size()));
        u32(static_cast<std::uint32_t>(text.size()));
        out.insert(out.end(), {'J', 'S', 'O', 'N'});
        out.insert(out.end(), text.begin(), text.end());
        u32(static_cast<std::uint32_t>(bin.size()));
        out.insert(out.end(), {'B', 'I', 'N', '\0'});
        out.insert(out.end(), bin.begin(), bin.end());
        return out;
    }
    void write(const std::filesystem::path& path) const {
        const std::vector<std::uint8_t> out = bytes();
        std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(out.data()), std::streamsize(out.size()));
    }
    // Where element `element` of accessor `accessor` starts in the BIN chunk.
    std::size_t offset_of(int accessor, std::size_t element, std::size_t element_size) const {
        const nlohmann::json& a = json["accessors"][accessor];
        const nlohmann::json& view = json["bufferViews"][a["bufferView"].get<int>()];
        return view.value("byteOffset", std::size_t(0)) + a.value("byteOffset", std::size_t(0)) + element * element_size;
    }
    int attribute(const char* name) const { return json["meshes"][0]["primitives"][0]["attributes"][name].get<int>(); }

    int node_named(const std::string& name) const {
        for (std::size_t n = 0; n < json["nodes"].size(); ++n) {
            if (json["nodes"][n].value("name", std::string()) == name) return int(n);
        }
        return -1;
    }
    int parent_of(int node) const {
        for (std::size_t n = 0; n < json["nodes"].size(); ++n) {
            for (const auto& child : json["nodes"][n].value("children", nlohmann::json::array())) {
                if (child.get<int>() == node) return int(n);
            }
        }
        return -1;
    }
    Eigen::Matrix4d local(int node) const {
        const nlohmann::json& n = json["nodes"][node];
        Eigen::Affine3d m = Eigen::Affine3d::Identity();
        if (n.contains("translation")) m.translate(Eigen::Vector3d(n["translation"][0], n["translation"][1], n["translation"][2]));
        if (n.contains("rotation")) m.rotate(Eigen::Quaterniond(n["rotation"][3], n["rotation"][0], n["rotation"][1], n["rotation"][2]));
        if (n.contains("scale")) m.scale(Eigen::Vector3d(n["scale"][0], n["scale"][1], n["scale"][2]));
        return m.matrix();
    }
    Eigen::Matrix4d world(int node) const {
        Eigen::Matrix4d m = local(node);
        for (int at = parent_of(node); at >= 0; at = parent_of(at)) m = local(at) * m;
        return m;
    }
    // Sets a node's local transform (no scale) from a matrix.
    void set_local(int node, const Eigen::Matrix4d& m) {
        const Eigen::Quaterniond q(Eigen::Matrix3d(m.block<3, 3>(0, 0)));
        nlohmann::json& n = json["nodes"][node];
        n.erase("matrix");
        n["translation"] = {m(0, 3), m(1, 3), m(2, 3)};
        n["rotation"] = {q.x(), q.y(), q.z(), q.w()};
    }
    // Moves `node` under `new_parent` (-1: a scene root) keeping its world transform.
    void reparent(int node, int new_parent) {
        const Eigen::Matrix4d world_before = world(node);
        const int old = parent_of(node);
        if (old >= 0) {
            nlohmann::json& children = json["nodes"][old]["children"];
            for (std::size_t i = 0; i < children.size(); ++i) {
                if (children[i].get<int>() == node) {
                    children.erase(i);
                    break;
                }
            }
            if (children.empty()) json["nodes"][old].erase("children");
        } else {
            nlohmann::json& roots = json["scenes"][0]["nodes"];
            for (std::size_t i = 0; i < roots.size(); ++i) {
                if (roots[i].get<int>() == node) {
                    roots.erase(i);
                    break;
                }
            }
        }
        const Eigen::Matrix4d parent_world = new_parent >= 0 ? world(new_parent) : Eigen::Matrix4d::Identity();
        if (new_parent >= 0) json["nodes"][new_parent]["children"].push_back(node);
        else json["scenes"][0]["nodes"].push_back(node);
        set_local(node, parent_world.inverse() * world_before);
    }
    // A new node (no weight) under `parent` (-1: a scene root) at `local`; returns its index.
    int add_node(const std::string& name, int parent, const Eigen::Matrix4d& local_transform) {
        const int node = int(json["nodes"].size());
        json["nodes"].push_back({{"name", name}});
        set_local(node, local_transform);
        if (parent >= 0) json["nodes"][parent]["children"].push_back(node);
        else json["scenes"][0]["nodes"].push_back(node);
        return node;
    }
    // Adds nodes to skin 0's joints, with inverse bind matrices from their current world transforms.
    void add_joints(const std::vector<int>& nodes) {
        nlohmann::json& skin = json["skins"][0];
        const int matrices = skin["inverseBindMatrices"].get<int>();
        const std::size_t count = json["accessors"][matrices]["count"].get<std::size_t>();
        std::vector<float> values(count * 16);
        std::memcpy(values.data(), bin.data() + offset_of(matrices, 0, 64), count * 64);
        for (int node : nodes) {
            const Eigen::Matrix4f inverse = world(node).inverse().cast<float>();
            for (int c = 0; c < 16; ++c) values.push_back(inverse(c % 4, c / 4));
            skin["joints"].push_back(node);
        }
        while (bin.size() % 4) bin.push_back(0);
        const std::size_t offset = bin.size();
        bin.resize(offset + values.size() * 4);
        std::memcpy(bin.data() + offset, values.data(), values.size() * 4);
        json["buffers"][0]["byteLength"] = bin.size();
        json["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", values.size() * 4}});
        json["accessors"].push_back({{"bufferView", json["bufferViews"].size() - 1}, {"componentType", 5126}, {"count", values.size() / 16}, {"type", "MAT4"}});
        skin["inverseBindMatrices"] = json["accessors"].size() - 1;
    }
};

} // namespace kumite::test
