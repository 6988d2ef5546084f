#pragma once
// Which way a skinned body's triangles face, so that a renderer may cull back faces (half the triangles drawn) only
// where that is safe: a body wound as glTF says (counter-clockwise front faces, normals outwards), or wound the other
// way throughout; not one with a mix (an open or hand-edited mesh), which is drawn two-sided.

#include "kumite/core/skinned_mesh.h"

namespace kumite {

// The share of triangles (by area) whose face normal, counter-clockwise, points the way their vertices' normals do:
// ~1 for a body wound as glTF says, ~0 for one wound the other way, in between for a mix; 0.5 when no triangle has
// an area.
double skinned_mesh_front_facing_share(const SkinnedMesh& mesh);

} // namespace kumite
