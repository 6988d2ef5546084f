#include "kumite/core/skinned_mesh_decimate.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <queue>
#include <unordered_map>
#include <vector>

namespace kumite {
namespace {

constexpr double k_min_normal_cos = 0.5;     // a triangle around the folded vertex turns by less than 60 degrees
constexpr double k_min_quality = 0.1;        // nor becomes a sliver (area over longest edge squared, ~0.43 equilateral)
constexpr double k_min_facing_cos = 0.2;     // and faces within 78 degrees of the full surface at its corners
constexpr double k_skin_step = 0.5;          // neighbours this differently skinned hold their places

double skin_difference(const SkinnedMesh& mesh, std::uint32_t a, std::uint32_t b) {
    // Half the L1 distance between the two weight vectors over joints: 0 skinned alike, 1 nothing shared.
    double shared = 0.0;
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            if (mesh.joints[a][i] == mesh.joints[b][j]) shared += std::min(mesh.weights[a][i], mesh.weights[b][j]);
        }
    }
    return std::clamp(1.0 - shared, 0.0, 1.0);
}

double quality(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    const double longest = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    return longest > 0.0 ? 0.5 * (b - a).cross(c - a).norm() / longest : 0.0;
}

struct Candidate {
    double cost;
    std::uint32_t from, to;
    std::uint32_t from_stamp, to_stamp;
    bool operator>(const Candidate& other) const { return cost > other.cost; }
};

class Decimator {
public:
    Decimator(const SkinnedMesh& mesh, const DecimationLimits& limits) : m_mesh(mesh), m_limits(limits) {}

    SkinnedMesh run() {
        const std::size_t n = m_mesh.vertex_count();
        m_position.resize(n);
        for (std::size_t v = 0; v < n; ++v) m_position[v] = m_mesh.positions[v].cast<double>();
        m_quadric.assign(n, Eigen::Matrix4d::Zero());
        m_facing.assign(n, Eigen::Vector3d::Zero());
        m_planes.assign(n, 0);
        m_stamp.assign(n, 0);
        m_alive_vertex.assign(n, true);
        m_locked.assign(n, false);
        m_faces.assign(n, {});
        m_triangles = m_mesh.triangles;
        m_alive_triangle.assign(m_triangles.size() / 3, true);
        std::unordered_map<std::uint64_t, int> edge_uses;
        for (std::size_t t = 0; t < m_alive_triangle.size(); ++t) {
            const std::uint32_t* c = &m_triangles[3 * t];
            const Eigen::Vector3d normal = (m_position[c[1]] - m_position[c[0]]).cross(m_position[c[2]] - m_position[c[0]]);
            for (int k = 0; k < 3; ++k) m_facing[c[k]] += normal; // area-weighted
            if (normal.norm() > 0.0) {
                const Eigen::Vector3d unit = normal.normalized();
                const Eigen::Vector4d plane(unit.x(), unit.y(), unit.z(), -unit.dot(m_position[c[0]]));
                for (int k = 0; k < 3; ++k) m_quadric[c[k]] += plane * plane.transpose(), ++m_planes[c[k]];
            }
            for (int k = 0; k < 3; ++k) {
                m_faces[c[k]].push_back(std::uint32_t(t));
                ++edge_uses[edge_key(c[k], c[(k + 1) % 3])];
            }
        }
        // Open edges and seams (used by one triangle) and non-manifold ones (more than two) hold their vertices.
        // So do the ends of an edge where the skinning steps (half or more of the weight on other joints): a rigidly
        // skinned body's joints, where the parts move apart.
        for (const auto& [key, uses] : edge_uses) {
            const auto a = std::uint32_t(key >> 32), b = std::uint32_t(key & 0xffffffffu);
            if (uses != 2 || skin_difference(m_mesh, a, b) >= k_skin_step) m_locked[a] = m_locked[b] = true;
        }
        for (const auto& [key, uses] : edge_uses) {
            const auto a = std::uint32_t(key >> 32), b = std::uint32_t(key & 0xffffffffu);
            push(a, b), push(b, a);
        }
        std::size_t triangles = m_alive_triangle.size();
        const double max_cost = m_limits.max_error_m * m_limits.max_error_m;
        while (triangles > m_limits.target_triangles && !m_queue.empty()) {
            const Candidate best = m_queue.top();
            m_queue.pop();
            const bool stale = !m_alive_vertex[best.from] || !m_alive_vertex[best.to] || best.from_stamp != m_stamp[best.from] ||
                               best.to_stamp != m_stamp[best.to];
            if (stale) continue;
            if (best.cost > max_cost) break;
            if (!collapsible(best.from, best.to)) continue;
            triangles -= collapse(best.from, best.to);
        }
        return output();
    }

private:
    static std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
        return (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
    }

