#include "kumite/core/fist_pose.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace kumite {
namespace {

constexpr double k_pi = 3.14159265358979323846;
constexpr double k_palm_share = 0.3;        // of a finger's wrist-to-tip distance: joints nearer the wrist are the palm's
constexpr double k_finger_share = 0.4;      // of the longest finger's reach: shorter chains (a prop joint) are no finger
constexpr double k_thumb_reach_share = 0.8; // the thumb's tip reaches less than this share of the next finger's along the forearm
constexpr std::array<double, 3> k_flexion_deg = {90.0, 100.0, 60.0}; // knuckle, middle joint, last joint
constexpr double k_thumb_gap_share = 0.6;   // the thumb lies out from the curled fingers' middle joints on the palm's side, in knuckle-to-middle lengths
constexpr double k_thumb_max_bend_deg = 80.0;

struct Finger {
    std::vector<int> joints; // its own joints (shared with no other chain), from the hand outwards
    Eigen::Vector3d tip = Eigen::Vector3d::Zero(); // rest
    double reach_m = 0.0;    // wrist to tip
    std::size_t first_bending = 0; // joints[first_bending..] bend; the ones before are in the palm
};

Eigen::Vector3d square_to(const Eigen::Vector3d& v, const Eigen::Vector3d& unit) { return v - v.dot(unit) * unit; }

// The chains below `hand`, one per leaf, with their tips and reaches; chains much shorter than the longest left out.
std::vector<Finger> hand_chains(const Skeleton& skeleton, std::span<const Eigen::Vector3d> rest, int hand) {
    const int joints = skeleton.joint_count();
    std::vector<int> child_count(std::size_t(joints), 0), chains_through(std::size_t(joints), 0);
    for (int joint = 1; joint < joints; ++joint) ++child_count[std::size_t(skeleton.parents[joint])];
    std::vector<Finger> chains;
    for (int leaf = hand + 1; leaf < joints; ++leaf) {
        if (child_count[std::size_t(leaf)] > 0 || !skeleton.is_ancestor(hand, leaf)) continue;
        Finger chain;
        for (int joint = leaf; joint != hand; joint = skeleton.parents[joint]) chain.joints.insert(chain.joints.begin(), joint);
        chain.tip = rest[std::size_t(leaf)];
        for (const EndSite& end : skeleton.end_sites) {
            const Eigen::Vector3d tip = rest[std::size_t(leaf)] + end.offset_in_joint;
            if (end.joint == leaf && (tip - rest[std::size_t(hand)]).norm() > (chain.tip - rest[std::size_t(hand)]).norm()) chain.tip = tip;
        }
        chain.reach_m = (chain.tip - rest[std::size_t(hand)]).norm();
        for (int joint : chain.joints) ++chains_through[std::size_t(joint)];
        chains.push_back(std::move(chain));
    }
    double longest = 0.0;
    for (const Finger& chain : chains) longest = std::max(longest, chain.reach_m);
    std::vector<Finger> fingers;
    for (Finger& chain : chains) {
        std::erase_if(chain.joints, [&](int joint) { return chains_through[std::size_t(joint)] > 1; });
        // A finger bends at two joints at least: a lone joint below the wrist is the palm's bone, or a prop's.
        if (chain.joints.size() >= 2 && chain.reach_m > 1e-4 && chain.reach_m >= k_finger_share * longest) fingers.push_back(std::move(chain));
    }
    return fingers;
}

// The chain's points from its first bending joint to its tip, after bending joint i by angles[i] about `axis`
// (one axis for the whole finger: a turn about it leaves it in place for the joints after).
std::vector<Eigen::Vector3d> bent_points(const Finger& finger, std::span<const Eigen::Vector3d> rest, const Eigen::Vector3d& axis,
                                         std::span<const double> angles_rad) {
    std::vector<Eigen::Vector3d> points;
    for (std::size_t i = finger.first_bending; i < finger.joints.size(); ++i) points.push_back(rest[std::size_t(finger.joints[i])]);
    points.push_back(finger.tip);
    for (std::size_t i = 0; i + 1 < points.size() && i < angles_rad.size(); ++i) {
        const Eigen::AngleAxisd turn(angles_rad[i], axis);
        for (std::size_t k = i + 1; k < points.size(); ++k) points[k] = points[i] + turn * (points[k] - points[i]);
    }
    return points;
}

double flexion_rad(std::size_t joint_in_finger) {
    return joint_in_finger < k_flexion_deg.size() ? k_flexion_deg[joint_in_finger] * k_pi / 180.0 : 0.0;
}

// The thumb onto `target`: its joints after the first bend about one axis until the tip is no farther from the
// first joint than the target (bisection), then the first joint turns the bent thumb's tip onto the target.
void fold_thumb(std::vector<Eigen::Quaterniond>& local, const Finger& thumb, std::span<const Eigen::Vector3d> rest, const Eigen::Vector3d& target) {
    const Eigen::Vector3d base = rest[std::size_t(thumb.joints.front())];
    const Eigen::Vector3d to_tip = thumb.tip - base, to_target = target - base;
    const Eigen::Vector3d normal = to_tip.cross(to_target);
    if (normal.norm() < 1e-9 * to_tip.norm() * to_target.norm() || to_target.norm() < 1e-6) return;
    const Eigen::Vector3d axis = normal.normalized();
    const std::size_t bends = thumb.joints.size() - 1;
    std::vector<double> angles(thumb.joints.size(), 0.0);
    auto tip_at = [&](double bend) {
        std::fill(angles.begin() + 1, angles.end(), bend);
        return Eigen::Vector3d(bent_points(thumb, rest, axis, angles).back());
    };
    double bend = 0.0;
    if (bends > 0 && to_tip.norm() > to_target.norm()) {
        double low = 0.0, high = k_thumb_max_bend_deg * k_pi / 180.0 / double(bends);
        for (int step = 0; step < 40; ++step) {
            const double middle = 0.5 * (low + high);
            ((tip_at(middle) - base).norm() > to_target.norm() ? low : high) = middle;
        }
        bend = high;
    }
    const Eigen::Vector3d bent_tip = tip_at(bend) - base;
    local[std::size_t(thumb.joints.front())] = Eigen::Quaterniond::FromTwoVectors(bent_tip, to_target);
    for (std::size_t i = 1; i < thumb.joints.size(); ++i) local[std::size_t(thumb.joints[i])] = Eigen::Quaterniond(Eigen::AngleAxisd(bend, axis));
}

// The thumb, when a tip reaches least far along the forearm by a margin; fingers.size() when none does.
std::size_t find_thumb(const std::vector<Finger>& fingers, const Eigen::Vector3d& wrist, const Eigen::Vector3d& forearm) {
    if (fingers.size() < 2) return fingers.size();
    std::vector<double> along(fingers.size());
    for (std::size_t i = 0; i < fingers.size(); ++i) along[i] = (fingers[i].tip - wrist).dot(forearm);
    std::vector<std::size_t> order(fingers.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return along[a] < along[b]; });
    return along[order[0]] < k_thumb_reach_share * along[order[1]] ? order[0] : fingers.size();
}

