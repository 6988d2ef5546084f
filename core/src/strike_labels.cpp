#include "kumite/core/strike_labels.h"

#include "kumite/core/contact_point.h"
#include "kumite/core/forward_kinematics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace kumite {
namespace {

constexpr std::array<const char*, k_strike_kind_count> k_kind_names = {"none", "straight", "hook", "uppercut", "front", "roundhouse", "side", "other", "rising", "downward", "inward", "outward"};
constexpr std::array<const char*, k_strike_height_count> k_height_names = {"none", "low", "middle", "high"};
constexpr double k_approach_fraction = 0.4;
constexpr double k_min_approach_s = 0.2; // a strike found late in its rise still shows its course

} // namespace

const char* strike_kind_name(StrikeKind kind) { return k_kind_names[static_cast<int>(kind) % k_strike_kind_count]; }
const char* strike_height_name(StrikeHeight height) { return k_height_names[static_cast<int>(height) % k_strike_height_count]; }

std::optional<StrikeKind> strike_kind_from_name(std::string_view name) {
    for (int k = 0; k < k_strike_kind_count; ++k) {
        if (name == k_kind_names[k]) return static_cast<StrikeKind>(k);
    }
    return std::nullopt;
}

std::optional<StrikeHeight> strike_height_from_name(std::string_view name) {
    for (int h = 0; h < k_strike_height_count; ++h) {
        if (name == k_height_names[h]) return static_cast<StrikeHeight>(h);
    }
    return std::nullopt;
}

bool strike_kind_fits(std::string_view semantics, StrikeKind kind) {
    if (kind == StrikeKind::none || kind == StrikeKind::other) return true;
    if (semantics == "punch") return kind == StrikeKind::straight || kind == StrikeKind::hook || kind == StrikeKind::uppercut;
    if (semantics == "kick") return kind == StrikeKind::front || kind == StrikeKind::roundhouse || kind == StrikeKind::side;
    if (semantics_is_block(semantics)) {
        return kind == StrikeKind::rising || kind == StrikeKind::downward || kind == StrikeKind::inward || kind == StrikeKind::outward;
    }
    return false;
}

StrikeHeightThresholds strike_height_thresholds(const RestAnatomy& anatomy) {
    const auto midpoint = [&](int left, int right) { return 0.5 * (anatomy.rest_positions[left] + anatomy.rest_positions[right]); };
    const Eigen::Vector3d hips = midpoint(anatomy.limbs[static_cast<int>(Limb::leg_l)].root, anatomy.limbs[static_cast<int>(Limb::leg_r)].root);
    const Eigen::Vector3d shoulders = midpoint(anatomy.limbs[static_cast<int>(Limb::arm_l)].root, anatomy.limbs[static_cast<int>(Limb::arm_r)].root);
    StrikeHeightThresholds thresholds;
    thresholds.hip_m = anatomy.ankle_height + anatomy.leg_length;
    thresholds.shoulder_m = thresholds.hip_m + (shoulders - hips).norm(); // rest poses need not be upright
    return thresholds;
}

StrikeHeight strike_height_of(double hit_height_m, const StrikeHeightThresholds& thresholds) {
    if (hit_height_m < thresholds.hip_m) return StrikeHeight::low;
    if (hit_height_m > thresholds.shoulder_m) return StrikeHeight::high;
    return StrikeHeight::middle;
}

