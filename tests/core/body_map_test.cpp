#include "kumite/core/body_map.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <map>

using namespace kumite;

namespace {

// A skeleton from "name parent" pairs (parents listed before children); offsets do not matter here.
Skeleton skeleton_from(std::initializer_list<std::pair<const char*, const char*>> joints) {
    Skeleton skeleton;
    for (const auto& [name, parent] : joints) {
        skeleton.names.push_back(name);
        skeleton.parents.push_back(parent ? *skeleton.find(parent) : -1);
        skeleton.rest_offsets.push_back(Eigen::Vector3d::Zero());
    }
    return skeleton;
}

std::map<std::string, std::string> named_map(const Skeleton& skeleton) {
    const BodyMap map = detect_body_map(skeleton);
    std::map<std::string, std::string> result;
    for (int part = 0; part < k_body_part_count; ++part) {
        if (map.joints[part] >= 0) result[std::string(body_part_name(BodyPart(part)))] = skeleton.names[map.joints[part]];
    }
    return result;
}

} // namespace

TEST_CASE("split_joint_name: prefixes and side marks of the corpus's schemes", "[core]") {
    struct Case { const char* name; Side side; const char* base; };
    for (const Case& c : {Case{"mixamorig:LeftForeArm", Side::left, "forearm"}, Case{"CC_Base_L_Thigh", Side::left, "thigh"},
                          Case{"Hand_R", Side::right, "hand"}, Case{"UpperArm_L", Side::left, "upperarm"},
                          Case{"Character1_RightUpLeg", Side::right, "upleg"}, Case{"LHipJoint", Side::left, "hipjoint"},
                          Case{"lhand", Side::left, "hand"}, Case{"rhand", Side::right, "hand"}, Case{"hand.L", Side::left, "hand"},
                          Case{"LowerBack", Side::none, "lowerback"}, Case{"Hips", Side::none, "hips"},
                          Case{"RightHand_End", Side::right, "handend"}, Case{"joint_Root", Side::none, "root"},
                          Case{"LeftToe", Side::left, "toe"}, Case{"Root", Side::none, "root"}}) {
        INFO(c.name);
        const JointNameParts parts = split_joint_name(c.name);
        CHECK(parts.side == c.side);
        CHECK(parts.base == c.base);
    }
}

TEST_CASE("body_map: Bandai names map all 21 parts", "[core]") {
    const Skeleton skeleton = skeleton_from({{"joint_Root", nullptr}, {"Hips", "joint_Root"}, {"Spine", "Hips"}, {"Chest", "Spine"},
        {"Neck", "Chest"}, {"Head", "Neck"}, {"Shoulder_L", "Chest"}, {"UpperArm_L", "Shoulder_L"}, {"LowerArm_L", "UpperArm_L"},
        {"Hand_L", "LowerArm_L"}, {"Shoulder_R", "Chest"}, {"UpperArm_R", "Shoulder_R"}, {"LowerArm_R", "UpperArm_R"},
        {"Hand_R", "LowerArm_R"}, {"UpperLeg_L", "Hips"}, {"LowerLeg_L", "UpperLeg_L"}, {"Foot_L", "LowerLeg_L"},
        {"Toes_L", "Foot_L"}, {"UpperLeg_R", "Hips"}, {"LowerLeg_R", "UpperLeg_R"}, {"Foot_R", "LowerLeg_R"}, {"Toes_R", "Foot_R"}});
    const auto map = named_map(skeleton);
    CHECK(map.size() == 21);
    CHECK(map.at("pelvis") == "Hips");
    CHECK(map.at("clavicle_l") == "Shoulder_L");
    CHECK(map.at("upper_arm_r") == "UpperArm_R");
    CHECK(map.at("toe_r") == "Toes_R");
}

