#pragma once
// BodyMap: which joint of a skeleton plays each body part, so algorithms talk about parts, not joint names.
// A part names the joint at the start of its segment: upper_arm_l is the left shoulder joint, forearm_l the
// elbow, hand_l the wrist, thigh_l the hip joint, shin_l the knee, foot_l the ankle.

#include "kumite/core/skeleton.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace kumite {

enum class BodyPart : int {
    pelvis, spine, chest, neck, head,
    clavicle_l, upper_arm_l, forearm_l, hand_l,
    clavicle_r, upper_arm_r, forearm_r, hand_r,
    thigh_l, shin_l, foot_l, toe_l,
    thigh_r, shin_r, foot_r, toe_r,
};
inline constexpr int k_body_part_count = 21;

std::string_view body_part_name(BodyPart part);           // "upper_arm_l"
std::optional<BodyPart> body_part_from_name(std::string_view name);
BodyPart body_part_mirrored(BodyPart part);                // hand_l <-> hand_r, pelvis -> pelvis

enum class Side { none, left, right };

// How a part's joint was found: by its name, by the skeleton's structure (names gave too little), from a
// .bodymap.json the user wrote, or from a VRM avatar's own humanoid bone map.
enum class BodyMapSource : std::uint8_t { none, name, structure, file, vrm };
std::string_view body_map_source_name(BodyMapSource source); // "name", "structure", "file", "vrm", "none"

// The parts a strike cannot do without: pelvis, chest, head, both arms (shoulder, elbow, wrist) and both legs
// (hip, knee, ankle).
inline constexpr BodyPart k_strike_parts[] = {BodyPart::pelvis, BodyPart::chest, BodyPart::head, BodyPart::upper_arm_l, BodyPart::forearm_l,
                                              BodyPart::hand_l, BodyPart::upper_arm_r, BodyPart::forearm_r, BodyPart::hand_r, BodyPart::thigh_l,
                                              BodyPart::shin_l, BodyPart::foot_l, BodyPart::thigh_r, BodyPart::shin_r, BodyPart::foot_r};

struct BodyMap {
    std::array<int, k_body_part_count> joints;            // [part] joint index, or -1 when the skeleton lacks it
    std::array<BodyMapSource, k_body_part_count> sources{}; // [part] how it was found
    double structure_confidence = 0.0; // when parts came from structure: how alike left and right limbs are (0-1)

    BodyMap() { joints.fill(-1); }
    int joint(BodyPart part) const { return joints[static_cast<int>(part)]; }
    BodyMapSource source(BodyPart part) const { return sources[static_cast<int>(part)]; }
    void set(BodyPart part, int joint) { joints[static_cast<int>(part)] = joint; }
    void set(BodyPart part, int joint, BodyMapSource source) { set(part, joint), sources[static_cast<int>(part)] = joint >= 0 ? source : BodyMapSource::none; }
    bool has(BodyPart part) const { return joint(part) >= 0; }
    int mapped_count() const;
    std::optional<BodyPart> part_of(int joint) const;
};

// Detects the parts from joint names and structure; when the names leave a part a strike needs unfound, the parts
// they left are taken from detect_body_map_by_structure (if it agrees with what the names found). Naming schemes handled: Bandai (`UpperArm_L`),
// CMU/Hahne (`LeftUpLeg`), bvh11/Biovision (`LeftHip`, `LeftCollar`, `lhand`), Mixamo (`mixamorig:`),
// MotionBuilder/HumanIK (`Character1_`), Reallusion CC4 (`CC_Base_L_`), Blender (`hand.L`), LaFAN-style.
// Hands and feet are found by name; arms and legs by walking up from them; pelvis, chest, spine and neck from
// where the limbs and the head branch.
BodyMap detect_body_map(const Skeleton& skeleton);

// The parts from the tree and the rest pose alone, ignoring names (body_structure.cpp): legs are the chains that
// end lowest, the pelvis where they meet, the spine the chain to the topmost end, arms the chains that leave the
// spine sideways. Needs a standing rest pose (T or A), Y up. An empty map when no humanoid is found.
BodyMap detect_body_map_by_structure(const Skeleton& skeleton);

// The side a joint name denotes and the name with prefixes, side marks and separators removed, lowercase:
// "mixamorig:LeftForeArm" -> {left, "forearm"}, "CC_Base_L_Thigh" -> {left, "thigh"}, "Hand_R" -> {right, "hand"}.
struct JointNameParts {
    Side side = Side::none;
    std::string base;
};
JointNameParts split_joint_name(std::string_view name);

} // namespace kumite
