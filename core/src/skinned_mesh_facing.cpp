#include "kumite/core/skinned_mesh_facing.h"

namespace kumite {

double skinned_mesh_front_facing_share(const SkinnedMesh& mesh) {
    double agreeing = 0.0, total = 0.0;
    for (std::size_t t = 0; t + 2 < mesh.triangles.size(); t += 3) {
        const std::uint32_t a = mesh.triangles[t], b = mesh.triangles[t + 1], c = mesh.triangles[t + 2];
        if (a >= mesh.vertex_count() || b >= mesh.vertex_count() || c >= mesh.vertex_count()) continue;
        const Eigen::Vector3d face = (mesh.positions[b] - mesh.positions[a]).cast<double>().cross((mesh.positions[c] - mesh.positions[a]).cast<double>());
        const double area = face.norm();
        if (!(area > 0.0)) continue;
        const Eigen::Vector3d normals = (mesh.normals[a] + mesh.normals[b] + mesh.normals[c]).cast<double>();
        total += area;
        if (face.dot(normals) > 0.0) agreeing += area;
    }
    return total > 0.0 ? agreeing / total : 0.5;
}

} // namespace kumite