TEST_CASE("body_map: CMU names, with hip joints and two neck joints", "[core]") {
    const Skeleton skeleton = skeleton_from({{"Hips", nullptr}, {"LHipJoint", "Hips"}, {"LeftUpLeg", "LHipJoint"},
        {"LeftLeg", "LeftUpLeg"}, {"LeftFoot", "LeftLeg"}, {"LeftToeBase", "LeftFoot"}, {"RHipJoint", "Hips"},
        {"RightUpLeg", "RHipJoint"}, {"RightLeg", "RightUpLeg"}, {"RightFoot", "RightLeg"}, {"RightToeBase", "RightFoot"},
        {"LowerBack", "Hips"}, {"Spine", "LowerBack"}, {"Spine1", "Spine"}, {"Neck", "Spine1"}, {"Neck1", "Neck"},
        {"Head", "Neck1"}, {"LeftShoulder", "Spine1"}, {"LeftArm", "LeftShoulder"}, {"LeftForeArm", "LeftArm"},
        {"LeftHand", "LeftForeArm"}, {"LeftFingerBase", "LeftHand"}, {"RightShoulder", "Spine1"}, {"RightArm", "RightShoulder"},
        {"RightForeArm", "RightArm"}, {"RightHand", "RightForeArm"}, {"RThumb", "RightHand"}});
    const auto map = named_map(skeleton);
    CHECK(map.size() == 21);
    CHECK(map.at("pelvis") == "Hips");
    CHECK(map.at("spine") == "LowerBack");
    CHECK(map.at("chest") == "Spine1");
    CHECK(map.at("neck") == "Neck");
    CHECK(map.at("thigh_l") == "LeftUpLeg");
    CHECK(map.at("clavicle_r") == "RightShoulder");
    CHECK(map.at("hand_r") == "RightHand");
}

TEST_CASE("body_map: bvh11 names where 'Shoulder' is the upper arm and the wrist is the hand", "[core]") {
    const Skeleton skeleton = skeleton_from({{"Hips", nullptr}, {"LeftHip", "Hips"}, {"LeftKnee", "LeftHip"},
        {"LeftAnkle", "LeftKnee"}, {"LeftToe", "LeftAnkle"}, {"lowerback", "Hips"}, {"Chest", "lowerback"}, {"Chest2", "Chest"},
        {"lowerneck", "Chest2"}, {"Neck", "lowerneck"}, {"Head", "Neck"}, {"LeftCollar", "Chest2"}, {"LeftShoulder", "LeftCollar"},
        {"LeftElbow", "LeftShoulder"}, {"LeftWrist", "LeftElbow"}, {"lhand", "LeftWrist"}, {"RightCollar", "Chest2"},
        {"RightShoulder", "RightCollar"}, {"RightElbow", "RightShoulder"}, {"RightWrist", "RightElbow"}, {"rhand", "RightWrist"},
        {"RightHip", "Hips"}, {"RightKnee", "RightHip"}, {"RightAnkle", "RightKnee"}, {"RightToe", "RightAnkle"}});
    const auto map = named_map(skeleton);
    CHECK(map.size() == 21);
    CHECK(map.at("upper_arm_l") == "LeftShoulder");
    CHECK(map.at("clavicle_l") == "LeftCollar");
    CHECK(map.at("hand_l") == "LeftWrist");
    CHECK(map.at("chest") == "Chest2");
    CHECK(map.at("toe_r") == "RightToe");
}

