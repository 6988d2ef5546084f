// The coarse bodies drawn in small views (skinned_mesh_decimate.h): a third of the human's triangles, every kept
// vertex as it was, no gap opened, nothing turned over, the surface where it was.

#include "kumite/core/skinned_mesh_decimate.h"
#include "kumite/core/skinned_mesh_facing.h"
#include "kumite/core/skinned_mesh_flat.h"
#include "kumite/formats/gltf_reader.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <iostream>
#include <map>
#include <set>

using namespace kumite;

namespace {

// Distance from p to the triangle abc (Ericson, Real-Time Collision Detection 5.1.5).
double point_triangle_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0) return (p - a).norm();
    const Eigen::Vector3d bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3) return (p - b).norm();
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).norm();
    const Eigen::Vector3d cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6) return (p - c).norm();
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).norm();
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
    const double denom = 1.0 / (va + vb + vc);
    return (p - (a + ab * vb * denom + ac * vc * denom)).norm();
}

// The farthest any vertex of `from` lies from the surface of `to`.
double farthest_from_surface(const SkinnedMesh& from, const SkinnedMesh& to) {
    double farthest = 0.0;
    for (const Eigen::Vector3f& v : from.positions) {
        double nearest = 1e9;
        for (std::size_t t = 0; t + 2 < to.triangles.size(); t += 3) {
            nearest = std::min(nearest, point_triangle_distance(v.cast<double>(), to.positions[to.triangles[t]].cast<double>(),
                                                                to.positions[to.triangles[t + 1]].cast<double>(), to.positions[to.triangles[t + 2]].cast<double>()));
        }
        farthest = std::max(farthest, nearest);
    }
    return farthest;
}

// The mesh's open edges (used by one triangle), as pairs of positions.
std::set<std::array<float, 6>> open_edges(const SkinnedMesh& mesh) {
    std::map<std::array<float, 6>, int> uses;
    for (std::size_t t = 0; t + 2 < mesh.triangles.size(); t += 3) {
        for (int k = 0; k < 3; ++k) {
            Eigen::Vector3f a = mesh.positions[mesh.triangles[t + k]], b = mesh.positions[mesh.triangles[t + (k + 1) % 3]];
            if (std::lexicographical_compare(b.data(), b.data() + 3, a.data(), a.data() + 3)) std::swap(a, b);
            ++uses[{a.x(), a.y(), a.z(), b.x(), b.y(), b.z()}];
        }
    }
    std::set<std::array<float, 6>> out;
    for (const auto& [edge, count] : uses) {
        if (count == 1) out.insert(edge);
    }
    return out;
}

// A flat square of n x n quads in the XY plane, wound towards +Z, on joint 0.
SkinnedMesh grid(int n) {
    SkinnedMesh mesh;
    for (int y = 0; y <= n; ++y) {
        for (int x = 0; x <= n; ++x) {
            mesh.positions.emplace_back(float(x) / float(n), float(y) / float(n), 0.0f);
            mesh.normals.push_back(Eigen::Vector3f::UnitZ());
            mesh.joints.push_back({0, 0, 0, 0}), mesh.weights.push_back({1, 0, 0, 0});
        }
    }
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            const auto v = std::uint32_t(y * (n + 1) + x);
            mesh.triangles.insert(mesh.triangles.end(), {v, v + 1, v + std::uint32_t(n) + 2, v, v + std::uint32_t(n) + 2, v + std::uint32_t(n) + 1});
        }
    }
    mesh.bind_to_rest = {Eigen::Matrix4f::Identity()};
    return mesh;
}

} // namespace

