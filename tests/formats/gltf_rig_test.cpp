// Rigs as artists make them (gltf_rig.h, gltf_body.h): rigs made from a shipped body the way control rigs,
// IK rigs, VRM exports and animation-pose saves make them read as the same body, with a warning saying what was
// done; partial humanoids are refused with every missing part and how to give it; hostile rigs never crash.

#include "kumite/core/forward_kinematics.h"
#include "kumite/formats/gltf_reader.h"
#include "support/glb_edit.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace kumite;
using kumite::test::Glb;

namespace {

std::vector<std::uint8_t> brawler_bytes() { return kumite::test::read_bytes(kumite::test::source_dir() / "data/characters/brawler.glb"); }

GltfCharacter read(const Glb& glb) {
    Result<GltfCharacter> character = gltf_parse(glb.bytes(), "rig.glb");
    INFO((character ? std::string("read") : character.error().message));
    REQUIRE(character.has_value());
    return std::move(*character);
}

std::string warnings_of(const GltfCharacter& character) {
    std::string text;
    for (const std::string& warning : character.character.warnings) text += warning + "\n";
    return text;
}

// The same body: every joint of `original` is in `changed` by name, at the same rest position, and the parts a
// strike needs are the same joints (by name).
void check_same_body(const GltfCharacter& original, const GltfCharacter& changed) {
    const Skeleton& a = original.character.clip.skeleton;
    const Skeleton& b = changed.character.clip.skeleton;
    const std::vector<Eigen::Vector3d> at_a = rest_model_positions(a), at_b = rest_model_positions(b);
    for (int j = 0; j < a.joint_count(); ++j) {
        const auto found = std::find(b.names.begin(), b.names.end(), a.names[std::size_t(j)]);
        INFO(a.names[std::size_t(j)]);
        REQUIRE(found != b.names.end());
        CHECK((at_b[std::size_t(found - b.names.begin())] - at_a[std::size_t(j)]).norm() < 1e-5);
    }
    for (BodyPart part : k_strike_parts) {
        INFO(body_part_name(part));
        REQUIRE(changed.character.body_map.has(part));
        CHECK(b.names[std::size_t(changed.character.body_map.joint(part))] == a.names[std::size_t(original.character.body_map.joint(part))]);
    }
    CHECK(changed.mesh.vertex_count() == original.mesh.vertex_count());
    CHECK(std::abs(changed.character.height_m - original.character.height_m) < 1e-6);
}

// Takes joints out of the body: their vertices follow `heir`, the first one's node hangs apart from the body
// (a scene root), so nothing of them is left for names or structure to find.
void drop_from_body(Glb& glb, const std::vector<std::string>& names, const std::string& heir) {
    const nlohmann::json& joints = glb.json["skins"][0]["joints"];
    auto skin_index = [&](const std::string& name) {
        for (std::size_t k = 0; k < joints.size(); ++k) {
            if (joints[k].get<int>() == glb.node_named(name)) return int(k);
        }
        return -1;
    };
    std::vector<int> dropped;
    for (const std::string& name : names) dropped.push_back(skin_index(name));
    const int to = skin_index(heir);
    REQUIRE(to >= 0);
    REQUIRE(glb.json["meshes"][0]["primitives"].size() == 1);
    const int attribute = glb.attribute("JOINTS_0");
    const std::size_t count = glb.json["accessors"][attribute]["count"].get<std::size_t>();
    const bool byte_ids = glb.json["accessors"][attribute]["componentType"].get<int>() == 5121;
    for (std::size_t v = 0; v < count; ++v) {
        for (std::size_t k = 0; k < 4; ++k) {
            const std::size_t at = glb.offset_of(attribute, v, byte_ids ? 4 : 8) + k * (byte_ids ? 1 : 2);
            std::uint16_t id = byte_ids ? glb.bin[at] : std::uint16_t(glb.bin[at] | glb.bin[at + 1] << 8);
            if (std::find(dropped.begin(), dropped.end(), int(id)) != dropped.end()) id = std::uint16_t(to);
            glb.bin[at] = std::uint8_t(id & 0xff);
            if (!byte_ids) glb.bin[at + 1] = std::uint8_t(id >> 8);
        }
    }
    glb.reparent(glb.node_named(names.front()), -1);
}

} // namespace