TEST_CASE("body_map: Mixamo, MotionBuilder and CC4 prefixes", "[core]") {
    for (const std::string prefix : {"mixamorig:", "Character1_"}) {
        auto n = [&](const char* name) { return prefix + name; };
        Skeleton skeleton;
        const std::vector<std::pair<std::string, std::string>> joints = {{n("Hips"), ""}, {n("Spine"), n("Hips")},
            {n("Spine1"), n("Spine")}, {n("Spine2"), n("Spine1")}, {n("Neck"), n("Spine2")}, {n("Head"), n("Neck")},
            {n("LeftShoulder"), n("Spine2")}, {n("LeftArm"), n("LeftShoulder")}, {n("LeftForeArm"), n("LeftArm")},
            {n("LeftHand"), n("LeftForeArm")}, {n("LeftHandIndex1"), n("LeftHand")}, {n("RightShoulder"), n("Spine2")},
            {n("RightArm"), n("RightShoulder")}, {n("RightForeArm"), n("RightArm")}, {n("RightHand"), n("RightForeArm")},
            {n("LeftUpLeg"), n("Hips")}, {n("LeftLeg"), n("LeftUpLeg")}, {n("LeftFoot"), n("LeftLeg")},
            {n("LeftToeBase"), n("LeftFoot")}, {n("RightUpLeg"), n("Hips")}, {n("RightLeg"), n("RightUpLeg")},
            {n("RightFoot"), n("RightLeg")}, {n("RightToeBase"), n("RightFoot")}};
        for (const auto& [name, parent] : joints) {
            skeleton.names.push_back(name);
            skeleton.parents.push_back(parent.empty() ? -1 : *skeleton.find(parent));
            skeleton.rest_offsets.push_back(Eigen::Vector3d::Zero());
        }
        const auto map = named_map(skeleton);
        INFO(prefix);
        CHECK(map.size() == 21);
        CHECK(map.at("chest") == n("Spine2"));
        CHECK(map.at("hand_l") == n("LeftHand"));
    }

    const Skeleton cc4 = skeleton_from({{"CC_Base_Hip", nullptr}, {"CC_Base_Pelvis", "CC_Base_Hip"},
        {"CC_Base_L_Thigh", "CC_Base_Pelvis"}, {"CC_Base_L_Calf", "CC_Base_L_Thigh"}, {"CC_Base_L_Foot", "CC_Base_L_Calf"},
        {"CC_Base_L_ToeBaseShareBone", "CC_Base_L_Foot"}, {"CC_Base_L_ToeBase", "CC_Base_L_Foot"},
        {"CC_Base_L_ThighTwist01", "CC_Base_L_Thigh"}, {"CC_Base_R_Thigh", "CC_Base_Pelvis"}, {"CC_Base_R_Calf", "CC_Base_R_Thigh"},
        {"CC_Base_R_Foot", "CC_Base_R_Calf"}, {"CC_Base_R_ToeBase", "CC_Base_R_Foot"}, {"CC_Base_Waist", "CC_Base_Hip"},
        {"CC_Base_Spine01", "CC_Base_Waist"}, {"CC_Base_Spine02", "CC_Base_Spine01"}, {"CC_Base_NeckTwist01", "CC_Base_Spine02"},
        {"CC_Base_NeckTwist02", "CC_Base_NeckTwist01"}, {"CC_Base_Head", "CC_Base_NeckTwist02"},
        {"CC_Base_L_Clavicle", "CC_Base_Spine02"}, {"CC_Base_L_Upperarm", "CC_Base_L_Clavicle"},
        {"CC_Base_L_Forearm", "CC_Base_L_Upperarm"}, {"CC_Base_L_Hand", "CC_Base_L_Forearm"},
        {"CC_Base_R_Clavicle", "CC_Base_Spine02"}, {"CC_Base_R_Upperarm", "CC_Base_R_Clavicle"},
        {"CC_Base_R_Forearm", "CC_Base_R_Upperarm"}, {"CC_Base_R_Hand", "CC_Base_R_Forearm"}});
    const auto map = named_map(cc4);
    CHECK(map.size() == 21);
    CHECK(map.at("pelvis") == "CC_Base_Hip"); // where legs and trunk branch
    CHECK(map.at("spine") == "CC_Base_Waist");
    CHECK(map.at("toe_l") == "CC_Base_L_ToeBase");
    CHECK(map.at("thigh_l") == "CC_Base_L_Thigh");
}

TEST_CASE("body_map: a chain without human names maps nothing", "[core]") {
    const Skeleton skeleton = skeleton_from({{"base", nullptr}, {"child1", "base"}, {"child2", "child1"}});
    CHECK(detect_body_map(skeleton).mapped_count() == 0);
}

TEST_CASE("body_map: part names and mirroring", "[core]") {
    CHECK(body_part_name(BodyPart::upper_arm_l) == "upper_arm_l");
    CHECK(body_part_from_name("toe_r") == BodyPart::toe_r);
    CHECK_FALSE(body_part_from_name("elbow").has_value());
    CHECK(body_part_mirrored(BodyPart::hand_l) == BodyPart::hand_r);
    CHECK(body_part_mirrored(BodyPart::shin_r) == BodyPart::shin_l);
    CHECK(body_part_mirrored(BodyPart::head) == BodyPart::head);
}

