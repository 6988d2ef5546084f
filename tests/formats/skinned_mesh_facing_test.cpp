// Which way bodies' triangles face (skinned_mesh_facing.h: back faces are culled only when it is clear), which are
// flat-shaded and drawn welded (skinned_mesh_flat.h), and the headset's human body's colours.

#include "kumite/core/skinned_mesh_facing.h"
#include "kumite/core/skinned_mesh_flat.h"
#include "kumite/formats/gltf_reader.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <set>

using namespace kumite;

namespace {

std::filesystem::path human_body() { return kumite::test::source_dir() / "data/bodies/quaternius-adventurer/Adventurer.glb"; }

std::vector<std::filesystem::path> bodies() {
    std::vector<std::filesystem::path> out = {human_body()};
    for (const char* name : {"kid", "scout", "brawler", "runner", "giant"}) out.push_back(kumite::test::source_dir() / "data/characters" / (std::string(name) + ".glb"));
    return out;
}

// A strip of two triangles, both wound counter-clockwise seen from +Z, normals +Z, on joint 0.
SkinnedMesh strip() {
    SkinnedMesh mesh;
    for (const Eigen::Vector3f& p : {Eigen::Vector3f(0, 0, 0), Eigen::Vector3f(1, 0, 0), Eigen::Vector3f(1, 1, 0), Eigen::Vector3f(0, 1, 0)}) {
        mesh.positions.push_back(p), mesh.normals.push_back(Eigen::Vector3f::UnitZ());
        mesh.joints.push_back({0, 0, 0, 0}), mesh.weights.push_back({1, 0, 0, 0});
    }
    mesh.triangles = {0, 1, 2, 0, 2, 3};
    mesh.bind_to_rest = {Eigen::Matrix4f::Identity()};
    return mesh;
}

} // namespace

TEST_CASE("skinned mesh facing: the shipped bodies face outwards, so their back faces can be culled", "[formats]") {
    for (const std::filesystem::path& path : bodies()) {
        INFO(path.filename().string());
        Result<GltfCharacter> read = gltf_read_file(path);
        REQUIRE(read.has_value());
        CHECK(skinned_mesh_front_facing_share(read->mesh) > 0.98);
    }
    SkinnedMesh mesh = strip();
    CHECK(skinned_mesh_front_facing_share(mesh) == Approx(1.0));
    std::swap(mesh.triangles[1], mesh.triangles[2]); // the first triangle turned round: half the area each way
    CHECK(skinned_mesh_front_facing_share(mesh) == Approx(0.5));
    std::swap(mesh.triangles[4], mesh.triangles[5]);
    CHECK(skinned_mesh_front_facing_share(mesh) == Approx(0.0));
}

TEST_CASE("gltf: the headset's human body reads with its materials' colours on its vertices", "[formats]") {
    Result<GltfCharacter> read = gltf_read_file(human_body());
    REQUIRE(read.has_value());
    const SkinnedMesh& mesh = read->mesh;
    REQUIRE(mesh.colours.size() == mesh.vertex_count());
    std::set<std::array<float, 3>> distinct(mesh.colours.begin(), mesh.colours.end());
    CHECK(distinct.size() >= 8); // skin, hair, eyes, clothes, leather, gold ...
    CHECK(read->character.height_m == Approx(1.86).margin(0.05));
    // A shipped mannequin: one material, every vertex its colour.
    Result<GltfCharacter> scout = gltf_read_file(kumite::test::source_dir() / "data/characters/scout.glb");
    REQUIRE(scout.has_value());
    for (const auto& colour : scout->mesh.colours) CHECK(colour == (std::array<float, 3>{scout->mesh.base_colour[0], scout->mesh.base_colour[1], scout->mesh.base_colour[2]}));
}

TEST_CASE("skinned mesh flat: the low-poly human is flat-shaded and welds to a third of its vertices, triangles and skinning kept", "[formats]") {
    Result<GltfCharacter> human = gltf_read_file(human_body());
    REQUIRE(human.has_value());
    const SkinnedMesh& mesh = human->mesh;
    CHECK(skinned_mesh_is_flat_shaded(mesh));
    const SkinnedMesh welded = skinned_mesh_welded(mesh);
    INFO("vertices " << mesh.vertex_count() << " -> " << welded.vertex_count());
    CHECK(welded.vertex_count() * 3 <= mesh.vertex_count());
    REQUIRE(welded.triangles.size() == mesh.triangles.size());
    REQUIRE(welded.colours.size() == welded.vertex_count());
    // Every corner of every triangle where it was, on the same joints with the same weights, in the same colour.
    std::size_t differing = 0;
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        const std::uint32_t before = mesh.triangles[i], after = welded.triangles[i];
        REQUIRE(after < welded.vertex_count());
        differing += welded.positions[after] != mesh.positions[before] || welded.joints[after] != mesh.joints[before] ||
                     welded.weights[after] != mesh.weights[before] || welded.colours[after] != mesh.colours[before];
    }
    CHECK(differing == 0);
    // The mannequins are smooth: drawn as they are.
    for (const char* name : {"kid", "scout", "brawler", "runner", "giant"}) {
        INFO(name);
        Result<GltfCharacter> read = gltf_read_file(kumite::test::source_dir() / "data/characters" / (std::string(name) + ".glb"));
        REQUIRE(read.has_value());
        CHECK_FALSE(skinned_mesh_is_flat_shaded(read->mesh));
    }
}
