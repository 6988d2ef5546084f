#include "kumite/core/skinned_mesh.h"

#include <algorithm>
#include <cassert>

namespace kumite {

void skin_matrices(std::span<Eigen::Matrix4f> skin, const SkinnedMesh& mesh, std::span<const Eigen::Vector3d> model_positions,
                   std::span<const Eigen::Quaterniond> model_rotations) {
    assert(skin.size() == mesh.bind_to_rest.size() && model_positions.size() >= skin.size() && model_rotations.size() >= skin.size());
    for (std::size_t j = 0; j < skin.size(); ++j) {
        Eigen::Matrix4f pose = Eigen::Matrix4f::Identity();
        pose.topLeftCorner<3, 3>() = model_rotations[j].toRotationMatrix().cast<float>();
        pose.block<3, 1>(0, 3) = model_positions[j].cast<float>();
        skin[j] = pose * mesh.bind_to_rest[j];
    }
}

Eigen::Vector3f skin_vertex(const SkinnedMesh& mesh, std::span<const Eigen::Matrix4f> skin, std::size_t vertex) {
    const Eigen::Vector4f bound = mesh.positions[vertex].homogeneous();
    Eigen::Vector4f out = Eigen::Vector4f::Zero();
    for (int k = 0; k < 4; ++k) {
        const float weight = mesh.weights[vertex][k];
        if (weight > 0.0f) out += weight * (skin[mesh.joints[vertex][k]] * bound);
    }
    return out.head<3>();
}

double skinning_envelope_excess(const SkinnedMesh& mesh, std::span<const Eigen::Matrix4f> skin, std::span<const Eigen::Vector3d> model_positions,
                                std::span<const Eigen::Vector3d> rest_model_positions, std::size_t* worst) {
    double excess = -1e30;
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
        const auto& joints = mesh.joints[v];
        const auto& weights = mesh.weights[v];
        const int heaviest = joints[std::max_element(weights.begin(), weights.end()) - weights.begin()];
        // The rest position of the vertex (the rest skin matrices are translations to the joints).
        const Eigen::Vector4f at_rest_of_0 = mesh.bind_to_rest[joints[0]] * mesh.positions[v].homogeneous();
        const Eigen::Vector3d rest = rest_model_positions[joints[0]] + at_rest_of_0.head<3>().cast<double>();
        double bound = 0.0;
        for (int k = 0; k < 4; ++k) {
            if (weights[k] <= 0.0f) continue;
            const int j = joints[k];
            bound = std::max(bound, (rest - rest_model_positions[j]).norm() + (model_positions[j] - model_positions[heaviest]).norm());
        }
        const double distance = (skin_vertex(mesh, skin, v).cast<double>() - model_positions[heaviest]).norm();
        if (distance - bound > excess) {
            excess = distance - bound;
            if (worst) *worst = v;
        }
    }
    return excess;
}

} // namespace kumite