TEST_CASE("body_map: 3ds Max Biped, Unreal and Blender/Rigify names", "[core]") {
    const Skeleton biped = skeleton_from({{"Bip01", nullptr}, {"Bip01 Pelvis", "Bip01"}, {"Bip01 Spine", "Bip01 Pelvis"},
        {"Bip01 Spine1", "Bip01 Spine"}, {"Bip01 Neck", "Bip01 Spine1"}, {"Bip01 Head", "Bip01 Neck"},
        {"Bip01 L Clavicle", "Bip01 Neck"}, {"Bip01 L UpperArm", "Bip01 L Clavicle"}, {"Bip01 L Forearm", "Bip01 L UpperArm"},
        {"Bip01 L Hand", "Bip01 L Forearm"}, {"Bip01 R Clavicle", "Bip01 Neck"}, {"Bip01 R UpperArm", "Bip01 R Clavicle"},
        {"Bip01 R Forearm", "Bip01 R UpperArm"}, {"Bip01 R Hand", "Bip01 R Forearm"}, {"Bip01 L Thigh", "Bip01 Spine"},
        {"Bip01 L Calf", "Bip01 L Thigh"}, {"Bip01 L Foot", "Bip01 L Calf"}, {"Bip01 L Toe0", "Bip01 L Foot"},
        {"Bip01 R Thigh", "Bip01 Spine"}, {"Bip01 R Calf", "Bip01 R Thigh"}, {"Bip01 R Foot", "Bip01 R Calf"},
        {"Bip01 R Toe0", "Bip01 R Foot"}});
    const auto biped_map = named_map(biped);
    CHECK(biped_map.at("hand_l") == "Bip01 L Hand");
    CHECK(biped_map.at("toe_r") == "Bip01 R Toe0");
    CHECK(biped_map.at("thigh_r") == "Bip01 R Thigh");
    CHECK(biped_map.at("clavicle_l") == "Bip01 L Clavicle");

    const Skeleton unreal = skeleton_from({{"root", nullptr}, {"pelvis", "root"}, {"spine_01", "pelvis"}, {"spine_02", "spine_01"},
        {"spine_03", "spine_02"}, {"neck_01", "spine_03"}, {"head", "neck_01"}, {"clavicle_l", "spine_03"},
        {"upperarm_l", "clavicle_l"}, {"lowerarm_l", "upperarm_l"}, {"lowerarm_twist_01_l", "lowerarm_l"}, {"hand_l", "lowerarm_l"},
        {"clavicle_r", "spine_03"}, {"upperarm_r", "clavicle_r"}, {"lowerarm_r", "upperarm_r"}, {"hand_r", "lowerarm_r"},
        {"thigh_l", "pelvis"}, {"calf_l", "thigh_l"}, {"foot_l", "calf_l"}, {"ball_l", "foot_l"}, {"thigh_r", "pelvis"},
        {"calf_r", "thigh_r"}, {"foot_r", "calf_r"}, {"ball_r", "foot_r"}});
    const auto unreal_map = named_map(unreal);
    CHECK(unreal_map.size() == 21);
    CHECK(unreal_map.at("pelvis") == "pelvis");
    CHECK(unreal_map.at("spine") == "spine_01");
    CHECK(unreal_map.at("chest") == "spine_03");
    CHECK(unreal_map.at("forearm_l") == "lowerarm_l");
    CHECK(unreal_map.at("toe_l") == "ball_l");

    const Skeleton rigify = skeleton_from({{"hips", nullptr}, {"spine", "hips"}, {"chest", "spine"}, {"neck", "chest"},
        {"head", "neck"}, {"shoulder.L", "chest"}, {"upper_arm.L", "shoulder.L"}, {"forearm.L", "upper_arm.L"}, {"hand.L", "forearm.L"},
        {"shoulder.R", "chest"}, {"upper_arm.R", "shoulder.R"}, {"forearm.R", "upper_arm.R"}, {"hand.R", "forearm.R"},
        {"thigh.L", "hips"}, {"shin.L", "thigh.L"}, {"foot.L", "shin.L"}, {"toe.L", "foot.L"}, {"thigh.R", "hips"},
        {"shin.R", "thigh.R"}, {"foot.R", "shin.R"}, {"toe.R", "foot.R"}});
    const auto rigify_map = named_map(rigify);
    CHECK(rigify_map.size() == 21);
    CHECK(rigify_map.at("upper_arm_r") == "upper_arm.R");
    CHECK(rigify_map.at("shin_l") == "shin.L");
}

