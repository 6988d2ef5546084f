// Recording a motion as glTF: the shipped bodies moved onto their BVH skeletons (by joint name, rest poses
// checked), a moving clip written as .glb and read back with the same skeleton, rest pose and mesh, the
// animation's frames and times as written; bodies that do not fit the skeleton are refused.

#include "kumite/core/forward_kinematics.h"
#include "kumite/formats/bvh_reader.h"
#include "kumite/formats/character_body.h"
#include "kumite/formats/character_catalog.h"
#include "kumite/formats/gltf_writer.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstring>
#include <fstream>

using namespace kumite;

namespace {

std::filesystem::path characters_dir() { return kumite::test::source_dir() / "data/characters"; }

// The JSON chunk of a .glb.
nlohmann::json glb_json(const std::string& bytes) {
    std::uint32_t length = 0;
    std::memcpy(&length, bytes.data() + 12, 4);
    return nlohmann::json::parse(bytes.begin() + 20, bytes.begin() + 20 + length);
}

// A clip on `skeleton`: the rest pose with the root walking forward and every joint turning a little per frame.
Clip moving_clip(const Skeleton& skeleton, int frames) {
    Clip clip;
    clip.skeleton = skeleton;
    clip.frame_time_s = 1.0 / 60.0;
    for (int f = 0; f < frames; ++f) {
        clip.root_translations.push_back(skeleton.rest_offsets[0] + Eigen::Vector3d(0.0, 0.0, 0.01 * f));
        for (int j = 0; j < skeleton.joint_count(); ++j) {
            clip.local_rotations.push_back(Eigen::Quaterniond(Eigen::AngleAxisd(0.01 * f * (1 + j % 3), Eigen::Vector3d::UnitX())));
        }
    }
    return clip;
}

} // namespace

TEST_CASE("glTF bodies: every shipped body fits its BVH skeleton by name", "[formats][gltf]") {
    for (const CharacterEntry& entry : list_characters(characters_dir())) {
        INFO(entry.name);
        REQUIRE(!entry.body.empty());
        Result<BvhFile> character = bvh_read_file(entry.file);
        REQUIRE(character.has_value());
        Result<std::optional<SkinnedMesh>> body = load_character_body(characters_dir(), entry.name, character->clip.skeleton);
        REQUIRE(body.has_value());
        REQUIRE(body->has_value());
        const SkinnedMesh& mesh = **body;
        CHECK(mesh.bind_to_rest.size() == std::size_t(character->clip.skeleton.joint_count()));
        // Skinned in the BVH's rest pose, every vertex lands where the body file modelled it.
        const Pose rest = character->clip.rest_pose();
        const int joints = character->clip.skeleton.joint_count();
        std::vector<Eigen::Vector3d> positions(joints);
        std::vector<Eigen::Quaterniond> rotations(joints);
        forward_kinematics(positions, rotations, character->clip.skeleton, rest.view());
        std::vector<Eigen::Matrix4f> skin(joints);
        skin_matrices(skin, mesh, positions, rotations);
        CHECK(skinning_envelope_excess(mesh, skin, positions, positions) <= 1e-5);
        Result<GltfCharacter> file = gltf_read_file(entry.body);
        REQUIRE(file.has_value());
        double worst = 0.0;
        const std::vector<Eigen::Vector3d> file_rest = rest_model_positions(file->character.clip.skeleton);
        for (std::size_t v = 0; v < mesh.vertex_count(); v += 7) {
            const std::uint16_t j = file->mesh.joints[v][0];
            const Eigen::Vector4f in_joint = file->mesh.bind_to_rest[j] * file->mesh.positions[v].homogeneous();
            worst = std::max(worst, (skin_vertex(mesh, skin, v).cast<double>() - (file_rest[j] + in_joint.head<3>().cast<double>())).norm());
        }
        CHECK(worst < 1e-4 * character->height_m);
    }
}

TEST_CASE("glTF bodies: a body that does not fit the skeleton is refused", "[formats][gltf]") {
    Result<BvhFile> character = bvh_read_file(characters_dir() / "scout.bvh");
    REQUIRE(character.has_value());
    Result<GltfCharacter> body = gltf_read_file(characters_dir() / "scout.glb");
    REQUIRE(body.has_value());
    SECTION("a joint the skeleton does not have") {
        Skeleton renamed = character->clip.skeleton;
        renamed.names[renamed.joint_count() - 1] += "_renamed";
        Result<SkinnedMesh> moved = body_on_skeleton(*body, renamed, "scout.glb");
        REQUIRE_FALSE(moved.has_value());
        CHECK_THAT(moved.error().message, Catch::Contains("does not have"));
    }
    SECTION("another rest pose") {
        Skeleton longer = character->clip.skeleton;
        for (Eigen::Vector3d& offset : longer.rest_offsets) offset *= 1.2;
        Result<SkinnedMesh> moved = body_on_skeleton(*body, longer, "scout.glb");
        REQUIRE_FALSE(moved.has_value());
        CHECK_THAT(moved.error().message, Catch::Contains("rest pose"));
    }
    SECTION("another character's body") {
        Result<BvhFile> giant = bvh_read_file(characters_dir() / "giant.bvh");
        REQUIRE(giant.has_value());
        CHECK_FALSE(body_on_skeleton(*body, giant->clip.skeleton, "scout.glb").has_value());
    }
}

