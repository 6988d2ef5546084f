#pragma once
// A flat-shaded body (low-poly characters: every triangle its own normal, so every corner its own vertex, ~2
// vertices a triangle where a smooth mesh has ~0.5) drawn from its welded vertices: a renderer that takes each
// triangle's normal from its screen derivatives shows it the same with a quarter of the vertices to skin — what a
// software renderer (a headset's eyes drawn on the CPU) spends most on.

#include "kumite/core/skinned_mesh.h"

namespace kumite {

// True when nearly every triangle corner (90%) carries its triangle's own normal, within 10 degrees (exporters
// round; the low-poly human's corners are a median 1 degree and 95% within 8 degrees off their faces').
bool skinned_mesh_is_flat_shaded(const SkinnedMesh& mesh);

// The mesh with the vertices that differ only by their normal made one (same position, joints, weights and colour,
// bit for bit): the same triangles, the same skinning and colours; each kept vertex has the normal of the first of
// its kind (meaningless for a flat-shaded mesh, whose normals are the triangles').
SkinnedMesh skinned_mesh_welded(const SkinnedMesh& mesh);

} // namespace kumite
