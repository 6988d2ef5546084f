// The body found from the skeleton's tree and rest geometry alone (detect_body_map_by_structure in body_map.h):
// for joints with no names, numbered names or names of a scheme nobody listed.
//
// At rest (Y up): the legs are the two chains that end lowest (the feet on the floor), the pelvis where they meet;
// the spine is the chain from the pelvis to the topmost end (the head); the arms are the chains that leave the
// spine sideways and end farthest from it. Along a limb the joints are placed by where they sit: the knee at the
// middle of the leg's height, the ankle near the floor (below 15% of the height), the elbow at 55% of the way from the shoulder to the wrist
// (straight arms in a T- or A-pose do not bend at the elbow, and twist bones sit on the same line). Left is the
// character's left, from its facing (toes forward).

#include "kumite/core/body_map.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace kumite {

namespace {

struct Rest {
    const Skeleton& skeleton;
    std::vector<Eigen::Vector3d> at; // model positions at rest
    std::vector<std::vector<int>> children;
    double floor = 0.0, top = 0.0;   // the lowest and highest joint heights
    double height() const { return std::max(top - floor, 1e-9); }
    double y(int joint) const { return at[std::size_t(joint)].y() - floor; } // above the floor
};

Rest rest_of(const Skeleton& skeleton) {
    Rest rest{skeleton, std::vector<Eigen::Vector3d>(std::size_t(skeleton.joint_count())), std::vector<std::vector<int>>(std::size_t(skeleton.joint_count()))};
    for (int j = 0; j < skeleton.joint_count(); ++j) {
        const int parent = skeleton.parents[std::size_t(j)];
        rest.at[std::size_t(j)] = (parent >= 0 ? rest.at[std::size_t(parent)] : Eigen::Vector3d::Zero()) + skeleton.rest_offsets[std::size_t(j)];
        if (parent >= 0) rest.children[std::size_t(parent)].push_back(j);
    }
    rest.floor = rest.top = rest.at.empty() ? 0.0 : rest.at[0].y();
    for (const Eigen::Vector3d& p : rest.at) rest.floor = std::min(rest.floor, p.y()), rest.top = std::max(rest.top, p.y());
    return rest;
}

// From `top` (exclusive) down to `bottom` (inclusive), top first; empty when `top` is not above `bottom`.
std::vector<int> chain_between(const Skeleton& skeleton, int top, int bottom) {
    std::vector<int> chain;
    for (int j = bottom; j >= 0 && j != top; j = skeleton.parents[std::size_t(j)]) chain.push_back(j);
    if (chain.empty() || skeleton.parents[std::size_t(chain.back())] != top) return {};
    std::reverse(chain.begin(), chain.end());
    return chain;
}

// The joint of the chain whose value of `key` is closest to `wanted`, among chain[from .. to), or -1.
template <class Key>
int closest_in(const std::vector<int>& chain, std::size_t from, std::size_t to, double wanted, Key key) {
    int best = -1;
    double best_distance = 1e300;
    for (std::size_t i = from; i < to && i < chain.size(); ++i) {
        const double distance = std::abs(key(chain[i]) - wanted);
        if (distance < best_distance) best = chain[i], best_distance = distance;
    }
    return best;
}

std::size_t index_in(const std::vector<int>& chain, int joint) {
    return std::size_t(std::find(chain.begin(), chain.end(), joint) - chain.begin());
}

struct Leg {
    int thigh = -1, shin = -1, foot = -1, toe = -1;
};

// thigh: the first joint of the chain set out sideways from the pelvis (3% of the body; a hip bone right at the
// pelvis comes before it), else the first; foot: the first joint below 15% of the body (the ankle; a chibi's is at 12%); shin: between
// them, closest to their middle height; toe: the joint after the ankle, if any.
Leg leg_of(const Rest& rest, const std::vector<int>& chain, int pelvis) {
    Leg leg;
    const double h = rest.height();
    if (chain.size() < 3) return {};
    std::size_t thigh_at = 0, foot_at = chain.size();
    for (std::size_t i = 0; i < chain.size(); ++i) {
        const Eigen::Vector3d out = rest.at[std::size_t(chain[i])] - rest.at[std::size_t(pelvis)];
        if (std::hypot(out.x(), out.z()) >= 0.03 * h) {
            thigh_at = i;
            break;
        }
    }
    for (std::size_t i = thigh_at + 1; i < chain.size(); ++i) {
        if (rest.y(chain[i]) < 0.15 * h) {
            foot_at = i;
            break;
        }
    }
    if (foot_at >= chain.size() || foot_at < thigh_at + 2) return {}; // no knee between hip and ankle
    leg.thigh = chain[thigh_at];
    leg.foot = chain[foot_at];
    const double middle = 0.5 * (rest.y(leg.thigh) + rest.y(leg.foot));
    leg.shin = closest_in(chain, thigh_at + 1, foot_at, middle, [&](int j) { return rest.y(j); });
    if (foot_at + 1 < chain.size()) leg.toe = chain[foot_at + 1];
    return leg;
}

struct Arm {
    int clavicle = -1, upper_arm = -1, forearm = -1, hand = -1;
};

// From the spine's branch joint out to a hand's end: the shoulder where the chain has come 8% of the body's height
// out from the spine (5% for narrow shoulders) (the joint before it, if any, the clavicle); the wrist the first joint with two or more
// children (fingers), else the end's parent when the end is a short stub, else the end; the elbow closest to 55%
// of the shoulder-to-wrist distance.
Arm arm_of(const Rest& rest, const std::vector<int>& chain, const Eigen::Vector3d& spine_at, const Eigen::Vector3d& left) {
    Arm arm;
    const double h = rest.height();
    auto out_from_spine = [&](int j) { return std::abs((rest.at[std::size_t(j)] - spine_at).dot(left)); };
    std::size_t shoulder_at = chain.size();
    for (const double out : {0.08, 0.05}) { // a human's shoulder joint is 10-12% of the height out; narrow cartoons less
        for (std::size_t i = 0; i < chain.size() && shoulder_at == chain.size(); ++i) {
            if (out_from_spine(chain[i]) >= out * h) shoulder_at = i;
        }
        if (shoulder_at + 2 < chain.size()) break;
        shoulder_at = chain.size();
    }
    if (shoulder_at >= chain.size()) return {};
    std::size_t wrist_at = chain.size();
    for (std::size_t i = shoulder_at + 1; i < chain.size(); ++i) {
        const std::vector<int>& children = rest.children[std::size_t(chain[i])];
        if (children.size() < 2) continue;
        // Fingers start near the wrist; branches that start farther out than half the arm so far (a robot's
        // palms hung from its elbow) start at the wrist instead: the next joint of the chain.
        double spread = 0.0;
        for (int child : children) spread += (rest.at[std::size_t(child)] - rest.at[std::size_t(chain[i])]).norm() / double(children.size());
        const double so_far = (rest.at[std::size_t(chain[i])] - rest.at[std::size_t(chain[shoulder_at])]).norm();
        wrist_at = spread > 0.5 * so_far && i + 1 < chain.size() ? i + 1 : i;
        break;
    }
    if (wrist_at == chain.size()) {
        const std::size_t end = chain.size() - 1;
        const double stub = (rest.at[std::size_t(chain[end])] - rest.at[std::size_t(chain[end - (end > 0)])]).norm();
        wrist_at = end > shoulder_at + 2 && stub < 0.06 * h ? end - 1 : end;
    }
    if (wrist_at < shoulder_at + 2) return {}; // no elbow between shoulder and wrist
    arm.upper_arm = chain[shoulder_at];
    arm.hand = chain[wrist_at];
    if (shoulder_at > 0) arm.clavicle = chain[shoulder_at - 1];
    const Eigen::Vector3d shoulder = rest.at[std::size_t(arm.upper_arm)];
    const double reach = (rest.at[std::size_t(arm.hand)] - shoulder).norm();
    arm.forearm = closest_in(chain, shoulder_at + 1, wrist_at, 0.55 * reach, [&](int j) { return (rest.at[std::size_t(j)] - shoulder).norm(); });
    // A joint just past the shoulder (within a fifth of the way to the elbow) is the real shoulder, the one before
    // it a short clavicle.
    const std::size_t elbow_at = index_in(chain, arm.forearm);
    if (shoulder_at + 1 < elbow_at &&
        (rest.at[std::size_t(chain[shoulder_at + 1])] - shoulder).norm() < 0.2 * (rest.at[std::size_t(arm.forearm)] - shoulder).norm()) {
        arm.clavicle = chain[shoulder_at];
        arm.upper_arm = chain[shoulder_at + 1];
    }
    return arm;
}

} // namespace

