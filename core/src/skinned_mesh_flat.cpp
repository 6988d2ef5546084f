#include "kumite/core/skinned_mesh_flat.h"

#include <cstring>
#include <string>
#include <unordered_map>

namespace kumite {

bool skinned_mesh_is_flat_shaded(const SkinnedMesh& mesh) {
    std::size_t corners = 0, own = 0;
    for (std::size_t t = 0; t + 2 < mesh.triangles.size(); t += 3) {
        const std::uint32_t a = mesh.triangles[t], b = mesh.triangles[t + 1], c = mesh.triangles[t + 2];
        if (a >= mesh.vertex_count() || b >= mesh.vertex_count() || c >= mesh.vertex_count()) continue;
        const Eigen::Vector3d face = (mesh.positions[b] - mesh.positions[a]).cast<double>().cross((mesh.positions[c] - mesh.positions[a]).cast<double>());
        if (!(face.norm() > 0.0)) continue;
        const Eigen::Vector3d unit = face.normalized();
        for (const std::uint32_t v : {a, b, c}) {
            ++corners;
            // Either way round: the winding is skinned_mesh_facing.h's question.
            if (std::abs(unit.dot(mesh.normals[v].cast<double>())) > 0.9848) ++own; // cos 10 degrees
        }
    }
    return corners > 0 && double(own) >= 0.9 * double(corners);
}

SkinnedMesh skinned_mesh_welded(const SkinnedMesh& mesh) {
    SkinnedMesh out;
    out.base_colour = mesh.base_colour;
    out.bind_to_rest = mesh.bind_to_rest;
    const bool coloured = mesh.colours.size() == mesh.vertex_count();
    // The key: the vertex's bytes but its normal's.
    std::unordered_map<std::string, std::uint32_t> kept;
    std::vector<std::uint32_t> index(mesh.vertex_count());
    std::string key;
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
        key.assign(reinterpret_cast<const char*>(mesh.positions[v].data()), sizeof(float) * 3);
        key.append(reinterpret_cast<const char*>(mesh.joints[v].data()), sizeof(mesh.joints[v]));
        key.append(reinterpret_cast<const char*>(mesh.weights[v].data()), sizeof(mesh.weights[v]));
        if (coloured) key.append(reinterpret_cast<const char*>(mesh.colours[v].data()), sizeof(mesh.colours[v]));
        const auto [found, added] = kept.try_emplace(key, std::uint32_t(out.positions.size()));
        if (added) {
            out.positions.push_back(mesh.positions[v]);
            out.normals.push_back(mesh.normals[v]);
            out.joints.push_back(mesh.joints[v]);
            out.weights.push_back(mesh.weights[v]);
            if (coloured) out.colours.push_back(mesh.colours[v]);
        }
        index[v] = found->second;
    }
    out.triangles.reserve(mesh.triangles.size());
    for (const std::uint32_t v : mesh.triangles) out.triangles.push_back(v < index.size() ? index[v] : v);
    return out;
}

} // namespace kumite