TEST_CASE("glTF recording: a moving clip with its body reads back as the same character", "[formats][gltf]") {
    for (const char* name : {"kid", "giant"}) {
        INFO(name);
        Result<BvhFile> character = bvh_read_file(characters_dir() / (std::string(name) + ".bvh"));
        REQUIRE(character.has_value());
        Result<std::optional<SkinnedMesh>> body = load_character_body(characters_dir(), name, character->clip.skeleton);
        REQUIRE(body.has_value());
        REQUIRE(body->has_value());
        const Clip motion = moving_clip(character->clip.skeleton, 40);
        Result<std::string> bytes = gltf_animation_glb(motion, &**body, name);
        REQUIRE(bytes.has_value());
        CHECK(bytes->size() < 2'000'000);

        // The animation: one rotation channel per joint and the root's translation, 40 keys 1/60 s apart.
        const nlohmann::json json = glb_json(*bytes);
        REQUIRE(json["animations"].size() == 1);
        CHECK(json["animations"][0]["channels"].size() == std::size_t(motion.skeleton.joint_count() + 1));
        const nlohmann::json& times = json["accessors"][json["animations"][0]["samplers"][0]["input"].get<int>()];
        CHECK(times["count"] == 40);
        CHECK(times["max"][0].get<double>() == Approx(39.0 / 60.0));

        // Read back: the same joints, rest pose and mesh.
        const std::vector<std::uint8_t> raw(bytes->begin(), bytes->end());
        Result<GltfCharacter> read = gltf_parse(raw, "recorded.glb");
        REQUIRE(read.has_value());
        const Skeleton& skeleton = read->character.clip.skeleton;
        REQUIRE(skeleton.joint_count() == motion.skeleton.joint_count());
        double offset_error = 0.0;
        for (int j = 0; j < motion.skeleton.joint_count(); ++j) { // the reader orders joints by depth: match by name
            const std::optional<int> same = skeleton.find(motion.skeleton.names[j]);
            REQUIRE(same.has_value());
            const int parent = motion.skeleton.parents[j], read_parent = skeleton.parents[*same];
            CHECK((parent < 0 ? read_parent < 0 : read_parent >= 0 && skeleton.names[read_parent] == motion.skeleton.names[parent]));
            offset_error = std::max(offset_error, (skeleton.rest_offsets[*same] - motion.skeleton.rest_offsets[j]).norm());
        }
        CHECK(offset_error < 1e-6);
        CHECK(read->mesh.vertex_count() == (*body)->vertex_count());
        CHECK(read->mesh.triangles == (*body)->triangles);
        CHECK(read->character.body_map.joint(BodyPart::hand_r) == character->body_map.joint(BodyPart::hand_r));
    }
}

TEST_CASE("glTF recording: without a body, the skeleton alone; bad motions are refused", "[formats][gltf]") {
    Result<BvhFile> character = bvh_read_file(characters_dir() / "runner.bvh");
    REQUIRE(character.has_value());
    const Clip motion = moving_clip(character->clip.skeleton, 5);
    Result<std::string> bytes = gltf_animation_glb(motion, nullptr, "runner");
    REQUIRE(bytes.has_value());
    const nlohmann::json json = glb_json(*bytes);
    CHECK(json["nodes"].size() == std::size_t(motion.skeleton.joint_count()));
    CHECK_FALSE(json.contains("skins"));

    Clip empty = motion;
    empty.root_translations.clear();
    empty.local_rotations.clear();
    CHECK_FALSE(gltf_animation_glb(empty, nullptr, "x").has_value());
    Result<BvhFile> kid = bvh_read_file(characters_dir() / "kid.bvh");
    REQUIRE(kid.has_value());
    Result<std::optional<SkinnedMesh>> kid_body = load_character_body(characters_dir(), "kid", kid->clip.skeleton);
    REQUIRE(kid_body.has_value());
    if (kid->clip.skeleton.joint_count() != motion.skeleton.joint_count()) {
        CHECK_FALSE(gltf_animation_glb(motion, &**kid_body, "x").has_value());
    }
    // Written atomically: a folder that does not exist leaves nothing behind and says so.
    Result<void> written = gltf_write_animation_file("/nonexistent-folder/out.glb", motion, nullptr);
    CHECK_FALSE(written.has_value());
}