TEST_CASE("gltf rigs: control rigs, IK rigs and animation-pose saves read as the body they deform", "[formats]") {
    const std::vector<std::uint8_t> bytes = brawler_bytes();
    const GltfCharacter original = read(Glb(bytes));
    REQUIRE(original.character.warnings.empty());

    SECTION("IK targets and pole vectors as extra roots of the skin") {
        Glb glb(bytes);
        const int hand = glb.node_named("mixamorig:LeftHand");
        const int target = glb.add_node("hand_IK_target.L", -1, glb.world(hand));
        Eigen::Matrix4d pole = glb.world(glb.node_named("mixamorig:RightLeg"));
        pole(2, 3) += 0.5;
        const int pole_node = glb.add_node("PoleTarget.R", -1, pole);
        glb.add_joints({target, pole_node});
        const GltfCharacter rig = read(glb);
        check_same_body(original, rig);
        CHECK(rig.character.clip.skeleton.joint_count() == original.character.clip.skeleton.joint_count());
        CHECK_THAT(warnings_of(rig), Catch::Contains("hand_IK_target.L") && Catch::Contains("left out"));
    }
    SECTION("feet hung from the root (an IK rig): attached back to the shins") {
        Glb glb(bytes);
        const int hips = glb.node_named("mixamorig:Hips");
        const int root = glb.add_node("root", glb.parent_of(hips), Eigen::Matrix4d::Identity());
        glb.reparent(hips, root);
        glb.add_joints({root});
        for (const char* foot : {"mixamorig:LeftFoot", "mixamorig:RightFoot"}) glb.reparent(glb.node_named(foot), root);
        const GltfCharacter rig = read(glb);
        check_same_body(original, rig);
        const Skeleton& skeleton = rig.character.clip.skeleton;
        CHECK(skeleton.parents[std::size_t(rig.character.body_map.joint(BodyPart::foot_l))] == rig.character.body_map.joint(BodyPart::shin_l));
        CHECK(skeleton.parents[std::size_t(rig.character.body_map.joint(BodyPart::foot_r))] == rig.character.body_map.joint(BodyPart::shin_r));
        CHECK_THAT(warnings_of(rig), Catch::Contains("joint mixamorig:LeftFoot hangs from root") && Catch::Contains("attached to mixamorig:LeftLeg"));
    }
    SECTION("IK and FK copies of an arm beside the chain that deforms") {
        Glb glb(bytes);
        std::vector<int> copies;
        for (const char* kind : {"IK", "FK"}) {
            int parent = glb.node_named("mixamorig:RightShoulder");
            for (const char* bone : {"mixamorig:RightArm", "mixamorig:RightForeArm", "mixamorig:RightHand"}) {
                const int copy = glb.add_node(std::string(bone) + "_" + kind, parent, glb.local(glb.node_named(bone)));
                copies.push_back(copy);
                parent = copy;
            }
        }
        // Listed first in the skin, so the names meet the copies before the deforming arm.
        glb.add_joints(copies);
        nlohmann::json& joints = glb.json["skins"][0]["joints"];
        CHECK(joints.size() == 28);
        const GltfCharacter rig = read(glb);
        check_same_body(original, rig);
        for (BodyPart part : {BodyPart::upper_arm_r, BodyPart::forearm_r, BodyPart::hand_r}) {
            CHECK(rig.character.clip.skeleton.names[std::size_t(rig.character.body_map.joint(part))].find('_') == std::string::npos);
        }
    }
    SECTION("each mesh its own skin, one bound with other matrices: every mesh read, placed where its skin puts it") {
        Glb glb(bytes);
        // A second mesh node on the same mesh with a skin over the same joints whose bind matrices take each vertex
        // 0.3 m to the right first (IBM * T(-0.3, 0, 0)): the body twice, the copy shifted by -0.3 m in X.
        nlohmann::json skin = glb.json["skins"][0];
        const int matrices = skin["inverseBindMatrices"].get<int>();
        const std::size_t count = glb.json["accessors"][matrices]["count"].get<std::size_t>();
        std::vector<float> values(count * 16);
        std::memcpy(values.data(), glb.bin.data() + glb.offset_of(matrices, 0, 64), count * 64);
        Eigen::Matrix4f shift = Eigen::Matrix4f::Identity();
        shift(0, 3) = -0.3f;
        for (std::size_t k = 0; k < count; ++k) {
            Eigen::Map<Eigen::Matrix4f> matrix(values.data() + 16 * k);
            matrix = Eigen::Matrix4f(matrix) * shift;
        }
        const std::size_t offset = glb.bin.size();
        glb.bin.resize(offset + values.size() * 4);
        std::memcpy(glb.bin.data() + offset, values.data(), values.size() * 4);
        glb.json["buffers"][0]["byteLength"] = glb.bin.size();
        glb.json["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", values.size() * 4}});
        glb.json["accessors"].push_back({{"bufferView", glb.json["bufferViews"].size() - 1}, {"componentType", 5126}, {"count", count}, {"type", "MAT4"}});
        skin["inverseBindMatrices"] = glb.json["accessors"].size() - 1;
        glb.json["skins"].push_back(skin);
        int mesh_node = -1;
        for (std::size_t n = 0; n < glb.json["nodes"].size(); ++n) {
            if (glb.json["nodes"][n].contains("skin")) mesh_node = int(n);
        }
        REQUIRE(mesh_node >= 0);
        const int copy = glb.add_node("body_copy", glb.parent_of(mesh_node), glb.local(mesh_node));
        glb.json["nodes"][copy]["mesh"] = glb.json["nodes"][mesh_node]["mesh"];
        glb.json["nodes"][copy]["skin"] = 1;
        const GltfCharacter twice = read(glb);
        CHECK(twice.character.clip.skeleton.joint_count() == original.character.clip.skeleton.joint_count());
        REQUIRE(twice.mesh.vertex_count() == 2 * original.mesh.vertex_count());
        double worst = 0.0;
        for (std::size_t v = 0; v < original.mesh.vertex_count(); ++v) {
            const Eigen::Vector3f moved = twice.mesh.positions[original.mesh.vertex_count() + v] - twice.mesh.positions[v];
            worst = std::max(worst, double((moved - Eigen::Vector3f(-0.3f, 0.0f, 0.0f)).norm()));
        }
        CHECK(worst < 1e-4);
    }
    SECTION("a file saved in an animation's pose: the rest pose from the inverse bind matrices") {
        Glb glb(bytes);
        for (const char* bone : {"mixamorig:LeftForeArm", "mixamorig:RightUpLeg", "mixamorig:Spine1"}) {
            const int node = glb.node_named(bone);
            Eigen::Matrix4d turned = glb.local(node);
            turned.block<3, 3>(0, 0) = turned.block<3, 3>(0, 0) * Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitX()).toRotationMatrix();
            glb.set_local(node, turned);
        }
        const GltfCharacter rig = read(glb);
        check_same_body(original, rig);
        CHECK_THAT(warnings_of(rig), Catch::Contains("bind pose from the inverse bind matrices"));
    }
}