TEST_CASE("decimate: the human's coarse body has a third of the triangles, its vertices as they were, no gap, nothing turned over", "[formats]") {
    Result<GltfCharacter> read = gltf_read_file(kumite::test::source_dir() / "data/bodies/quaternius-adventurer/Adventurer.glb");
    REQUIRE(read.has_value());
    const SkinnedMesh welded = skinned_mesh_welded(read->mesh);
    const std::size_t triangles = welded.triangles.size() / 3;
    const SkinnedMesh coarse = skinned_mesh_decimated(welded, {triangles / 3, 0.005});
    const std::size_t coarse_triangles = coarse.triangles.size() / 3;
    INFO("triangles " << triangles << " -> " << coarse_triangles << ", vertices " << welded.vertex_count() << " -> " << coarse.vertex_count());
    CHECK(coarse_triangles <= triangles * 35 / 100);
    CHECK(coarse_triangles >= triangles / 4);
    // Every vertex kept bit for bit: position, skinning, colour.
    std::set<std::vector<char>> original;
    auto bytes = [](const SkinnedMesh& m, std::size_t v) {
        std::vector<char> out(sizeof(float) * 3 + sizeof(m.joints[v]) + sizeof(m.weights[v]) + sizeof(m.colours[v]));
        std::memcpy(out.data(), m.positions[v].data(), sizeof(float) * 3);
        std::memcpy(out.data() + 12, m.joints[v].data(), sizeof(m.joints[v]));
        std::memcpy(out.data() + 12 + sizeof(m.joints[v]), m.weights[v].data(), sizeof(m.weights[v]));
        std::memcpy(out.data() + 12 + sizeof(m.joints[v]) + sizeof(m.weights[v]), m.colours[v].data(), sizeof(m.colours[v]));
        return out;
    };
    for (std::size_t v = 0; v < welded.vertex_count(); ++v) original.insert(bytes(welded, v));
    REQUIRE(coarse.colours.size() == coarse.vertex_count());
    std::size_t kept = 0;
    for (std::size_t v = 0; v < coarse.vertex_count(); ++v) kept += original.count(bytes(coarse, v));
    CHECK(kept == coarse.vertex_count());
    CHECK(coarse.bind_to_rest.size() == welded.bind_to_rest.size());
    // The seams and open edges of the parts (head, body, legs, feet, backpack) are where they were: no gap opens.
    CHECK(open_edges(coarse) == open_edges(welded));
    // Nothing turned over: each coarse triangle faces the way the full surface did at its corners (the full mesh's
    // triangle normals summed at each vertex, by the winding: the welded mesh's own normals mean nothing).
    std::map<std::array<float, 3>, Eigen::Vector3d> facing;
    for (std::size_t t = 0; t + 2 < welded.triangles.size(); t += 3) {
        const Eigen::Vector3f &a = welded.positions[welded.triangles[t]], &b = welded.positions[welded.triangles[t + 1]], &c = welded.positions[welded.triangles[t + 2]];
        const Eigen::Vector3d face = (b - a).cross(c - a).cast<double>();
        for (const Eigen::Vector3f* p : {&a, &b, &c}) {
            auto [it, added] = facing.try_emplace({p->x(), p->y(), p->z()}, Eigen::Vector3d::Zero());
            it->second += face;
        }
    }
    auto against = [&](const SkinnedMesh& m) {
        std::size_t turned = 0;
        for (std::size_t t = 0; t + 2 < m.triangles.size(); t += 3) {
            const Eigen::Vector3f &a = m.positions[m.triangles[t]], &b = m.positions[m.triangles[t + 1]], &c = m.positions[m.triangles[t + 2]];
            Eigen::Vector3d was = Eigen::Vector3d::Zero();
            for (const Eigen::Vector3f* p : {&a, &b, &c}) was += facing.at({p->x(), p->y(), p->z()});
            turned += (b - a).cross(c - a).cast<double>().dot(was) < 0.0;
        }
        return turned;
    };
    const std::size_t turned = against(coarse), turned_full = against(welded);
    INFO(turned << " coarse triangles face against the full surface (" << turned_full << " of the full mesh's by this measure)");
    CHECK(turned <= turned_full);
    // The full body's every vertex is near the coarse surface.
    const double farthest = farthest_from_surface(welded, coarse);
    std::cout << "coarse human: " << triangles << " -> " << coarse_triangles << " triangles, " << turned
              << " facing against the full surface (full mesh " << turned_full << "), farthest full vertex "
              << farthest * 1000.0 << " mm\n";
    INFO("farthest full-body vertex from the coarse surface " << farthest * 1000.0 << " mm");
    CHECK(farthest < 0.005);
}

TEST_CASE("decimate: a flat grid folds down to a few triangles on its plane, its border held; a bad mesh comes back as it was", "[formats]") {
    const SkinnedMesh flat = grid(8);
    const SkinnedMesh coarse = skinned_mesh_decimated(flat, {0, 0.001});
    // Only the 32 border vertices are held: the inside folds away, the border's edges stay.
    CHECK(coarse.triangles.size() / 3 < flat.triangles.size() / 3 / 2);
    CHECK(open_edges(coarse) == open_edges(flat));
    for (const Eigen::Vector3f& p : coarse.positions) CHECK(p.z() == 0.0f);
    CHECK(skinned_mesh_front_facing_share(coarse) == Approx(1.0));
    // Skinned apart (the right half on joint 1): a vertex is folded into a neighbour skinned alike first.
    SkinnedMesh two = grid(8);
    for (std::size_t v = 0; v < two.vertex_count(); ++v) {
        if (two.positions[v].x() > 0.5f) two.joints[v] = {1, 0, 0, 0};
    }
    two.bind_to_rest.push_back(Eigen::Matrix4f::Identity());
    const SkinnedMesh halves = skinned_mesh_decimated(two, {0, 0.001});
    CHECK(halves.triangles.size() < two.triangles.size() * 2 / 3);
    // Bent 90 degrees at x = 0.5 (joint 1 turns about the line there): the folded grid bends with it, no vertex of
    // the full grid off the coarse one by more than a millimetre.
    auto bent = [](const SkinnedMesh& m) {
        SkinnedMesh out = m;
        const Eigen::Affine3f turn = Eigen::Translation3f(0.5f, 0, 0) * Eigen::AngleAxisf(1.5708f, Eigen::Vector3f::UnitY()) * Eigen::Translation3f(-0.5f, 0, 0);
        for (std::size_t v = 0; v < m.vertex_count(); ++v) {
            if (m.joints[v][0] == 1) out.positions[v] = turn * m.positions[v];
        }
        return out;
    };
    CHECK(farthest_from_surface(bent(two), bent(halves)) < 0.001);
    SkinnedMesh broken = grid(2);
    broken.triangles.back() = 1000;
    CHECK(skinned_mesh_decimated(broken, {1, 0.01}).triangles == broken.triangles);
}
