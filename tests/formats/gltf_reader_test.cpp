// glTF characters: the shipped bodies read as the same skeletons as their BVH files, with a skinned mesh that the
// rest pose gives back; hostile files (truncated, indices or joints out of range, NaN, no skin, a million joints
// claimed, a node cycle, not glTF) are refused with a message naming what and where.

#include "kumite/core/forward_kinematics.h"
#include "kumite/formats/character_catalog.h"
#include "kumite/formats/gltf_reader.h"
#include "support/glb_edit.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

using namespace kumite;
using kumite::test::Glb;
using kumite::test::read_bytes;

namespace {

const char* k_names[] = {"kid", "scout", "brawler", "runner", "giant"};

std::filesystem::path shipped(const char* name) { return kumite::test::source_dir() / "data/characters" / (std::string(name) + ".glb"); }

std::string refusal(const std::vector<std::uint8_t>& bytes) {
    Result<GltfCharacter> read = gltf_parse(bytes, "hostile.glb");
    REQUIRE_FALSE(read.has_value());
    INFO(read.error().message);
    CHECK_THAT(read.error().message, Catch::StartsWith("hostile.glb: "));
    return read.error().message;
}

} // namespace

TEST_CASE("gltf: the shipped bodies read as their BVH skeletons, with a skinned mesh the rest pose gives back", "[formats]") {
    for (const char* name : k_names) {
        INFO(name);
        Result<GltfCharacter> read = gltf_read_file(shipped(name));
        REQUIRE(read.has_value());
        Result<BvhFile> bvh = bvh_read_file(kumite::test::source_dir() / "data/characters" / (std::string(name) + ".bvh"));
        REQUIRE(bvh.has_value());
        const Skeleton& ours = read->character.clip.skeleton;
        const Skeleton& theirs = bvh->clip.skeleton;
        REQUIRE(ours.joint_count() == theirs.joint_count());
        std::vector<Eigen::Vector3d> gltf_positions(ours.joint_count()), bvh_positions(theirs.joint_count());
        std::vector<Eigen::Quaterniond> rotations(ours.joint_count());
        forward_kinematics(gltf_positions, rotations, ours, read->character.clip.pose(0));
        const Pose bvh_rest = bvh->clip.rest_pose();
        forward_kinematics(bvh_positions, rotations, theirs, bvh_rest.view());
        for (int j = 0; j < ours.joint_count(); ++j) {
            const int k = *theirs.find(ours.names[j]);
            CHECK((gltf_positions[j] - bvh_positions[k]).norm() < 1e-6);
        }
        // The leaf joints' End Sites come from the mesh: the toe's is the tip of a foot that rests on the floor
        // with its radius (make_character_bodies.py), so the glTF character stands up to 2 cm shorter.
        CHECK(read->character.height_m == Approx(bvh->height_m).margin(0.02));
        CHECK(read->character.body_map.mapped_count() == bvh->body_map.mapped_count());
        const SkinnedMesh& mesh = read->mesh;
        CHECK(mesh.vertex_count() > 1000);
        CHECK(mesh.triangles.size() % 3 == 0);
        REQUIRE(mesh.bind_to_rest.size() == std::size_t(ours.joint_count()));
        // At rest, each vertex skinned by its joints lands where the file put it.
        double worst = 0.0;
        for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
            Eigen::Vector3f skinned = Eigen::Vector3f::Zero();
            float total = 0.0f;
            for (int k = 0; k < 4; ++k) {
                const int joint = mesh.joints[v][k];
                REQUIRE(joint < ours.joint_count());
                Eigen::Matrix4f rest = Eigen::Matrix4f::Identity();
                rest.block<3, 1>(0, 3) = gltf_positions[joint].cast<float>();
                skinned += mesh.weights[v][k] * (rest * mesh.bind_to_rest[joint] * mesh.positions[v].homogeneous()).head<3>();
                total += mesh.weights[v][k];
            }
            CHECK(total == Approx(1.0f).margin(1e-5));
            worst = std::max(worst, double((skinned - mesh.positions[v]).norm()));
        }
        CHECK(worst < 1e-5);
    }
    // Five distinct colours.
    std::vector<std::array<float, 4>> colours;
    for (const char* name : k_names) colours.push_back(gltf_read_file(shipped(name))->mesh.base_colour);
    for (std::size_t a = 0; a < colours.size(); ++a) {
        for (std::size_t b = a + 1; b < colours.size(); ++b) CHECK(colours[a] != colours[b]);
    }
}