TEST_CASE("gltf rigs: a VRM avatar's humanoid bone map names the parts, whatever the joints are called", "[formats]") {
    const std::vector<std::uint8_t> bytes = brawler_bytes();
    const GltfCharacter original = read(Glb(bytes));
    const Skeleton& skeleton = original.character.clip.skeleton;
    auto vrm_name = [](BodyPart part) -> std::string {
        const std::string name(body_part_name(part));
        const std::pair<const char*, const char*> names[] = {{"pelvis", "hips"}, {"spine", "spine"}, {"chest", "chest"}, {"neck", "neck"}, {"head", "head"},
                                                             {"clavicle", "Shoulder"}, {"upper_arm", "UpperArm"}, {"forearm", "LowerArm"}, {"hand", "Hand"},
                                                             {"thigh", "UpperLeg"}, {"shin", "LowerLeg"}, {"foot", "Foot"}, {"toe", "Toes"}};
        for (const auto& [ours, theirs] : names) {
            if (name.rfind(ours, 0) != 0) continue;
            if (name.size() > 2 && name[name.size() - 2] == '_') return std::string(name.back() == 'l' ? "left" : "right") + theirs;
            return theirs;
        }
        return name;
    };
    for (const bool version_1 : {false, true}) {
        INFO((version_1 ? "VRM 1.0" : "VRM 0.x"));
        Glb glb(bytes);
        // Joint names that say nothing; the bone map says everything.
        for (std::size_t n = 0; n < glb.json["nodes"].size(); ++n) glb.json["nodes"][n]["name"] = "bone" + std::to_string(n * 37 % 101);
        nlohmann::json bones = version_1 ? nlohmann::json::object() : nlohmann::json::array();
        for (int part = 0; part < k_body_part_count; ++part) {
            const int joint = original.character.body_map.joints[std::size_t(part)];
            if (joint < 0) continue;
            const int node = Glb(bytes).node_named(skeleton.names[std::size_t(joint)]);
            const std::string bone = vrm_name(static_cast<BodyPart>(part));
            if (version_1) bones[bone] = {{"node", node}};
            else bones.push_back({{"bone", bone}, {"node", node}});
        }
        if (!version_1) bones.push_back({{"bone", "leftEye"}, {"node", 9999}}); // eyes are no part of kumite's; a bad node is ignored
        glb.json["extensions"][version_1 ? "VRMC_vrm" : "VRM"] = {{"humanoid", {{"humanBones", bones}}}};
        const GltfCharacter avatar = read(glb);
        for (int part = 0; part < k_body_part_count; ++part) {
            INFO(body_part_name(static_cast<BodyPart>(part)));
            CHECK(avatar.character.body_map.joints[std::size_t(part)] == original.character.body_map.joints[std::size_t(part)]);
            if (original.character.body_map.joints[std::size_t(part)] >= 0) CHECK(avatar.character.body_map.sources[std::size_t(part)] == BodyMapSource::vrm);
        }
    }
    CHECK(is_gltf_path("avatar.VRM"));
}

