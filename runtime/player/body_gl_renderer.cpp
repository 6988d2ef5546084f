#include "body_gl_renderer.h"

#include "kumite/core/skinned_mesh_decimate.h"
#include "kumite/core/skinned_mesh_facing.h"
#include "kumite/core/skinned_mesh_flat.h"

#include <QMatrix4x4>

#include <algorithm>

namespace kumite::view {
namespace {

const char* k_skinned_vertex = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in uvec4 joints;
layout(location = 3) in vec4 weights;
layout(location = 4) in vec3 colour_in; // linear, the vertex's material
uniform sampler2D skin_texture; // row j: joint j's skin matrix, one column per texel
uniform mat4 view;
uniform mat4 view_projection;
out vec3 normal_eye;
out vec3 position_eye;
out vec3 colour;
mat4 skin_of(uint joint) {
    int row = int(joint);
    return mat4(texelFetch(skin_texture, ivec2(0, row), 0), texelFetch(skin_texture, ivec2(1, row), 0),
                texelFetch(skin_texture, ivec2(2, row), 0), texelFetch(skin_texture, ivec2(3, row), 0));
}
void main() {
    mat4 skin = weights.x * skin_of(joints.x) + weights.y * skin_of(joints.y) + weights.z * skin_of(joints.z) + weights.w * skin_of(joints.w);
    vec4 world = skin * vec4(position, 1.0);
    normal_eye = mat3(view) * normalize(mat3(skin) * normal);
    position_eye = (view * world).xyz;
    colour = colour_in;
    gl_Position = view_projection * world;
})";
const char* k_skinned_fragment = R"(#version 330 core
in vec3 normal_eye;
in vec3 position_eye;
in vec3 colour;
uniform bool flat_shading; // each triangle's own normal, from the screen derivatives (it faces the eye)
out vec4 fragment;
void main() {
    vec3 n;
    if (flat_shading) {
        n = normalize(cross(dFdx(position_eye), dFdy(position_eye)));
    } else {
        n = normalize(normal_eye);
        if (!gl_FrontFacing) n = -n;
    }
    vec3 light = normalize(vec3(-0.3, 0.6, 1.0));  // the capsules' head light
    float diffuse = max(dot(n, light), 0.0);
    // Powers by multiplication: a pow() per pixel is what a software renderer (a headset's eyes drawn on the CPU)
    // spends most on.
    float edge = 1.0 - max(n.z, 0.0);
    float rim = edge * edge * edge;
    float s = max(dot(reflect(-light, n), vec3(0.0, 0.0, 1.0)), 0.0);
    float s2 = s * s, s4 = s2 * s2, s8 = s4 * s4;
    float specular = s8 * s8 * s8; // s^24
    // Lit in linear light (glTF's colours are linear), written as the screen shows it: gamma 2 (a square root,
    // close to sRGB's curve).
    vec3 lit = colour * (0.28 + 0.72 * diffuse) + vec3(0.04) * specular + colour * 0.25 * rim;
    fragment = vec4(sqrt(lit), 1.0);
})";


} // namespace

// Vertex and index buffers of one mesh.
struct BodyGlRenderer::GpuMesh {
    QOpenGLVertexArrayObject vao;
    QOpenGLBuffer vertices{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer indices{QOpenGLBuffer::IndexBuffer};
    int index_count = 0;
    void destroy() { vao.destroy(), vertices.destroy(), indices.destroy(); }
};

// A SkinnedMesh on the GPU, and how its triangles face.
struct BodyGlRenderer::Uploaded {
    std::shared_ptr<const SkinnedMesh> mesh; // kept alive: its address keys the upload
    GpuMesh full;
    std::unique_ptr<GpuMesh> coarse; // for small views, made when first needed
    GLenum cull = GL_NONE; // GL_BACK or GL_FRONT when the winding is consistent, else nothing culled
    bool flat = false;     // flat-shaded: uploaded welded, normals from the screen derivatives
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

void BodyGlRenderer::upload(const SkinnedMesh& mesh, GpuMesh& gpu) {
    // Interleaved: position (3 floats), normal (3 floats), joints (4 u16), weights (4 floats), colour (3 floats).
    struct Vertex {
        float position[3], normal[3];
        std::uint16_t joints[4];
        float weights[4];
        float colour[3];
    };
    std::vector<Vertex> vertices(mesh.vertex_count());
    const bool coloured = mesh.colours.size() == mesh.vertex_count();
    for (std::size_t v = 0; v < vertices.size(); ++v) {
        for (int c = 0; c < 3; ++c) vertices[v].position[c] = mesh.positions[v][c], vertices[v].normal[c] = mesh.normals[v][c];
        for (int k = 0; k < 4; ++k) vertices[v].joints[k] = mesh.joints[v][k], vertices[v].weights[k] = mesh.weights[v][k];
        for (int c = 0; c < 3; ++c) vertices[v].colour[c] = coloured ? mesh.colours[v][std::size_t(c)] : mesh.base_colour[std::size_t(c)];
    }
    gpu.vao.create();
    gpu.vao.bind();
    gpu.vertices.create();
    gpu.vertices.bind();
    gpu.vertices.allocate(vertices.data(), int(vertices.size() * sizeof(Vertex)));
    gpu.indices.create();
    gpu.indices.bind();
    gpu.indices.allocate(mesh.triangles.data(), int(mesh.triangles.size() * sizeof(std::uint32_t)));
    gpu.index_count = int(mesh.triangles.size());
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, normal)));
    glEnableVertexAttribArray(2);
    glVertexAttribIPointer(2, 4, GL_UNSIGNED_SHORT, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, joints)));
    glEnableVertexAttribArray(3);
    glVertexAttribPointer(3, 4, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, weights)));
    glEnableVertexAttribArray(4);
    glVertexAttribPointer(4, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, colour)));
    gpu.vao.release();
}

