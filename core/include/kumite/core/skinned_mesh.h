#pragma once
// A character's body: a triangle mesh bound to its skeleton for linear-blend skinning, and the skinning itself.
// Read from glTF by formats/gltf_reader.h; drawn on the GPU by the viewer, on the CPU here for checks and for
// engines without a GPU path.
//
// Positions are in the body's bind space; `bind_to_rest[j]` takes a bind-space point into joint j's rest frame
// (the joint's rest position as origin, world axes: the project's skeletons have identity rest rotations). In a
// pose where joint j has model rotation R_j and position p_j, its skin matrix is S_j = [R_j | p_j] * bind_to_rest[j]
// and a vertex goes to sum_k w_k * S_{j_k} * v; the rest pose gives the mesh back where it was modelled.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace kumite {

struct SkinnedMesh {
    std::vector<Eigen::Vector3f> positions;              // [vertex] metres, bind space
    std::vector<Eigen::Vector3f> normals;                // [vertex] unit, bind space
    std::vector<std::array<std::uint16_t, 4>> joints;    // [vertex] skeleton joint indices
    std::vector<std::array<float, 4>> weights;           // [vertex] sum 1
    std::vector<std::uint32_t> triangles;                // 3 per triangle
    std::array<float, 4> base_colour{0.8f, 0.8f, 0.8f, 1.0f}; // linear RGBA (the first material's)
    std::vector<std::array<float, 3>> colours;          // [vertex] linear RGB of its primitive's material; empty: base_colour
    std::vector<Eigen::Matrix4f> bind_to_rest;           // [joint] see above

    std::size_t vertex_count() const { return positions.size(); }
};

// S_j for every joint (`skin` sized to the joint count by the caller: allocation-free per frame).
void skin_matrices(std::span<Eigen::Matrix4f> skin, const SkinnedMesh& mesh, std::span<const Eigen::Vector3d> model_positions,
                   std::span<const Eigen::Quaterniond> model_rotations);

// One vertex skinned with those matrices.
Eigen::Vector3f skin_vertex(const SkinnedMesh& mesh, std::span<const Eigen::Matrix4f> skin, std::size_t vertex);

// A check that skinning kept every vertex on its bones (skinning errors show as long spikes): each skinned vertex
// lies no farther from its heaviest joint than its rest distance to one of its joints plus that joint's distance
// from the heaviest in the pose (where rigid motion of each joint, and any blend of them, keeps it). Returns the
// largest excess over that bound in metres (<= 0 when every vertex is inside), and the vertex in `worst`.
double skinning_envelope_excess(const SkinnedMesh& mesh, std::span<const Eigen::Matrix4f> skin, std::span<const Eigen::Vector3d> model_positions,
                                std::span<const Eigen::Vector3d> rest_model_positions, std::size_t* worst = nullptr);

} // namespace kumite