    // Mean squared distance of `to`'s position from both vertices' planes, plus the skinning's share.
    double cost(std::uint32_t from, std::uint32_t to) const {
        const Eigen::Vector4d p(m_position[to].x(), m_position[to].y(), m_position[to].z(), 1.0);
        const int planes = std::max(1, m_planes[from] + m_planes[to]);
        const double surface = std::max(0.0, p.dot((m_quadric[from] + m_quadric[to]) * p)) / planes;
        return surface + skin_difference(m_mesh, from, to) * (m_position[from] - m_position[to]).squaredNorm();
    }

    void push(std::uint32_t from, std::uint32_t to) {
        if (m_locked[from]) return;
        m_queue.push({cost(from, to), from, to, m_stamp[from], m_stamp[to]});
    }

    void neighbours(std::uint32_t v, std::vector<std::uint32_t>& out) const {
        out.clear();
        for (const std::uint32_t t : m_faces[v]) {
            if (!m_alive_triangle[t]) continue;
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t w = m_triangles[3 * t + k];
                if (w != v && std::find(out.begin(), out.end(), w) == out.end()) out.push_back(w);
            }
        }
    }

    bool collapsible(std::uint32_t from, std::uint32_t to) {
        // Link condition: the vertices both are joined to are exactly the far corners of the edge's two triangles.
        neighbours(from, m_from_ring);
        neighbours(to, m_to_ring);
        if (std::find(m_from_ring.begin(), m_from_ring.end(), to) == m_from_ring.end()) return false;
        int shared = 0, edge_triangles = 0;
        for (const std::uint32_t w : m_from_ring) shared += std::find(m_to_ring.begin(), m_to_ring.end(), w) != m_to_ring.end();
        for (const std::uint32_t t : m_faces[from]) {
            if (!m_alive_triangle[t]) continue;
            const std::uint32_t* c = &m_triangles[3 * t];
            if (c[0] == to || c[1] == to || c[2] == to) ++edge_triangles;
        }
        if (edge_triangles != 2 || shared != 2) return false;
        // The triangles that stay: none turns over or becomes a sliver.
        for (const std::uint32_t t : m_faces[from]) {
            if (!m_alive_triangle[t]) continue;
            const std::uint32_t* c = &m_triangles[3 * t];
            if (c[0] == to || c[1] == to || c[2] == to) continue;
            Eigen::Vector3d before[3], after[3];
            for (int k = 0; k < 3; ++k) {
                before[k] = m_position[c[k]];
                after[k] = c[k] == from ? m_position[to] : m_position[c[k]];
            }
            const Eigen::Vector3d n0 = (before[1] - before[0]).cross(before[2] - before[0]), n1 = (after[1] - after[0]).cross(after[2] - after[0]);
            if (!(n1.norm() > 0.0) || !(n0.norm() > 0.0)) return false;
            if (n0.normalized().dot(n1.normalized()) < k_min_normal_cos) return false;
            // Nor, over many collapses, away from the way the full surface faced at its corners.
            const Eigen::Vector3d was = m_facing[c[0] == from ? to : c[0]] + m_facing[c[1] == from ? to : c[1]] + m_facing[c[2] == from ? to : c[2]];
            if (!(was.norm() > 0.0) || n1.normalized().dot(was.normalized()) < k_min_facing_cos) return false;
            const double quality_after = quality(after[0], after[1], after[2]);
            if (quality_after < k_min_quality && quality_after < quality(before[0], before[1], before[2])) return false;
        }
        return true;
    }

    // Folds `from` into `to`; returns how many triangles went.
    std::size_t collapse(std::uint32_t from, std::uint32_t to) {
        std::size_t removed = 0;
        for (const std::uint32_t t : m_faces[from]) {
            if (!m_alive_triangle[t]) continue;
            std::uint32_t* c = &m_triangles[3 * t];
            if (c[0] == to || c[1] == to || c[2] == to) {
                m_alive_triangle[t] = false;
                ++removed;
                continue;
            }
            for (int k = 0; k < 3; ++k) c[k] = c[k] == from ? to : c[k];
            m_faces[to].push_back(t);
        }
        m_faces[from].clear();
        m_alive_vertex[from] = false;
        m_quadric[to] += m_quadric[from];
        m_planes[to] += m_planes[from];
        // Only the edges at `to` cost otherwise now: they are queued again (the old entries go stale); whether any
        // other collapse is still allowed is asked when it comes up.
        ++m_stamp[to];
        neighbours(to, m_to_ring);
        for (const std::uint32_t w : m_to_ring) push(w, to), push(to, w);
        return removed;
    }

    SkinnedMesh output() const {
        SkinnedMesh out;
        out.base_colour = m_mesh.base_colour;
        out.bind_to_rest = m_mesh.bind_to_rest;
        const bool coloured = m_mesh.colours.size() == m_mesh.vertex_count();
        std::vector<std::uint32_t> index(m_mesh.vertex_count(), 0);
        std::vector<bool> used(m_mesh.vertex_count(), false);
        for (std::size_t t = 0; t < m_alive_triangle.size(); ++t) {
            if (m_alive_triangle[t]) used[m_triangles[3 * t]] = used[m_triangles[3 * t + 1]] = used[m_triangles[3 * t + 2]] = true;
        }
        for (std::size_t v = 0; v < m_mesh.vertex_count(); ++v) {
            if (!used[v]) continue;
            index[v] = std::uint32_t(out.positions.size());
            out.positions.push_back(m_mesh.positions[v]);
            out.normals.push_back(m_mesh.normals[v]);
            out.joints.push_back(m_mesh.joints[v]);
            out.weights.push_back(m_mesh.weights[v]);
            if (coloured) out.colours.push_back(m_mesh.colours[v]);
        }
        for (std::size_t t = 0; t < m_alive_triangle.size(); ++t) {
            if (!m_alive_triangle[t]) continue;
            for (int k = 0; k < 3; ++k) out.triangles.push_back(index[m_triangles[3 * t + k]]);
        }
        return out;
    }

    const SkinnedMesh& m_mesh;
    DecimationLimits m_limits;
    std::vector<Eigen::Vector3d> m_position;
    std::vector<Eigen::Matrix4d> m_quadric;
    std::vector<Eigen::Vector3d> m_facing; // [vertex] the full mesh's triangle normals there, summed by area
    std::vector<int> m_planes;
    std::vector<std::uint32_t> m_stamp;
    std::vector<bool> m_alive_vertex, m_locked, m_alive_triangle;
    std::vector<std::vector<std::uint32_t>> m_faces; // [vertex] triangles that used it (some since removed)
    std::vector<std::uint32_t> m_triangles;
    std::priority_queue<Candidate, std::vector<Candidate>, std::greater<>> m_queue;
    std::vector<std::uint32_t> m_from_ring, m_to_ring;
};

} // namespace

SkinnedMesh skinned_mesh_decimated(const SkinnedMesh& mesh, const DecimationLimits& limits) {
    const std::size_t n = mesh.vertex_count();
    const bool consistent = mesh.normals.size() == n && mesh.joints.size() == n && mesh.weights.size() == n && mesh.triangles.size() % 3 == 0 &&
                            std::all_of(mesh.triangles.begin(), mesh.triangles.end(), [n](std::uint32_t v) { return v < n; });
    if (!consistent || mesh.triangles.size() / 3 <= limits.target_triangles) return mesh;
    return Decimator(mesh, limits).run();
}

} // namespace kumite
