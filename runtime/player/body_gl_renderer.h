#pragma once
// Skinned bodies drawn with OpenGL 3.3 core: linear-blend skinning in the vertex shader, the skin matrices in a
// float texture (4 texels a joint, one row per joint: any joint count), each vertex in its material's colour, lit
// like the capsules. Each SkinnedMesh is uploaded once (vertex and index buffers kept while the mesh is alive) and
// shared by every body drawn with it; per body and frame only its skin matrices go to the GPU. Back faces are
// culled when the mesh's winding says which they are (skinned_mesh_facing.h); a flat-shaded body goes up welded and
// takes its triangles' normals from the screen (skinned_mesh_flat.h). Lit in linear light and written
// with gamma 2, with no pow() per pixel: in software (a headset's eyes drawn on the CPU) that was half the cost.
// In a view at most k_coarse_view_px tall (a headset's eyes drawn in software at the null compositor's 320x240) a
// body goes with a coarse copy of its mesh (skinned_mesh_decimate.h: a third of the triangles, the surface within
// 5 mm, every kept vertex skinned as in the full mesh), made once per mesh when first needed.
// Lives inside a current context, like SceneGlRenderer.

#include "scene.h"

#include <QOpenGLBuffer>
#include <QOpenGLExtraFunctions>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>

#include <memory>
#include <vector>

namespace kumite::view {

class BodyGlRenderer : protected QOpenGLExtraFunctions {
public:
    BodyGlRenderer();
    ~BodyGlRenderer();
    bool initialize(QString& error); // in the current context
    static constexpr int k_coarse_view_px = 480;
    // Depth test on, blending as the caller set it; `view_height_px` the viewport's height (picks the mesh's detail).
    void draw(const std::vector<SkinnedBody>& bodies, const Eigen::Matrix4f& view, const Eigen::Matrix4f& view_projection, int view_height_px);
    void release(); // before the context goes away
    int mesh_uploads() const { return m_uploads; } // meshes uploaded so far (one per SkinnedMesh drawn)

private:
    struct GpuMesh;
    struct Uploaded;
    Uploaded& uploaded(const std::shared_ptr<const SkinnedMesh>& mesh);
    GpuMesh& coarse(Uploaded& mesh);
    void upload(const SkinnedMesh& mesh, GpuMesh& gpu);

    QOpenGLShaderProgram m_program;
    GLuint m_skin_texture = 0;
    int m_skin_rows = 0; // joints the skin texture holds
    std::vector<std::unique_ptr<Uploaded>> m_meshes;
    int m_uploads = 0;
    bool m_ready = false;
};

} // namespace kumite::view
