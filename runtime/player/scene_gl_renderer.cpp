#include "scene_gl_renderer.h"

#include "scene_geometry.h"

#include <Eigen/Geometry>

#include <cmath>

namespace kumite::view {
namespace {

const char* k_lit_vertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
uniform mat4 model;
uniform mat4 view;
uniform mat4 view_projection;
out vec3 normal_eye;
void main() {
    normal_eye = mat3(view) * normalize(mat3(model) * normal);
    gl_Position = view_projection * model * vec4(position, 1.0);
})";
const char* k_lit_fragment = R"(#version 330 core
in vec3 normal_eye;
uniform vec3 color;
uniform float opacity;
out vec4 fragment;
void main() {
    vec3 n = normalize(normal_eye);
    vec3 light = normalize(vec3(-0.3, 0.6, 1.0));  // a head light, a little above and left
    float diffuse = max(dot(n, light), 0.0);
    float rim = pow(1.0 - max(n.z, 0.0), 3.0);
    float specular = pow(max(dot(reflect(-light, n), vec3(0.0, 0.0, 1.0)), 0.0), 24.0);
    vec3 lit = color * (0.28 + 0.72 * diffuse) + vec3(0.25) * specular + color * 0.25 * rim;
    fragment = vec4(lit, opacity);
})";
const char* k_flat_vertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 color_in;
uniform mat4 view_projection;
uniform float point_size;
out vec3 color;
void main() {
    color = color_in;
    gl_PointSize = point_size;
    gl_Position = view_projection * vec4(position, 1.0);
})";
const char* k_flat_fragment = R"(#version 330 core
in vec3 color;
out vec4 fragment;
void main() { fragment = vec4(color, 1.0); })";

void push_vertex(std::vector<float>& out, const Eigen::Vector3f& p, const Eigen::Vector3f& n) {
    out.insert(out.end(), {p.x(), p.y(), p.z(), n.x(), n.y(), n.z()});
}

std::vector<float> unit_sphere(int rings, int segments) {
    std::vector<float> out;
    auto point = [&](int ring, int segment) {
        const float theta = float(M_PI) * ring / rings, phi = 2.0f * float(M_PI) * segment / segments;
        return Eigen::Vector3f(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
    };
    for (int r = 0; r < rings; ++r) {
        for (int s = 0; s < segments; ++s) {
            const Eigen::Vector3f a = point(r, s), b = point(r + 1, s), c = point(r + 1, s + 1), d = point(r, s + 1);
            for (const Eigen::Vector3f& p : {a, b, c, a, c, d}) push_vertex(out, p, p);
        }
    }
    return out;
}

std::vector<float> unit_cylinder(int segments) { // radius 1, y from 0 to 1, open ends
    std::vector<float> out;
    for (int s = 0; s < segments; ++s) {
        const float p0 = 2.0f * float(M_PI) * s / segments, p1 = 2.0f * float(M_PI) * (s + 1) / segments;
        const Eigen::Vector3f n0(std::cos(p0), 0, std::sin(p0)), n1(std::cos(p1), 0, std::sin(p1));
        const Eigen::Vector3f up = Eigen::Vector3f::UnitY();
        push_vertex(out, n0, n0), push_vertex(out, n0 + up, n0), push_vertex(out, n1 + up, n1);
        push_vertex(out, n0, n0), push_vertex(out, n1 + up, n1), push_vertex(out, n1, n1);
    }
    return out;
}

Eigen::Matrix4f sphere_model(const Eigen::Vector3f& center, float radius) {
    Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
    m.topLeftCorner<3, 3>() *= radius;
    m.block<3, 1>(0, 3) = center;
    return m;
}

} // namespace

bool SceneGlRenderer::initialize(QString& error) {
    initializeOpenGLFunctions();
    if (!m_lit.addShaderFromSourceCode(QOpenGLShader::Vertex, k_lit_vertex) ||
        !m_lit.addShaderFromSourceCode(QOpenGLShader::Fragment, k_lit_fragment) || !m_lit.link() ||
        !m_flat.addShaderFromSourceCode(QOpenGLShader::Vertex, k_flat_vertex) ||
        !m_flat.addShaderFromSourceCode(QOpenGLShader::Fragment, k_flat_fragment) || !m_flat.link()) {
        error = m_lit.log() + m_flat.log();
        return false;
    }
    if (!m_bodies.initialize(error)) return false;
    build_mesh(m_sphere, unit_sphere(12, 20));
    build_mesh(m_cylinder, unit_cylinder(20));
    m_lines_vao.create();
    m_lines_vao.bind();
    m_lines.create();
    m_lines.setUsagePattern(QOpenGLBuffer::StreamDraw);
    m_lines.bind();
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<void*>(3 * sizeof(float)));
    m_lines_vao.release();
    m_ready = true;
    return true;
}

void SceneGlRenderer::build_mesh(Mesh& mesh, const std::vector<float>& position_normal) {
    mesh.vao.create();
    mesh.vao.bind();
    mesh.buffer.create();
    mesh.buffer.bind();
    mesh.buffer.allocate(position_normal.data(), int(position_normal.size() * sizeof(float)));
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<void*>(3 * sizeof(float)));
    mesh.vao.release();
    mesh.vertices = int(position_normal.size() / 6);
}

void SceneGlRenderer::release() {
    for (Mesh* mesh : {&m_sphere, &m_cylinder}) mesh->vao.destroy(), mesh->buffer.destroy();
    m_lines_vao.destroy();
    m_lines.destroy();
    m_bodies.release();
    m_ready = false;
}