StrikeLabels strike_labels_propose(const Clip& clip, const RestAnatomy& anatomy, std::string_view semantics, BodyPart segment,
                                   int first_frame, int hit_frame) {
    StrikeLabels labels;
    const BodyMap& map = anatomy.body_map;
    const ContactPoint contact = contact_point_of(semantics, segment, map);
    const int pelvis = map.joint(BodyPart::pelvis);
    if (!contact.valid() || pelvis < 0 || clip.frame_count() == 0) return labels;
    hit_frame = std::clamp(hit_frame, 0, clip.frame_count() - 1);
    first_frame = std::clamp(first_frame, 0, hit_frame);
    const Skeleton& skeleton = clip.skeleton;
    std::vector<Eigen::Vector3d> positions(skeleton.joint_count());
    std::vector<Eigen::Quaterniond> rotations(skeleton.joint_count());
    const std::string_view name = body_part_name(segment);
    const bool left = name.ends_with("_l");
    const bool leg = segment == BodyPart::foot_l || segment == BodyPart::foot_r || segment == BodyPart::shin_l || segment == BodyPart::shin_r ||
                     segment == BodyPart::toe_l || segment == BodyPart::toe_r;
    const int root = anatomy.limbs[static_cast<int>(leg ? (left ? Limb::leg_l : Limb::leg_r) : (left ? Limb::arm_l : Limb::arm_r))].root;

    const int approach_frames = std::max({2, static_cast<int>(std::lround(k_approach_fraction * (hit_frame - first_frame))),
                                          clip.has_frame_rate() ? static_cast<int>(std::lround(k_min_approach_s / clip.frame_time_s)) : 2});
    forward_kinematics(positions, rotations, skeleton, clip.pose(std::max(0, hit_frame - approach_frames)));
    const Eigen::Vector3d approach_start = contact.at(positions);
    forward_kinematics(positions, rotations, skeleton, clip.pose(hit_frame));
    const Eigen::Vector3d hit_point = contact.at(positions);
    const Eigen::Vector3d approach = hit_point - approach_start;
    Eigen::Vector3d line = hit_point - positions[root];
    line.y() = 0.0;
    line = line.norm() > 1e-9 ? line.normalized() : Eigen::Vector3d::UnitZ();
    Eigen::Vector3d facing = (rotations[pelvis] * anatomy.rest_frames[pelvis]) * Eigen::Vector3d::UnitZ();
    facing.y() = 0.0;
    facing = facing.norm() > 1e-9 ? facing.normalized() : line;
    labels.approach_along_m = approach.dot(line);
    labels.approach_up_m = approach.y();
    labels.approach_sideways_m = std::abs(approach.cross(line).y());
    labels.hips_to_line_deg = std::acos(std::clamp(facing.dot(line), -1.0, 1.0)) * 180.0 / 3.14159265358979323846;

    const StrikeHeightThresholds thresholds = strike_height_thresholds(anatomy);
    labels.hip_height_m = thresholds.hip_m;
    labels.shoulder_height_m = thresholds.shoulder_m;
    labels.hit_height_m = hit_point.y() - anatomy.floor_y;
    labels.height = strike_height_of(labels.hit_height_m, thresholds);

    const double along = labels.approach_along_m, sideways = labels.approach_sideways_m, up = labels.approach_up_m;
    if (semantics == "punch") {
        if (up > std::hypot(along, sideways)) labels.kind = StrikeKind::uppercut;
        else if (sideways > along) labels.kind = StrikeKind::hook;
        else labels.kind = StrikeKind::straight;
    } else if (semantics == "kick") {
        if (sideways > along) labels.kind = StrikeKind::roundhouse;
        else if (labels.hips_to_line_deg > 55.0) labels.kind = StrikeKind::side;
        else labels.kind = StrikeKind::front;
    } else if (semantics_is_block(semantics)) {
        // Sideways relative to the body (the hips' facing), signed: out to the blocking arm's side is positive.
        const Eigen::Vector3d out_side = Eigen::Vector3d::UnitY().cross(facing) * (left ? 1.0 : -1.0); // +X of a heading is its left
        const double outward = approach.dot(out_side);
        if (up > 0.0 && labels.hit_height_m > labels.shoulder_height_m) labels.kind = StrikeKind::rising;
        else if (up < 0.0 && labels.hit_height_m < 0.5 * (labels.hip_height_m + labels.shoulder_height_m)) labels.kind = StrikeKind::downward;
        else labels.kind = outward > 0.0 ? StrikeKind::outward : StrikeKind::inward;
    } else {
        labels.kind = StrikeKind::other;
    }
    return labels;
}

} // namespace kumite