TEST_CASE("body_map: VRM / VRoid humanoid names", "[core]") {
    const Skeleton skeleton = skeleton_from({{"Root", nullptr}, {"J_Bip_C_Hips", "Root"}, {"J_Bip_C_Spine", "J_Bip_C_Hips"},
        {"J_Bip_C_Chest", "J_Bip_C_Spine"}, {"J_Bip_C_UpperChest", "J_Bip_C_Chest"}, {"J_Bip_C_Neck", "J_Bip_C_UpperChest"},
        {"J_Bip_C_Head", "J_Bip_C_Neck"}, {"J_Bip_L_Shoulder", "J_Bip_C_UpperChest"}, {"J_Bip_L_UpperArm", "J_Bip_L_Shoulder"},
        {"J_Bip_L_LowerArm", "J_Bip_L_UpperArm"}, {"J_Bip_L_Hand", "J_Bip_L_LowerArm"}, {"J_Bip_R_Shoulder", "J_Bip_C_UpperChest"},
        {"J_Bip_R_UpperArm", "J_Bip_R_Shoulder"}, {"J_Bip_R_LowerArm", "J_Bip_R_UpperArm"}, {"J_Bip_R_Hand", "J_Bip_R_LowerArm"},
        {"J_Bip_L_UpperLeg", "J_Bip_C_Hips"}, {"J_Bip_L_LowerLeg", "J_Bip_L_UpperLeg"}, {"J_Bip_L_Foot", "J_Bip_L_LowerLeg"},
        {"J_Bip_L_ToeBase", "J_Bip_L_Foot"}, {"J_Bip_R_UpperLeg", "J_Bip_C_Hips"}, {"J_Bip_R_LowerLeg", "J_Bip_R_UpperLeg"},
        {"J_Bip_R_Foot", "J_Bip_R_LowerLeg"}, {"J_Bip_R_ToeBase", "J_Bip_R_Foot"}});
    const auto map = named_map(skeleton);
    CHECK(map.size() == 21);
    CHECK(map.at("pelvis") == "J_Bip_C_Hips");
    CHECK(map.at("chest") == "J_Bip_C_UpperChest");
    CHECK(map.at("head") == "J_Bip_C_Head");
    CHECK(map.at("neck") == "J_Bip_C_Neck");
    CHECK(map.at("forearm_l") == "J_Bip_L_LowerArm");
    CHECK(map.at("toe_r") == "J_Bip_R_ToeBase");
}

TEST_CASE("body_map: Rigify's deform bones, numbered segments and a head named spine.006", "[core]") {
    // Offsets matter here: the head is found as the top of the trunk.
    Skeleton skeleton;
    auto add = [&](const std::string& name, const std::string& parent, Eigen::Vector3d offset) {
        skeleton.names.push_back(name);
        skeleton.parents.push_back(parent.empty() ? -1 : *skeleton.find(parent));
        skeleton.rest_offsets.push_back(offset);
    };
    add("DEF-spine", "", {0, 1.0, 0});
    add("DEF-spine.001", "DEF-spine", {0, 0.1, 0});
    add("DEF-spine.002", "DEF-spine.001", {0, 0.1, 0});
    add("DEF-spine.003", "DEF-spine.002", {0, 0.12, 0});
    add("DEF-spine.004", "DEF-spine.003", {0, 0.15, 0});
    add("DEF-spine.005", "DEF-spine.004", {0, 0.05, 0.01});
    add("DEF-spine.006", "DEF-spine.005", {0, 0.05, 0.01});
    add("DEF-jaw", "DEF-spine.006", {0, -0.05, 0.08});
    for (const char* side : {"L", "R"}) {
        const double x = side[0] == 'L' ? 1.0 : -1.0;
        const std::string s = side;
        auto n = [&](const char* base) { return std::string("DEF-") + base + "." + s; };
        add(n("shoulder"), "DEF-spine.003", {0.02 * x, 0.1, 0});
        add(n("upper_arm"), n("shoulder"), {0.15 * x, 0, 0});
        add((n("upper_arm") + ".001"), n("upper_arm"), {0.14 * x, 0, 0});
        add(n("forearm"), (n("upper_arm") + ".001"), {0.14 * x, 0, 0});
        add((n("forearm") + ".001"), n("forearm"), {0.13 * x, 0, 0});
        add(n("hand"), (n("forearm") + ".001"), {0.13 * x, 0, 0});
        add(n("thigh"), "DEF-spine", {0.1 * x, 0, 0});
        add((n("thigh") + ".001"), n("thigh"), {0, -0.22, 0});
        add(n("shin"), (n("thigh") + ".001"), {0, -0.22, 0});
        add((n("shin") + ".001"), n("shin"), {0, -0.21, 0});
        add(n("foot"), (n("shin") + ".001"), {0, -0.21, 0});
        add(n("toe"), n("foot"), {0, -0.05, 0.12});
    }
    const auto map = named_map(skeleton);
    CHECK(map.at("pelvis") == "DEF-spine");
    CHECK(map.at("chest") == "DEF-spine.003");
    CHECK(map.at("head") == "DEF-spine.006");
    CHECK(map.at("upper_arm_l") == "DEF-upper_arm.L");
    CHECK(map.at("forearm_l") == "DEF-forearm.L");
    CHECK(map.at("hand_r") == "DEF-hand.R");
    CHECK(map.at("thigh_r") == "DEF-thigh.R");
    CHECK(map.at("shin_l") == "DEF-shin.L");
    CHECK(map.at("toe_l") == "DEF-toe.L");
    CHECK(split_joint_name("DEF-forearm.L.001").base == "forearmsegment");
    CHECK(split_joint_name("spine_01").base == "spine01");
}
