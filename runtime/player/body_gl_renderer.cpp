#include "body_gl_renderer.h"

#include <QMatrix4x4>

#include <algorithm>

namespace kumite::view {
namespace {

const char* k_skinned_vertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in uvec4 joints;
layout(location = 3) in vec4 weights;
uniform sampler2D skin_texture; // row j: joint j's skin matrix, one column per texel
uniform mat4 view;
uniform mat4 view_projection;
out vec3 normal_eye;
mat4 skin_of(uint joint) {
    int row = int(joint);
    return mat4(texelFetch(skin_texture, ivec2(0, row), 0), texelFetch(skin_texture, ivec2(1, row), 0),
                texelFetch(skin_texture, ivec2(2, row), 0), texelFetch(skin_texture, ivec2(3, row), 0));
}
void main() {
    mat4 skin = weights.x * skin_of(joints.x) + weights.y * skin_of(joints.y) + weights.z * skin_of(joints.z) + weights.w * skin_of(joints.w);
    normal_eye = mat3(view) * normalize(mat3(skin) * normal);
    gl_Position = view_projection * (skin * vec4(position, 1.0));
})";
const char* k_skinned_fragment = R"(#version 330 core
in vec3 normal_eye;
uniform vec3 color;
out vec4 fragment;
void main() {
    vec3 n = normalize(normal_eye);
    if (!gl_FrontFacing) n = -n;
    vec3 light = normalize(vec3(-0.3, 0.6, 1.0));  // the capsules' head light
    float diffuse = max(dot(n, light), 0.0);
    float rim = pow(1.0 - max(n.z, 0.0), 3.0);
    float specular = pow(max(dot(reflect(-light, n), vec3(0.0, 0.0, 1.0)), 0.0), 24.0);
    fragment = vec4(color * (0.28 + 0.72 * diffuse) + vec3(0.2) * specular + color * 0.25 * rim, 1.0);
})";

} // namespace

struct BodyGlRenderer::Uploaded {
    std::shared_ptr<const SkinnedMesh> mesh; // kept alive: its address keys the upload
    QOpenGLVertexArrayObject vao;
    QOpenGLBuffer vertices{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer indices{QOpenGLBuffer::IndexBuffer};
    int index_count = 0;
};

BodyGlRenderer::BodyGlRenderer() = default;
BodyGlRenderer::~BodyGlRenderer() = default;

bool BodyGlRenderer::initialize(QString& error) {
    initializeOpenGLFunctions();
    if (!m_program.addShaderFromSourceCode(QOpenGLShader::Vertex, k_skinned_vertex) ||
        !m_program.addShaderFromSourceCode(QOpenGLShader::Fragment, k_skinned_fragment) || !m_program.link()) {
        error = m_program.log();
        return false;
    }
    glGenTextures(1, &m_skin_texture);
    glBindTexture(GL_TEXTURE_2D, m_skin_texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
    m_ready = true;
    return true;
}

BodyGlRenderer::Uploaded& BodyGlRenderer::uploaded(const std::shared_ptr<const SkinnedMesh>& mesh) {
    for (const auto& entry : m_meshes) {
        if (entry->mesh == mesh) return *entry;
    }
    // Interleaved: position (3 floats), normal (3 floats), joints (4 u16), weights (4 floats): 48 bytes.
    struct Vertex {
        float position[3], normal[3];
        std::uint16_t joints[4];
        float weights[4];
    };
    std::vector<Vertex> vertices(mesh->vertex_count());
    for (std::size_t v = 0; v < vertices.size(); ++v) {
        for (int c = 0; c < 3; ++c) vertices[v].position[c] = mesh->positions[v][c], vertices[v].normal[c] = mesh->normals[v][c];
        for (int k = 0; k < 4; ++k) vertices[v].joints[k] = mesh->joints[v][k], vertices[v].weights[k] = mesh->weights[v][k];
    }
    auto entry = std::make_unique<Uploaded>();
    entry->mesh = mesh;
    entry->vao.create();
    entry->vao.bind();
    entry->vertices.create();
    entry->vertices.bind();
    entry->vertices.allocate(vertices.data(), int(vertices.size() * sizeof(Vertex)));
    entry->indices.create();
    entry->indices.bind();
    entry->indices.allocate(mesh->triangles.data(), int(mesh->triangles.size() * sizeof(std::uint32_t)));
    entry->index_count = int(mesh->triangles.size());
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, normal)));
    glEnableVertexAttribArray(2);
    glVertexAttribIPointer(2, 4, GL_UNSIGNED_SHORT, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, joints)));
    glEnableVertexAttribArray(3);
    glVertexAttribPointer(3, 4, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, weights)));
    entry->vao.release();
    ++m_uploads;
    m_meshes.push_back(std::move(entry));
    return *m_meshes.back();
}

void BodyGlRenderer::draw(const std::vector<SkinnedBody>& bodies, const Eigen::Matrix4f& view, const Eigen::Matrix4f& view_projection) {
    if (!m_ready || bodies.empty()) return;
    m_program.bind();
    m_program.setUniformValue("view", QMatrix4x4(view.data()).transposed());
    m_program.setUniformValue("view_projection", QMatrix4x4(view_projection.data()).transposed());
    m_program.setUniformValue("skin_texture", 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, m_skin_texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    for (const SkinnedBody& body : bodies) {
        if (!body.mesh || body.skin.size() != body.mesh->bind_to_rest.size() || body.skin.empty()) continue;
        Uploaded& mesh = uploaded(body.mesh);
        // Eigen matrices are column-major: each joint's 16 floats are its 4 columns, one RGBA texel each.
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 4, GLsizei(body.skin.size()), 0, GL_RGBA, GL_FLOAT, body.skin.data());
        m_program.setUniformValue("color", QVector3D(body.color.x(), body.color.y(), body.color.z()));
        mesh.vao.bind();
        glDrawElements(GL_TRIANGLES, mesh.index_count, GL_UNSIGNED_INT, nullptr);
    }
    glBindVertexArray(0);
    glBindTexture(GL_TEXTURE_2D, 0);
    m_program.release();
}

void BodyGlRenderer::release() {
    for (const auto& entry : m_meshes) entry->vao.destroy(), entry->vertices.destroy(), entry->indices.destroy();
    m_meshes.clear();
    if (m_skin_texture != 0) glDeleteTextures(1, &m_skin_texture);
    m_skin_texture = 0;
    m_ready = false;
}

} // namespace kumite::view