TEST_CASE("gltf: the catalogue pairs each shipped BVH with its body, and a .glb path is a character too", "[formats]") {
    const std::vector<CharacterEntry> entries = list_characters(kumite::test::source_dir() / "data/characters");
    REQUIRE(entries.size() == 5);
    for (const CharacterEntry& entry : entries) {
        CHECK(entry.file.extension() == ".bvh");
        CHECK(entry.body.extension() == ".glb");
    }
    Result<BvhFile> by_path = load_character(kumite::test::source_dir() / "data/characters", shipped("giant").string());
    REQUIRE(by_path.has_value());
    CHECK(by_path->height_m == Approx(2.1).margin(0.02));
}

TEST_CASE("gltf: hostile files are refused with what and where, never read out of bounds", "[formats]") {
    const std::vector<std::uint8_t> good = read_bytes(shipped("brawler"));
    REQUIRE(good.size() > 1000);
    REQUIRE(gltf_parse(good, "good.glb").has_value());

    SECTION("truncated") {
        for (std::size_t size : {std::size_t(0), std::size_t(11), std::size_t(30), good.size() / 2, good.size() - 1}) {
            INFO("cut at " << size);
            refusal(std::vector<std::uint8_t>(good.begin(), good.begin() + size));
        }
    }
    SECTION("not glTF") { CHECK_THAT(refusal(std::vector<std::uint8_t>{'h', 'e', 'l', 'l', 'o'}), Catch::Contains("not a valid glTF")); }
    SECTION("an index past the vertices") {
        Glb glb(good);
        const int indices = glb.json["meshes"][0]["primitives"][0]["indices"].get<int>();
        const std::size_t at = glb.offset_of(indices, 5, 2);
        glb.bin[at] = 0xff;
        glb.bin[at + 1] = 0xff;
        CHECK_THAT(refusal(glb.bytes()), Catch::Contains("mesh 0 primitive 0 indices: index 5 is vertex 65535"));
    }
    SECTION("an accessor running past its buffer view") {
        Glb glb(good);
        glb.json["accessors"][glb.attribute("POSITION")]["count"] = 10'000'000;
        CHECK_THAT(refusal(glb.bytes()), Catch::Contains("POSITION: accessor") && Catch::Contains("run past buffer view"));
    }
    SECTION("a joint past the skin's") {
        Glb glb(good);
        const std::size_t at = glb.offset_of(glb.attribute("JOINTS_0"), 3, 8);
        glb.bin[at] = 200;
        CHECK_THAT(refusal(glb.bytes()), Catch::Contains("JOINTS_0: vertex 3 names joint 200 of a skin with 22"));
    }
    SECTION("NaN in a position and in an inverse bind matrix") {
        Glb glb(good);
        const float nan = std::numeric_limits<float>::quiet_NaN();
        std::memcpy(glb.bin.data() + glb.offset_of(glb.attribute("POSITION"), 7, 12) + 4, &nan, 4);
        CHECK_THAT(refusal(glb.bytes()), Catch::Contains("POSITION: vertex 7 is not a finite point"));
        Glb binds(good);
        const int matrices = binds.json["skins"][0]["inverseBindMatrices"].get<int>();
        std::memcpy(binds.bin.data() + binds.offset_of(matrices, 2, 64), &nan, 4);
        CHECK_THAT(refusal(binds.bytes()), Catch::Contains("inverse bind matrix 2"));
    }
    SECTION("no skin") {
        Glb glb(good);
        glb.json.erase("skins");
        for (auto& node : glb.json["nodes"]) node.erase("skin");
        CHECK_THAT(refusal(glb.bytes()), Catch::Contains("no skin"));
    }
    SECTION("a million joints claimed") {
        Glb glb(good);
        std::vector<int> joints(1'000'000, 0);
        glb.json["skins"][0]["joints"] = joints;
        CHECK_THAT(refusal(glb.bytes()), Catch::Contains("1000000 joints"));
    }
    SECTION("not a humanoid") {
        Glb glb(good);
        glb.json["skins"][0]["joints"] = {0, 1, 2, 3, 4};
        CHECK_THAT(refusal(glb.bytes()), Catch::Contains("not a whole humanoid") || Catch::Contains("JOINTS_0"));
    }
    SECTION("a skin from glTF 2.0's draft (jointNames)") {
        const std::string draft = R"({"asset": {"version": "2.0"}, "nodes": [{"jointName": "torso_joint_1"}], "skins": [{"jointNames": ["torso_joint_1"]}]})";
        CHECK_THAT(refusal(std::vector<std::uint8_t>(draft.begin(), draft.end())), Catch::Contains("skin 0 lists \"jointNames\" instead of \"joints\""));
    }
    SECTION("a node that is its own ancestor") {
        Glb glb(good);
        glb.json["nodes"][3]["children"] = {1};
        refusal(glb.bytes());
    }
}
