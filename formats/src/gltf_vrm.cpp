#include "gltf_vrm.h"

#include <string_view>

namespace kumite::gltf {
namespace {

// VRM's humanoid bone names (the same in 0.x and 1.0) for the parts kumite maps. VRM's chest is above the spine;
// its optional upperChest, when present, is where the shoulders hang and so kumite's chest.
std::optional<BodyPart> part_of_vrm_bone(std::string_view bone) {
    struct Entry {
        std::string_view bone;
        BodyPart part;
    };
    static constexpr Entry k_bones[] = {
        {"hips", BodyPart::pelvis}, {"spine", BodyPart::spine}, {"chest", BodyPart::chest}, {"upperChest", BodyPart::chest},
        {"neck", BodyPart::neck}, {"head", BodyPart::head},
        {"leftShoulder", BodyPart::clavicle_l}, {"leftUpperArm", BodyPart::upper_arm_l}, {"leftLowerArm", BodyPart::forearm_l}, {"leftHand", BodyPart::hand_l},
        {"rightShoulder", BodyPart::clavicle_r}, {"rightUpperArm", BodyPart::upper_arm_r}, {"rightLowerArm", BodyPart::forearm_r}, {"rightHand", BodyPart::hand_r},
        {"leftUpperLeg", BodyPart::thigh_l}, {"leftLowerLeg", BodyPart::shin_l}, {"leftFoot", BodyPart::foot_l}, {"leftToes", BodyPart::toe_l},
        {"rightUpperLeg", BodyPart::thigh_r}, {"rightLowerLeg", BodyPart::shin_r}, {"rightFoot", BodyPart::foot_r}, {"rightToes", BodyPart::toe_r},
    };
    for (const Entry& entry : k_bones) {
        if (entry.bone == bone) return entry.part;
    }
    return std::nullopt;
}

void add_bone(VrmHumanoid& humanoid, const tinygltf::Model& model, const std::string& bone, const tinygltf::Value& node) {
    const std::optional<BodyPart> part = part_of_vrm_bone(bone);
    if (!part) return; // fingers, eyes, jaw: no part of kumite's
    if (!node.IsNumber() || node.GetNumberAsInt() < 0 || node.GetNumberAsInt() >= static_cast<int>(model.nodes.size())) {
        humanoid.warnings.push_back("VRM humanoid bone " + bone + " names no node of the file; left to names and structure");
        return;
    }
    // upperChest overrides chest whatever order the file lists them in.
    for (VrmBone& known : humanoid.bones) {
        if (known.part == *part) {
            if (bone == "upperChest") known.node = node.GetNumberAsInt();
            return;
        }
    }
    humanoid.bones.push_back({*part, node.GetNumberAsInt()});
}

// extension.humanoid.humanBones, or a null value when the extension does not have that shape.
tinygltf::Value human_bones(const tinygltf::Value& extension) {
    if (!extension.IsObject() || !extension.Get("humanoid").IsObject()) return {};
    return extension.Get("humanoid").Get("humanBones");
}

} // namespace

std::optional<VrmHumanoid> vrm_humanoid(const tinygltf::Model& model) {
    VrmHumanoid humanoid;
    const bool version_1 = model.extensions.count("VRMC_vrm") > 0;
    const auto found = model.extensions.find(version_1 ? "VRMC_vrm" : "VRM");
    if (found == model.extensions.end()) return std::nullopt;
    humanoid.version = version_1 ? "1.0" : "0.x";
    const tinygltf::Value bones = human_bones(found->second);
    if (version_1 ? !bones.IsObject() : !bones.IsArray()) {
        humanoid.warnings.push_back(found->first + " has no humanoid.humanBones " + (version_1 ? "object" : "list") +
                                    "; the body is found by names and structure");
        return humanoid;
    }
    if (version_1) { // {"leftUpperArm": {"node": 12}, ...}
        for (const std::string& bone : bones.Keys()) {
            const tinygltf::Value& entry = bones.Get(bone);
            add_bone(humanoid, model, bone, entry.IsObject() ? entry.Get("node") : tinygltf::Value());
        }
    } else { // [{"bone": "leftUpperArm", "node": 12}, ...]
        for (std::size_t i = 0; i < bones.ArrayLen(); ++i) {
            const tinygltf::Value& entry = bones.Get(static_cast<int>(i));
            if (entry.IsObject() && entry.Get("bone").IsString()) add_bone(humanoid, model, entry.Get("bone").Get<std::string>(), entry.Get("node"));
        }
    }
    return humanoid;
}

} // namespace kumite::gltf