BodyMap detect_body_map_by_structure(const Skeleton& skeleton) {
    BodyMap map;
    if (skeleton.joint_count() < 12) return map; // fewer joints than a body has parts: not a humanoid
    const Rest rest = rest_of(skeleton);
    const double h = rest.height();
    std::vector<int> ends;
    for (int j = 0; j < skeleton.joint_count(); ++j) {
        if (rest.children[std::size_t(j)].empty()) ends.push_back(j);
    }
    // The feet: the two lowest ends far enough apart sideways (a foot's toe and heel ends are not two legs).
    std::vector<int> low = ends;
    std::sort(low.begin(), low.end(), [&](int a, int b) { return rest.y(a) < rest.y(b); });
    int foot_end[2] = {-1, -1};
    for (int a : low) {
        if (rest.y(a) > 0.15 * h) break;
        if (foot_end[0] < 0) {
            foot_end[0] = a;
            continue;
        }
        const Eigen::Vector3d apart = rest.at[std::size_t(a)] - rest.at[std::size_t(foot_end[0])];
        if (std::hypot(apart.x(), apart.z()) > 0.05 * h && lowest_common_ancestor(skeleton, a, foot_end[0]) != foot_end[0]) {
            // Two legs meet above the knees, not inside one foot.
            const int meet = lowest_common_ancestor(skeleton, a, foot_end[0]);
            if (meet >= 0 && rest.y(meet) > 0.3 * h) {
                foot_end[1] = a;
                break;
            }
        }
    }
    if (foot_end[1] < 0) return map;
    const int pelvis = lowest_common_ancestor(skeleton, foot_end[0], foot_end[1]);
    // The head: the topmost end above the pelvis's subtree.
    int head_end = -1;
    for (int e : ends) {
        if (skeleton.is_ancestor(pelvis, e) && (head_end < 0 || rest.y(e) > rest.y(head_end))) head_end = e;
    }
    if (head_end < 0 || rest.y(head_end) < 0.8 * h) return map;
    const std::vector<int> spine_chain = chain_between(skeleton, pelvis, head_end);
    if (spine_chain.size() < 2) return map;

    // Facing: toes forward (from the ankle-ish joints to the foot ends), left = up x facing.
    Leg legs[2];
    for (int i = 0; i < 2; ++i) legs[i] = leg_of(rest, chain_between(skeleton, pelvis, foot_end[i]), pelvis);
    if (legs[0].foot < 0 || legs[1].foot < 0) return map;
    Eigen::Vector3d facing = Eigen::Vector3d::Zero();
    for (int i = 0; i < 2; ++i) facing += rest.at[std::size_t(foot_end[i])] - rest.at[std::size_t(legs[i].foot)];
    facing.y() = 0.0;
    if (facing.norm() < 0.01 * h) facing = Eigen::Vector3d::UnitZ(); // flat feet: the project's convention (+Z)
    facing.normalize();
    const Eigen::Vector3d up = Eigen::Vector3d::UnitY();
    const Eigen::Vector3d left = up.cross(facing).normalized();
    const Eigen::Vector3d middle = rest.at[std::size_t(pelvis)];
    const bool first_is_left = (rest.at[std::size_t(legs[0].foot)] - middle).dot(left) > (rest.at[std::size_t(legs[1].foot)] - middle).dot(left);
    const Leg& left_leg = legs[first_is_left ? 0 : 1];
    const Leg& right_leg = legs[first_is_left ? 1 : 0];

    // Arms: for each side, the end outside the legs and the head whose branch off the spine chain sits above the
    // pelvis and which reaches farthest out to that side (more than 15% of the height: ears, jaws, hair do not).
    Arm arms[2]; // left, right
    for (int side = 0; side < 2; ++side) {
        double best_out = 0.15 * h;
        for (int e : ends) {
            if (e == head_end || e == foot_end[0] || e == foot_end[1] || !skeleton.is_ancestor(pelvis, e)) continue;
            const int branch = lowest_common_ancestor(skeleton, e, head_end);
            if (branch == pelvis || std::find(spine_chain.begin(), spine_chain.end(), branch) == spine_chain.end()) continue;
            const double out = (rest.at[std::size_t(e)] - rest.at[std::size_t(branch)]).dot(left) * (side == 0 ? 1.0 : -1.0);
            if (out <= best_out) continue;
            const Arm arm = arm_of(rest, chain_between(skeleton, branch, e), rest.at[std::size_t(branch)], left);
            if (arm.hand < 0) continue;
            arms[side] = arm;
            best_out = out;
        }
    }
    if (arms[0].hand < 0 || arms[1].hand < 0) {
        // Armless to the structure (one bone per arm, no wrist): the legs and the trunk's ends still say what the
        // body has, so a refusal can name only what is missing.
        map.set(BodyPart::pelvis, pelvis, BodyMapSource::structure);
        map.set(BodyPart::head, spine_chain.back(), BodyMapSource::structure);
        map.set(BodyPart::thigh_l, left_leg.thigh, BodyMapSource::structure), map.set(BodyPart::shin_l, left_leg.shin, BodyMapSource::structure);
        map.set(BodyPart::foot_l, left_leg.foot, BodyMapSource::structure);
        map.set(BodyPart::thigh_r, right_leg.thigh, BodyMapSource::structure), map.set(BodyPart::shin_r, right_leg.shin, BodyMapSource::structure);
        map.set(BodyPart::foot_r, right_leg.foot, BodyMapSource::structure);
        return map;
    }
    // head: the top of the spine chain, or the joint before when the top is a long end (8% of the body or more from
    // its parent: the top of the skull, while the head joint sits 4-6% above the neck).
    // Without a neck (chibi rigs) the head hangs long from the chest: the joint before the top must itself be
    // above the shoulders to be the head.
    const double shoulders = 0.5 * (rest.y(arms[0].upper_arm) + rest.y(arms[1].upper_arm));
    std::size_t head_at = spine_chain.size() - 1;
    const double top_bone = (rest.at[std::size_t(spine_chain[head_at])] - rest.at[std::size_t(spine_chain[head_at - 1])]).norm();
    // A top joint that carries the head above it (an End Site reaching up a tenth of the body: a skinned mesh's
    // head over a robot's or a chibi's long head bone) is the head itself.
    double above_top = 0.0;
    for (const EndSite& site : skeleton.end_sites) {
        if (site.joint == spine_chain[head_at]) above_top = std::max(above_top, site.offset_in_joint.y());
    }
    if (head_at >= 2 && rest.children[std::size_t(spine_chain[head_at])].empty() && top_bone >= 0.08 * h &&
        rest.y(spine_chain[head_at - 1]) > shoulders && above_top < 0.1 * h) {
        --head_at;
    }
    const int head = spine_chain[head_at];
    if (rest.y(head) < shoulders) return map;
    const int chest = lowest_common_ancestor(skeleton, arms[0].clavicle >= 0 ? arms[0].clavicle : arms[0].upper_arm,
                                             arms[1].clavicle >= 0 ? arms[1].clavicle : arms[1].upper_arm);

    map.set(BodyPart::pelvis, pelvis);
    map.set(BodyPart::head, head);
    if (chest != pelvis) map.set(BodyPart::chest, chest);
    const std::size_t chest_at = index_in(spine_chain, chest);
    if (chest_at < spine_chain.size() && chest_at > 0) map.set(BodyPart::spine, spine_chain[0]);
    if (chest_at + 1 < head_at) map.set(BodyPart::neck, spine_chain[chest_at + 1]); // no neck joint: no neck (not the head twice)
    const BodyPart arm_parts[2][4] = {{BodyPart::clavicle_l, BodyPart::upper_arm_l, BodyPart::forearm_l, BodyPart::hand_l},
                                      {BodyPart::clavicle_r, BodyPart::upper_arm_r, BodyPart::forearm_r, BodyPart::hand_r}};
    for (int side = 0; side < 2; ++side) {
        map.set(arm_parts[side][0], arms[side].clavicle);
        map.set(arm_parts[side][1], arms[side].upper_arm);
        map.set(arm_parts[side][2], arms[side].forearm);
        map.set(arm_parts[side][3], arms[side].hand);
    }
    map.set(BodyPart::thigh_l, left_leg.thigh), map.set(BodyPart::shin_l, left_leg.shin), map.set(BodyPart::foot_l, left_leg.foot);
    map.set(BodyPart::toe_l, left_leg.toe);
    map.set(BodyPart::thigh_r, right_leg.thigh), map.set(BodyPart::shin_r, right_leg.shin), map.set(BodyPart::foot_r, right_leg.foot);
    map.set(BodyPart::toe_r, right_leg.toe);
    for (int part = 0; part < k_body_part_count; ++part) {
        if (map.joints[std::size_t(part)] >= 0) map.sources[std::size_t(part)] = BodyMapSource::structure;
    }
    // Confidence: a body's left and right limbs are alike; the worst ratio of a segment's length to its twin's.
    auto length = [&](int from, int to) { return (rest.at[std::size_t(to)] - rest.at[std::size_t(from)]).norm(); };
    const double pairs[4][2] = {{length(arms[0].upper_arm, arms[0].forearm), length(arms[1].upper_arm, arms[1].forearm)},
                                {length(arms[0].forearm, arms[0].hand), length(arms[1].forearm, arms[1].hand)},
                                {length(left_leg.thigh, left_leg.shin), length(right_leg.thigh, right_leg.shin)},
                                {length(left_leg.shin, left_leg.foot), length(right_leg.shin, right_leg.foot)}};
    map.structure_confidence = 1.0;
    for (const auto& pair : pairs) {
        const double larger = std::max(pair[0], pair[1]);
        map.structure_confidence = std::min(map.structure_confidence, larger > 0.0 ? std::min(pair[0], pair[1]) / larger : 0.0);
    }
    return map;
}

} // namespace kumite
