#include "kumite/core/body_map.h"

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

namespace kumite {
namespace {

constexpr std::array<std::string_view, k_body_part_count> k_part_names = {
    "pelvis",     "spine",       "chest",     "neck",   "head",
    "clavicle_l", "upper_arm_l", "forearm_l", "hand_l",
    "clavicle_r", "upper_arm_r", "forearm_r", "hand_r",
    "thigh_l",    "shin_l",      "foot_l",    "toe_l",
    "thigh_r",    "shin_r",      "foot_r",    "toe_r",
};

// Words that can follow a bare one-letter side prefix, as in bvh11's "lhand" or CMU's "LHipJoint".
constexpr std::array<std::string_view, 16> k_side_prefixed_words = {
    "hand", "foot", "hip", "knee", "ankle", "toe", "shoulder", "elbow",
    "wrist", "collar", "thigh", "shin", "finger", "thumb", "clavicle", "arm",
};

std::string lowercase(std::string_view text) {
    std::string result(text);
    for (char& c : result) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return result;
}

bool is_separator(char c) { return c == '_' || c == '.' || c == ' ' || c == '-' || c == '|'; }

std::string_view strip_known_prefix(std::string_view name) {
    if (const size_t colon = name.rfind(':'); colon != std::string_view::npos) name.remove_prefix(colon + 1);
    const std::string lower = lowercase(name);
    for (std::string_view prefix : {"cc_base_", "joint_", "bip01_", "bip01 ", "bip001 ", "mixamorig_", "def-", "j_bip_"}) {
        if (lower.starts_with(prefix) && lower.size() > prefix.size()) return name.substr(prefix.size());
    }
    // MotionBuilder / HumanIK: "Character1_Hips".
    if (lower.starts_with("character")) {
        size_t i = 9;
        while (i < lower.size() && std::isdigit(static_cast<unsigned char>(lower[i]))) ++i;
        if (i < lower.size() && is_separator(lower[i]) && i + 1 < lower.size()) return name.substr(i + 1);
    }
    return name;
}

Side side_of_token(const std::string& token) {
    if (token == "l" || token == "left") return Side::left;
    if (token == "r" || token == "right") return Side::right;
    return Side::none;
}

} // namespace

std::string_view body_part_name(BodyPart part) { return k_part_names[static_cast<int>(part)]; }

std::optional<BodyPart> body_part_from_name(std::string_view name) {
    for (int i = 0; i < k_body_part_count; ++i) {
        if (k_part_names[i] == name) return static_cast<BodyPart>(i);
    }
    return std::nullopt;
}

BodyPart body_part_mirrored(BodyPart part) {
    const std::string_view name = body_part_name(part);
    if (name.ends_with("_l")) return *body_part_from_name(std::string(name.substr(0, name.size() - 2)) + "_r");
    if (name.ends_with("_r")) return *body_part_from_name(std::string(name.substr(0, name.size() - 2)) + "_l");
    return part;
}

int BodyMap::mapped_count() const {
    return static_cast<int>(std::count_if(joints.begin(), joints.end(), [](int j) { return j >= 0; }));
}

std::optional<BodyPart> BodyMap::part_of(int joint) const {
    for (int i = 0; i < k_body_part_count; ++i) {
        if (joints[i] == joint) return static_cast<BodyPart>(i);
    }
    return std::nullopt;
}

JointNameParts split_joint_name(std::string_view full_name) {
    const std::string_view name = strip_known_prefix(full_name);
    // Split on separators; keep the original case to see camel-case side prefixes ("LHipJoint").
    std::vector<std::string> tokens;
    std::string current;
    for (char c : name) {
        if (is_separator(c)) {
            if (!current.empty()) tokens.push_back(current);
            current.clear();
        } else {
            current += c;
        }
    }
    if (!current.empty()) tokens.push_back(current);

    JointNameParts parts;
    std::string base, numbers;
    for (std::size_t t = 0; t < tokens.size(); ++t) {
        const std::string token = lowercase(tokens[t]);
        const Side side = side_of_token(token);
        if (side != Side::none && parts.side == Side::none && tokens.size() > 1) {
            parts.side = side;
            continue;
        }
        if (token == "c" && tokens.size() > 1) continue; // VRM's centre mark: J_Bip_C_Head
        if (t > 0 && std::all_of(token.begin(), token.end(), [](unsigned char c) { return std::isdigit(c); })) {
            numbers += token; // a trailing number: spine_01, or Rigify's DEF-forearm.L.001
            continue;
        }
        base += token;
    }
    if (parts.side == Side::none) {
        if (base.starts_with("left") && base.size() > 4) {
            parts.side = Side::left;
            base.erase(0, 4);
        } else if (base.starts_with("right") && base.size() > 5) {
            parts.side = Side::right;
            base.erase(0, 5);
        } else if (base.size() > 1 && (base[0] == 'l' || base[0] == 'r')) {
            const std::string rest = base.substr(1);
            const bool camel = name.size() > 1 && std::isupper(static_cast<unsigned char>(name[0])) &&
                               std::isupper(static_cast<unsigned char>(name[1]));
            const bool known_word = std::any_of(k_side_prefixed_words.begin(), k_side_prefixed_words.end(),
                                                [&](std::string_view word) { return rest.starts_with(word); });
            if (camel || known_word) {
                parts.side = base[0] == 'l' ? Side::left : Side::right;
                base = rest;
            }
        }
    }
    // A numbered segment of a side's limb bone (Rigify's DEF-forearm.L.001) is a helper, like a twist bone;
    // elsewhere the number stays part of the name (spine_01).
    if (!numbers.empty()) base += parts.side != Side::none ? "segment" : numbers;
    parts.base = base;
    return parts;
}

namespace {

struct NamedJoint {
    Side side;
    std::string base;
};

bool is_helper_bone(const std::string& base) {
    return base.find("twist") != std::string::npos || base.find("share") != std::string::npos ||
           base.find("roll") != std::string::npos || base.ends_with("segment");
}

// The first joint (closest to the root) of this side whose base name is one of `bases`, trying them in order.
int find_by_base(const std::vector<NamedJoint>& named, Side side, std::initializer_list<std::string_view> bases) {
    for (std::string_view wanted : bases) {
        for (size_t joint = 0; joint < named.size(); ++joint) {
            if (named[joint].side == side && named[joint].base == wanted) return static_cast<int>(joint);
        }
    }
    return -1;
}

// The parent, skipping twist/share/roll helper joints; -1 at the root.
int climb(const Skeleton& skeleton, const std::vector<NamedJoint>& named, int joint) {
    if (joint < 0) return -1;
    int parent = skeleton.parents[joint];
    while (parent >= 0 && is_helper_bone(named[parent].base)) parent = skeleton.parents[parent];
    return parent;
}

// Climbs one step only when the parent carries the same side mark (clavicles, limbs), else -1.
int climb_same_side(const Skeleton& skeleton, const std::vector<NamedJoint>& named, int joint, Side side) {
    const int parent = climb(skeleton, named, joint);
    return (parent >= 0 && named[parent].side == side) ? parent : -1;
}

// The joint just below `top` on the chain from `top` down to `bottom`, or -1 when `bottom` is `top`'s child.
int first_joint_below(const Skeleton& skeleton, int top, int bottom) {
    int below = -1;
    for (int j = skeleton.parents[bottom]; j >= 0 && j != top; j = skeleton.parents[j]) below = j;
    return below;
}

void detect_limbs(BodyMap& map, const Skeleton& skeleton, const std::vector<NamedJoint>& named, Side side) {
    const bool left = side == Side::left;
    const int hand = find_by_base(named, side, {"wrist", "hand"});
    const int forearm = climb_same_side(skeleton, named, hand, side);
    const int upper_arm = climb_same_side(skeleton, named, forearm, side);
    const int clavicle = climb_same_side(skeleton, named, upper_arm, side);
    if (upper_arm >= 0) {
        map.set(left ? BodyPart::hand_l : BodyPart::hand_r, hand);
        map.set(left ? BodyPart::forearm_l : BodyPart::forearm_r, forearm);
        map.set(left ? BodyPart::upper_arm_l : BodyPart::upper_arm_r, upper_arm);
        map.set(left ? BodyPart::clavicle_l : BodyPart::clavicle_r, clavicle);
    }

    const int foot = find_by_base(named, side, {"ankle", "foot"});
    const int shin = climb_same_side(skeleton, named, foot, side);
    const int thigh = climb_same_side(skeleton, named, shin, side);
    if (thigh >= 0) {
        map.set(left ? BodyPart::foot_l : BodyPart::foot_r, foot);
        map.set(left ? BodyPart::shin_l : BodyPart::shin_r, shin);
        map.set(left ? BodyPart::thigh_l : BodyPart::thigh_r, thigh);
        int toe = -1;
        for (std::string_view wanted : {"toebase", "toe", "toes", "ball", "toe0"}) {
            for (int child : skeleton.children(foot)) {
                if (toe < 0 && named[child].base == wanted) toe = child;
            }
        }
        for (int child : skeleton.children(foot)) {
            if (toe < 0 && !is_helper_bone(named[child].base)) toe = child;
        }
        map.set(left ? BodyPart::toe_l : BodyPart::toe_r, toe);
    }
}

// Without a joint named head (Rigify's DEF-spine.006): from the chest up the trunk, each step to the unsided child
// highest above its parent at rest, while one rises; the last is the head, when there are at least two (a neck).
int top_of_trunk(const Skeleton& skeleton, const std::vector<NamedJoint>& named, int chest) {
    int at = chest, steps = 0;
    for (;;) {
        int next = -1;
        double best_rise = 0.0;
        for (int child : skeleton.children(at)) {
            const double rise = skeleton.rest_offsets[child].y();
            if (named[child].side == Side::none && rise > 0.5 * skeleton.rest_offsets[child].norm() && rise > best_rise) {
                next = child;
                best_rise = rise;
            }
        }
        if (next < 0) break;
        at = next;
        ++steps;
    }
    return steps >= 2 ? at : -1;
}

int lca_of_present(const Skeleton& skeleton, int a, int b) {
    if (a < 0) return b;
    if (b < 0) return a;
    return lowest_common_ancestor(skeleton, a, b);
}

// Names that leave a needed part unfound: the parts they left, from the structure, when it agrees with them.
BodyMap with_structure(const Skeleton& skeleton, const BodyMap& by_name) {
    const bool complete = std::all_of(std::begin(k_strike_parts), std::end(k_strike_parts), [&](BodyPart part) { return by_name.has(part); });
    if (complete) return by_name;
    const BodyMap by_structure = detect_body_map_by_structure(skeleton);
    if (by_structure.mapped_count() == 0) return by_name;
    // A long head bone reads to the structure as the skull's top, the head one joint lower: the names know better.
    const bool head_one_below = by_name.has(BodyPart::head) && by_structure.has(BodyPart::head) &&
                                skeleton.parents[std::size_t(by_name.joint(BodyPart::head))] == by_structure.joint(BodyPart::head);
    for (BodyPart part : k_strike_parts) {
        if (part == BodyPart::head && head_one_below) continue;
        if (by_name.has(part) && by_structure.joint(part) != by_name.joint(part)) return by_name; // they disagree: trust neither blindly
    }
    BodyMap merged = by_name;
    for (int part = 0; part < k_body_part_count; ++part) {
        if (head_one_below && static_cast<BodyPart>(part) == BodyPart::neck) continue;
        if (merged.joints[std::size_t(part)] < 0 && by_structure.joints[std::size_t(part)] >= 0) {
            merged.set(static_cast<BodyPart>(part), by_structure.joints[std::size_t(part)], BodyMapSource::structure);
        }
    }
    merged.structure_confidence = by_structure.structure_confidence;
    return merged;
}

} // namespace

std::string_view body_map_source_name(BodyMapSource source) {
    switch (source) {
    case BodyMapSource::name: return "name";
    case BodyMapSource::structure: return "structure";
    case BodyMapSource::file: return "file";
    case BodyMapSource::vrm: return "vrm";
    default: return "none";
    }
}

BodyMap detect_body_map(const Skeleton& skeleton) {
    std::vector<NamedJoint> named;
    named.reserve(skeleton.joint_count());
    for (const std::string& name : skeleton.names) {
        JointNameParts parts = split_joint_name(name);
        named.push_back({parts.side, std::move(parts.base)});
    }

    BodyMap map;
    detect_limbs(map, skeleton, named, Side::left);
    detect_limbs(map, skeleton, named, Side::right);

    // The chest is where the arms branch; the pelvis where the legs and the trunk branch.
    auto arm_top = [&](BodyPart clavicle, BodyPart upper_arm) {
        return map.has(clavicle) ? map.joint(clavicle) : map.joint(upper_arm);
    };
    const int arm_top_l = arm_top(BodyPart::clavicle_l, BodyPart::upper_arm_l);
    const int arm_top_r = arm_top(BodyPart::clavicle_r, BodyPart::upper_arm_r);
    int chest = -1;
    if (arm_top_l >= 0 && arm_top_r >= 0) chest = lowest_common_ancestor(skeleton, arm_top_l, arm_top_r);
    else if (arm_top_l >= 0 || arm_top_r >= 0) chest = skeleton.parents[std::max(arm_top_l, arm_top_r)];

    int head = find_by_base(named, Side::none, {"head"});
    if (head >= 0 && chest >= 0 && !skeleton.is_ancestor(chest, head)) head = -1;
    if (head < 0 && chest >= 0) head = top_of_trunk(skeleton, named, chest);

    const int pelvis = lca_of_present(skeleton, lca_of_present(skeleton, map.joint(BodyPart::thigh_l),
                                                               map.joint(BodyPart::thigh_r)), chest);
    map.set(BodyPart::pelvis, pelvis);
    if (chest >= 0 && chest != pelvis) map.set(BodyPart::chest, chest);
    if (head >= 0) map.set(BodyPart::head, head);
    if (chest >= 0 && head >= 0 && head != chest) map.set(BodyPart::neck, first_joint_below(skeleton, chest, head));
    if (pelvis >= 0 && chest >= 0 && chest != pelvis && skeleton.is_ancestor(pelvis, chest)) {
        map.set(BodyPart::spine, first_joint_below(skeleton, pelvis, chest));
    }
    for (int part = 0; part < k_body_part_count; ++part) {
        if (map.joints[std::size_t(part)] >= 0) map.sources[std::size_t(part)] = BodyMapSource::name;
    }
    return with_structure(skeleton, map);
}

} // namespace kumite