TEST_CASE("gltf rigs: partial humanoids are refused with every missing part and how to give it", "[formats]") {
    const std::vector<std::uint8_t> bytes = brawler_bytes();
    SECTION("no head") {
        Glb glb(bytes);
        drop_from_body(glb, {"mixamorig:Neck", "mixamorig:Head"}, "mixamorig:Spine2");
        const Result<GltfCharacter> read = gltf_parse(glb.bytes(), "headless.glb");
        REQUIRE_FALSE(read.has_value());
        CHECK_THAT(read.error().message, Catch::StartsWith("headless.glb: not a whole humanoid: no joint found for head") &&
                                             Catch::Contains("headless.bodymap.json"));
    }
    SECTION("one bone per arm: no elbow, no wrist") {
        Glb glb(bytes);
        drop_from_body(glb, {"mixamorig:LeftForeArm", "mixamorig:LeftHand"}, "mixamorig:LeftArm");
        drop_from_body(glb, {"mixamorig:RightForeArm", "mixamorig:RightHand"}, "mixamorig:RightArm");
        const Result<GltfCharacter> read = gltf_parse(glb.bytes(), "stubby.glb");
        REQUIRE_FALSE(read.has_value());
        CHECK_THAT(read.error().message, Catch::Contains("stubby.glb: not a whole humanoid: no joint found for ") &&
                                             Catch::Contains("upper_arm_l, forearm_l, hand_l, upper_arm_r, forearm_r, hand_r") &&
                                             Catch::Contains("stubby.bodymap.json"));
    }
}

TEST_CASE("gltf rigs: hostile rigs are refused or taken with a message, never a crash", "[formats]") {
    const std::vector<std::uint8_t> bytes = brawler_bytes();
    auto outcome = [](const Glb& glb) {
        const Result<GltfCharacter> read = gltf_parse(glb.bytes(), "hostile.glb");
        if (!read) {
            CHECK_THAT(read.error().message, Catch::StartsWith("hostile.glb: "));
            return std::string("refused: ") + read.error().message;
        }
        CHECK(read->character.clip.skeleton.joint_count() > 0);
        return std::string("read");
    };
    SECTION("1,000 roots") {
        Glb glb(bytes);
        std::vector<int> roots;
        for (int k = 0; k < 1000; ++k) roots.push_back(glb.add_node("helper" + std::to_string(k), -1, Eigen::Matrix4d::Identity()));
        glb.add_joints(roots);
        CHECK(outcome(glb) == "read");
        const Result<GltfCharacter> read = gltf_parse(glb.bytes(), "hostile.glb");
        REQUIRE(read.has_value());
        CHECK_THAT(warnings_of(*read), Catch::Contains("1000 joints outside the body's tree"));
    }
    SECTION("a limb of 200 joints") {
        Glb glb(bytes);
        std::vector<int> chain;
        int parent = glb.node_named("mixamorig:LeftHand");
        Eigen::Matrix4d step = Eigen::Matrix4d::Identity();
        step(1, 3) = 0.005;
        for (int k = 0; k < 200; ++k) chain.push_back(parent = glb.add_node("tail" + std::to_string(k), parent, step));
        glb.add_joints(chain);
        INFO(outcome(glb));
        CHECK_FALSE(outcome(glb).empty());
    }
    SECTION("zero-length bones") {
        Glb glb(bytes);
        for (const char* bone : {"mixamorig:LeftForeArm", "mixamorig:RightLeg", "mixamorig:Spine1"}) {
            const int node = glb.node_named(bone);
            Eigen::Matrix4d local = glb.local(node);
            local.block<3, 1>(0, 3).setZero();
            glb.set_local(node, local);
        }
        INFO(outcome(glb));
        CHECK_FALSE(outcome(glb).empty());
    }
    SECTION("a mirrored rig (scale -1 on an ancestor)") {
        Glb glb(bytes);
        const int hips = glb.node_named("mixamorig:Hips");
        const int mirror = glb.add_node("mirror", glb.parent_of(hips), Eigen::Matrix4d::Identity());
        glb.json["nodes"][mirror]["scale"] = {-1.0, 1.0, 1.0};
        glb.reparent(hips, mirror);
        INFO(outcome(glb));
        CHECK_FALSE(outcome(glb).empty());
    }
}