struct Hand {
    std::vector<Finger> fingers;
    std::size_t thumb = 0;           // fingers.size(): none
    std::vector<std::size_t> others; // the fingers that curl, nearest the thumb first when there is one
    Eigen::Vector3d wrist = Eigen::Vector3d::Zero();
    Eigen::Vector3d direction = Eigen::Vector3d::Zero(); // wrist to the knuckles, unit
    Eigen::Vector3d knuckle(std::span<const Eigen::Vector3d> rest, std::size_t i) const {
        return rest[std::size_t(fingers[i].joints[fingers[i].first_bending])];
    }
};

// The palm's normal (unit; zero when the geometry gives none): from the hand's chirality when the thumb says which
// edge of the knuckles is the index's, else down and towards the body.
Eigen::Vector3d palm_normal(const Hand& hand, std::span<const Eigen::Vector3d> rest, const BodyMap& map, bool right) {
    Eigen::Vector3d palm = Eigen::Vector3d::Zero();
    if (hand.thumb < hand.fingers.size()) {
        const Eigen::Vector3d thumb_base = rest[std::size_t(hand.fingers[hand.thumb].joints.front())];
        const Eigen::Vector3d across = hand.others.size() >= 2 ? Eigen::Vector3d(hand.knuckle(rest, hand.others.back()) - hand.knuckle(rest, hand.others.front()))
                                                               : Eigen::Vector3d(hand.knuckle(rest, hand.others[0]) - thumb_base);
        palm = (right ? 1.0 : -1.0) * hand.direction.cross(square_to(across, hand.direction));
    }
    if (palm.norm() < 1e-9) {
        const int chest = map.joint(BodyPart::chest);
        Eigen::Vector3d inward = chest >= 0 ? Eigen::Vector3d(rest[std::size_t(chest)] - hand.wrist) : Eigen::Vector3d::Zero();
        inward.y() = 0.0;
        palm = square_to(-Eigen::Vector3d::UnitY() + (inward.norm() > 1e-6 ? inward.normalized() : Eigen::Vector3d::Zero()), hand.direction);
    }
    return palm.norm() < 1e-9 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(palm.normalized());
}