BodyGlRenderer::Uploaded& BodyGlRenderer::uploaded(const std::shared_ptr<const SkinnedMesh>& mesh) {
    for (const auto& entry : m_meshes) {
        if (entry->mesh == mesh) return *entry;
    }
    auto entry = std::make_unique<Uploaded>();
    entry->mesh = mesh;
    // A flat-shaded body goes up welded (skinned_mesh_flat.h): a quarter of the vertices to skin, the same picture.
    entry->flat = skinned_mesh_is_flat_shaded(*mesh);
    upload(entry->flat ? skinned_mesh_welded(*mesh) : *mesh, entry->full);
    // Back faces are culled only where the winding agrees with the normals nearly everywhere (half the triangles
    // rasterised); a mix (an open or hand-edited mesh) is drawn two-sided.
    const double front = skinned_mesh_front_facing_share(*mesh);
    entry->cull = front > 0.98 ? GL_BACK : front < 0.02 ? GL_FRONT : GL_NONE;
    ++m_uploads;
    m_meshes.push_back(std::move(entry));
    return *m_meshes.back();
}

BodyGlRenderer::GpuMesh& BodyGlRenderer::coarse(Uploaded& mesh) {
    if (!mesh.coarse) {
        // A flat-shaded body is decimated welded (its corners joined, so the surface is one piece to fold); any
        // other as it is (no copy).
        const SkinnedMesh welded = mesh.flat ? skinned_mesh_welded(*mesh.mesh) : SkinnedMesh{};
        const SkinnedMesh& source = mesh.flat ? welded : *mesh.mesh;
        mesh.coarse = std::make_unique<GpuMesh>();
        upload(skinned_mesh_decimated(source, {source.triangles.size() / 9, 0.005}), *mesh.coarse);
    }
    return *mesh.coarse;
}

void BodyGlRenderer::draw(const std::vector<SkinnedBody>& bodies, const Eigen::Matrix4f& view, const Eigen::Matrix4f& view_projection, int view_height_px) {
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
        // The texture's storage is made again only when a body has more joints than it holds.
        if (int(body.skin.size()) > m_skin_rows) {
            m_skin_rows = int(body.skin.size());
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 4, m_skin_rows, 0, GL_RGBA, GL_FLOAT, nullptr);
        }
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, GLsizei(body.skin.size()), GL_RGBA, GL_FLOAT, body.skin.data());
        if (mesh.cull != GL_NONE) glEnable(GL_CULL_FACE), glCullFace(mesh.cull);
        m_program.setUniformValue("flat_shading", mesh.flat);
        GpuMesh& gpu = view_height_px <= k_coarse_view_px ? coarse(mesh) : mesh.full;
        gpu.vao.bind();
        glDrawElements(GL_TRIANGLES, gpu.index_count, GL_UNSIGNED_INT, nullptr);
        glDisable(GL_CULL_FACE);
    }
    glBindVertexArray(0);
    glBindTexture(GL_TEXTURE_2D, 0);
    m_program.release();
}

void BodyGlRenderer::release() {
    for (const auto& entry : m_meshes) {
        entry->full.destroy();
        if (entry->coarse) entry->coarse->destroy();
    }
    m_meshes.clear();
    if (m_skin_texture != 0) glDeleteTextures(1, &m_skin_texture);
    m_skin_rows = 0;
    m_skin_texture = 0;
    m_ready = false;
}

} // namespace kumite::view