void SceneGlRenderer::draw_solid(const Mesh& mesh, const Eigen::Matrix4f& model, const Color& color, float opacity) {
    m_lit.setUniformValue("model", QMatrix4x4(model.data()).transposed());
    m_lit.setUniformValue("color", QVector3D(color.x(), color.y(), color.z()));
    m_lit.setUniformValue("opacity", opacity);
    const_cast<QOpenGLVertexArrayObject&>(mesh.vao).bind();
    glDrawArrays(GL_TRIANGLES, 0, mesh.vertices);
}

void SceneGlRenderer::draw_capsule(const Capsule& c) {
    const Eigen::Vector3f axis = c.b - c.a;
    const float length = axis.norm();
    if (length > 1e-6f) {
        Eigen::Matrix4f model = Eigen::Matrix4f::Identity();
        const Eigen::Matrix3f rotation = Eigen::Quaternionf::FromTwoVectors(Eigen::Vector3f::UnitY(), axis / length).toRotationMatrix();
        model.topLeftCorner<3, 3>() = rotation * Eigen::Vector3f(c.radius_m, length, c.radius_m).asDiagonal();
        model.block<3, 1>(0, 3) = c.a;
        draw_solid(m_cylinder, model, c.color, 1.0f);
    }
    draw_solid(m_sphere, sphere_model(c.a, c.radius_m), c.color, 1.0f);
    draw_solid(m_sphere, sphere_model(c.b, c.radius_m), c.color, 1.0f);
}

void SceneGlRenderer::render(const Scene& scene, const ViewProjection& vp, const QRect& viewport) {
    if (!m_ready) return;
    glViewport(viewport.x(), viewport.y(), viewport.width(), viewport.height());
    glEnable(GL_SCISSOR_TEST);
    glScissor(viewport.x(), viewport.y(), viewport.width(), viewport.height());
    glClearColor(0.16f, 0.18f, 0.22f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    // Colour blends; the framebuffer's alpha stays opaque (the widget is composed with it).
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    m_view = vp.view;
    m_view_projection = vp.projection * vp.view;
    const QMatrix4x4 view_projection = QMatrix4x4(m_view_projection.data()).transposed();

    m_lit.bind();
    m_lit.setUniformValue("view", QMatrix4x4(m_view.data()).transposed());
    m_lit.setUniformValue("view_projection", view_projection);
    for (const Capsule& c : scene.capsules) {
        if (!c.of_body) draw_capsule(c);
    }
    for (const Sphere& s : scene.spheres) {
        if (s.opacity < 1.0f) continue;
        draw_solid(m_sphere, sphere_model(s.center, s.radius_m), s.color, 1.0f);
    }

    m_bodies.draw(scene.bodies, m_view, m_view_projection, viewport.height());

    // Lines: grid, polylines, boxes; dots separately.
    m_line_vertices.clear();
    auto line = [&](const Eigen::Vector3f& a, const Eigen::Vector3f& b, const Color& color) {
        m_line_vertices.insert(m_line_vertices.end(), {a.x(), a.y(), a.z(), color.x(), color.y(), color.z(), b.x(), b.y(), b.z(), color.x(), color.y(), color.z()});
    };
    for (const FloorLine& floor : floor_grid_lines(scene.floor_half_size_m)) {
        line(floor.a, floor.b, floor.axis ? Color(0.43f, 0.46f, 0.53f) : Color(0.28f, 0.30f, 0.35f));
    }
    for (const Polyline& polyline : scene.polylines) {
        if (polyline.dots) continue;
        for (std::size_t i = 1; i < polyline.points.size(); ++i) line(polyline.points[i - 1], polyline.points[i], polyline.color);
    }
    for (const WireBox& box : scene.boxes) {
        for (const auto& [a, b] : wire_box_edges(box)) line(a, b, box.color);
    }
    const int line_vertices = int(m_line_vertices.size() / 6);
    for (const Polyline& polyline : scene.polylines) {
        if (!polyline.dots) continue;
        for (const Eigen::Vector3f& p : polyline.points) m_line_vertices.insert(m_line_vertices.end(), {p.x(), p.y(), p.z(), polyline.color.x(), polyline.color.y(), polyline.color.z()});
    }
    const int dot_vertices = int(m_line_vertices.size() / 6) - line_vertices;
    m_flat.bind();
    m_flat.setUniformValue("view_projection", view_projection);
    m_flat.setUniformValue("point_size", 6.0f);
    m_lines_vao.bind();
    m_lines.bind();
    m_lines.allocate(m_line_vertices.data(), int(m_line_vertices.size() * sizeof(float)));
    glDrawArrays(GL_LINES, 0, line_vertices);
    glEnable(GL_PROGRAM_POINT_SIZE);
    glDisable(GL_DEPTH_TEST); // trajectories stay visible through the body
    glDrawArrays(GL_POINTS, line_vertices, dot_vertices);
    m_lines_vao.release();

    // See-through spheres last, over everything.
    m_lit.bind();
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    for (const Sphere& s : scene.spheres) {
        if (s.opacity >= 1.0f) continue;
        draw_solid(m_sphere, sphere_model(s.center, s.radius_m), s.color, s.opacity);
    }
    glDepthMask(GL_TRUE);
    // The bodies' skeletons, seen through them.
    if (scene.skeleton_overlay && !scene.bodies.empty()) {
        glEnable(GL_SCISSOR_TEST);
        glClear(GL_DEPTH_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
        for (Capsule c : scene.capsules) {
            if (!c.of_body) continue;
            c.radius_m *= 0.45f; // thin bones over the body
            draw_capsule(c);
        }
    }
    // Leave the state QPainter expects.
    glBindVertexArray(0);
    m_lit.release();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_PROGRAM_POINT_SIZE);
}

} // namespace kumite::view