// A finger's bending axis: square to its direction (knuckle to tip) and to the palm's normal, turning it palm-wards.
Eigen::Vector3d bending_axis(const Hand& hand, std::span<const Eigen::Vector3d> rest, std::size_t finger, const Eigen::Vector3d& palm) {
    const Eigen::Vector3d direction = hand.fingers[finger].tip - hand.knuckle(rest, finger);
    if (direction.norm() < 1e-6) return Eigen::Vector3d::Zero();
    return direction.normalized().cross(square_to(palm, direction.normalized())).normalized();
}

void close_hand(std::vector<Eigen::Quaterniond>& local, const Skeleton& skeleton, const BodyMap& map, std::span<const Eigen::Vector3d> rest,
                bool right) {
    const int hand_joint = map.joint(right ? BodyPart::hand_r : BodyPart::hand_l);
    if (hand_joint < 0) return;
    Hand hand;
    hand.fingers = hand_chains(skeleton, rest, hand_joint);
    if (hand.fingers.empty()) return;
    hand.wrist = rest[std::size_t(hand_joint)];
    const BodyPart forearm_part = right ? BodyPart::forearm_r : BodyPart::forearm_l;
    const int elbow = map.has(forearm_part) ? map.joint(forearm_part) : skeleton.parents[hand_joint];
    const Eigen::Vector3d forearm = elbow >= 0 ? (hand.wrist - rest[std::size_t(elbow)]).normalized() : Eigen::Vector3d::UnitY();
    hand.thumb = find_thumb(hand.fingers, hand.wrist, forearm);

    // The palm is where a finger's joints are still near the wrist; the knuckle is its first joint past it, and a
    // finger has two past it at least.
    Eigen::Vector3d knuckles_mean = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < hand.fingers.size(); ++i) {
        if (i == hand.thumb) continue;
        Finger& finger = hand.fingers[i];
        while (finger.first_bending < finger.joints.size() &&
               (rest[std::size_t(finger.joints[finger.first_bending])] - hand.wrist).norm() < k_palm_share * finger.reach_m) {
            ++finger.first_bending;
        }
        if (finger.first_bending + 2 > finger.joints.size()) continue;
        hand.others.push_back(i);
        knuckles_mean += hand.knuckle(rest, i);
    }
    if (hand.others.empty()) return; // a thumb alone has nothing to close over
    knuckles_mean /= double(hand.others.size());
    hand.direction = (knuckles_mean - hand.wrist).norm() > 1e-6 ? Eigen::Vector3d((knuckles_mean - hand.wrist).normalized()) : forearm;
    const bool has_thumb = hand.thumb < hand.fingers.size();
    if (has_thumb) {
        const Eigen::Vector3d thumb_base = rest[std::size_t(hand.fingers[hand.thumb].joints.front())];
        std::sort(hand.others.begin(), hand.others.end(), [&](std::size_t a, std::size_t b) {
            return (hand.knuckle(rest, a) - thumb_base).norm() < (hand.knuckle(rest, b) - thumb_base).norm();
        });
    }
    const Eigen::Vector3d palm = palm_normal(hand, rest, map, right);
    if (palm.isZero()) return;

    for (std::size_t i : hand.others) {
        const Finger& finger = hand.fingers[i];
        const Eigen::Vector3d axis = bending_axis(hand, rest, i, palm);
        if (axis.isZero()) continue;
        for (std::size_t j = finger.first_bending; j < finger.joints.size(); ++j) {
            local[std::size_t(finger.joints[j])] = Eigen::Quaterniond(Eigen::AngleAxisd(flexion_rad(j - finger.first_bending), axis));
        }
    }
    if (!has_thumb) return;
    // The thumb onto the palm's side of the two nearest fingers' curled middle joints.
    std::array<double, k_flexion_deg.size()> angles{};
    for (std::size_t j = 0; j < angles.size(); ++j) angles[j] = flexion_rad(j);
    Eigen::Vector3d target = Eigen::Vector3d::Zero();
    const std::size_t under_thumb = std::min<std::size_t>(2, hand.others.size());
    for (std::size_t k = 0; k < under_thumb; ++k) {
        const std::vector<Eigen::Vector3d> bent = bent_points(hand.fingers[hand.others[k]], rest, bending_axis(hand, rest, hand.others[k], palm), angles);
        target += bent[1] + k_thumb_gap_share * (bent[1] - bent[0]).norm() * palm;
    }
    fold_thumb(local, hand.fingers[hand.thumb], rest, target / double(under_thumb));
}

} // namespace

std::vector<Eigen::Quaterniond> fist_local_rotations(const Skeleton& skeleton, const BodyMap& body_map, std::span<const Eigen::Vector3d> rest_positions) {
    std::vector<Eigen::Quaterniond> local(std::size_t(skeleton.joint_count()), Eigen::Quaterniond::Identity());
    close_hand(local, skeleton, body_map, rest_positions, false);
    close_hand(local, skeleton, body_map, rest_positions, true);
    return local;
}

} // namespace kumite
