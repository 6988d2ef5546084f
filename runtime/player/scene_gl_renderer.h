#pragma once
// The scene drawn with OpenGL 3.3 core: one lit shader for capsules (a cylinder and two sphere caps) and spheres,
// the skinned bodies (body_gl_renderer.h), one for the floor grid, lines, dots and boxes (one vertex buffer per
// frame). A body's skeleton capsules are drawn, seen through the body, only as the overlay. Lives inside a current
// context (a QOpenGLWidget's): initialize() once, render() per view.

#include "body_gl_renderer.h"
#include "scene.h"
#include "view_camera.h"

#include <QOpenGLBuffer>
#include <QOpenGLExtraFunctions>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <QRect>

#include <vector>

namespace kumite::view {

class SceneGlRenderer : protected QOpenGLExtraFunctions {
public:
    bool initialize(QString& error); // in the current context
    void render(const Scene& scene, const ViewProjection& view_projection, const QRect& viewport_px);
    void release(); // before the context goes away
    int body_mesh_uploads() const { return m_bodies.mesh_uploads(); }

private:
    struct Mesh {
        QOpenGLVertexArrayObject vao;
        QOpenGLBuffer buffer{QOpenGLBuffer::VertexBuffer};
        int vertices = 0;
    };
    void build_mesh(Mesh& mesh, const std::vector<float>& position_normal);
    void draw_solid(const Mesh& mesh, const Eigen::Matrix4f& model, const Color& color, float opacity);
    void draw_capsule(const Capsule& capsule);

    QOpenGLShaderProgram m_lit, m_flat;
    Mesh m_sphere, m_cylinder;
    BodyGlRenderer m_bodies;
    QOpenGLVertexArrayObject m_lines_vao;
    QOpenGLBuffer m_lines{QOpenGLBuffer::VertexBuffer};
    std::vector<float> m_line_vertices; // x y z r g b per vertex, reused
    Eigen::Matrix4f m_view_projection = Eigen::Matrix4f::Identity();
    Eigen::Matrix4f m_view = Eigen::Matrix4f::Identity();
    bool m_ready = false;
};

} // namespace kumite::view
