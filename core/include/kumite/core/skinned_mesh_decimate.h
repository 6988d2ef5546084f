#pragma once
// A coarser copy of a body for small views: a headset's eyes drawn in software at a few hundred pixels show no
// more of a 10k-triangle face than of a 3k-triangle one, and pay for every triangle. Quadric error metrics
// (Garland & Heckbert 1997) with half-edge collapses: a vertex is folded into a neighbour that already exists, so
// every kept vertex keeps its own position, joints, weights and colour bit for bit — the coarse body skins exactly as
// the full one where it has vertices.
//
// What is never done: moving a vertex on an open edge or a seam (where the mesh's parts or materials meet, or the
// skinning splits a position in two), so no gap opens; a collapse that turns a triangle over or makes a sliver; a
// collapse that breaks the surface's topology (the link condition); moving a vertex where the skinning steps (a
// neighbour with half its weight or more on other joints: where a rigidly skinned body's parts move apart).
// Folding a vertex into a neighbour skinned somewhat differently costs its squared travel in proportion to the
// difference, so the joints' smooth bands go last.

#include "kumite/core/skinned_mesh.h"

#include <cstddef>

namespace kumite {

struct DecimationLimits {
    std::size_t target_triangles = 0; // stop at this many (or fewer) triangles
    double max_error_m = 0.01;        // and before any collapse that moves the surface farther than this (RMS over its planes)
};

// `mesh` with vertices folded away until `limits` stop it; the bind matrices and base colour as they were. A mesh
// with out-of-range indices is returned as it is.
SkinnedMesh skinned_mesh_decimated(const SkinnedMesh& mesh, const DecimationLimits& limits);

} // namespace kumite
