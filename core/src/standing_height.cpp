#include "kumite/core/standing_height.h"

#include "kumite/core/forward_kinematics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace kumite {
namespace {

// Model positions of every joint and End Site of one pose, joints first.
std::vector<Eigen::Vector3d> pose_points(const Skeleton& skeleton, const PoseView& pose) {
    const size_t joints = static_cast<size_t>(skeleton.joint_count());
    std::vector<Eigen::Vector3d> points(joints + skeleton.end_sites.size());
    std::vector<Eigen::Quaterniond> rotations(joints);
    forward_kinematics(std::span(points).first(joints), rotations, skeleton, pose);
    end_site_positions(std::span(points).subspan(joints), skeleton, std::span(points).first(joints), rotations);
    return points;
}

// [joint] true when the joint is `top` or below it; one pass, since parents come before children.
std::vector<bool> subtree_of(const Skeleton& skeleton, int top) {
    std::vector<bool> below(skeleton.joint_count(), false);
    if (top < 0) return below;
    for (int joint = top; joint < skeleton.joint_count(); ++joint) {
        below[joint] = joint == top || (skeleton.parents[joint] >= 0 && below[skeleton.parents[joint]]);
    }
    return below;
}

// The head and feet subtrees, found once per skeleton and reused for every measured pose.
struct BodyRegions {
    int head = -1;
    std::vector<bool> head_subtree;
    std::vector<bool> feet_subtree;

    BodyRegions(const Skeleton& skeleton, const BodyMap& map)
        : head(map.joint(BodyPart::head)), head_subtree(subtree_of(skeleton, head)),
          feet_subtree(subtree_of(skeleton, map.joint(BodyPart::foot_l))) {
        const std::vector<bool> right = subtree_of(skeleton, map.joint(BodyPart::foot_r));
        for (size_t joint = 0; joint < right.size(); ++joint) feet_subtree[joint] = feet_subtree[joint] || right[joint];
    }
};

// Head top: the highest of the head joint and the End Sites below it.
double head_top_y(const Skeleton& skeleton, const BodyRegions& regions, const std::vector<Eigen::Vector3d>& points) {
    double top = points[regions.head].y();
    for (size_t i = 0; i < skeleton.end_sites.size(); ++i) {
        if (regions.head_subtree[skeleton.end_sites[i].joint]) top = std::max(top, points[skeleton.joint_count() + i].y());
    }
    return top;
}

// Lowest point of the feet: foot and toe joints and the End Sites below them.
double foot_bottom_y(const Skeleton& skeleton, const BodyRegions& regions, const std::vector<Eigen::Vector3d>& points) {
    double bottom = std::numeric_limits<double>::infinity();
    for (int joint = 0; joint < skeleton.joint_count(); ++joint) {
        if (regions.feet_subtree[joint]) bottom = std::min(bottom, points[joint].y());
    }
    for (size_t i = 0; i < skeleton.end_sites.size(); ++i) {
        if (regions.feet_subtree[skeleton.end_sites[i].joint]) bottom = std::min(bottom, points[skeleton.joint_count() + i].y());
    }
    return bottom;
}

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    return values[values.size() / 2];
}

// Bone lengths along foot -> knee -> hip and pelvis -> ... -> head top, plus the two short vertical pieces
// that bone lengths cannot give (ankle above the sole, hip joints below the pelvis), taken as medians over
// frames. Bone lengths do not depend on the pose, so every clip of one skeleton gets nearly the same height.
StandingHeight chain_height(const Clip& clip, const BodyMap& map, const BodyRegions& regions) {
    const Skeleton& skeleton = clip.skeleton;
    double leg = 0.0;
    for (auto [shin, foot] : {std::pair{BodyPart::shin_l, BodyPart::foot_l}, std::pair{BodyPart::shin_r, BodyPart::foot_r}}) {
        if (map.has(shin) && map.has(foot)) {
            leg = std::max(leg, skeleton.rest_offsets[map.joint(shin)].norm() + skeleton.rest_offsets[map.joint(foot)].norm());
        }
    }
    const int pelvis = map.joint(BodyPart::pelvis);
    const int head = map.joint(BodyPart::head);
    double trunk = 0.0;
    for (int joint = head; joint != pelvis && joint >= 0; joint = skeleton.parents[joint]) {
        trunk += skeleton.rest_offsets[joint].norm();
    }
    double head_end = 0.0;
    for (const EndSite& end_site : skeleton.end_sites) {
        if (end_site.joint == head) head_end = std::max(head_end, end_site.offset_in_joint.norm());
    }

    const int stride = std::max(1, clip.frame_count() / 100);
    std::vector<double> ankle_heights, hip_drops;
    for (int frame = 0; frame < clip.frame_count(); frame += stride) {
        const std::vector<Eigen::Vector3d> points = pose_points(skeleton, clip.pose(frame));
        const double sole = foot_bottom_y(skeleton, regions, points);
        double ankle = std::numeric_limits<double>::infinity();
        double hip = -std::numeric_limits<double>::infinity();
        for (auto [thigh, foot] : {std::pair{BodyPart::thigh_l, BodyPart::foot_l}, std::pair{BodyPart::thigh_r, BodyPart::foot_r}}) {
            if (map.has(foot)) ankle = std::min(ankle, points[map.joint(foot)].y() - sole);
            if (map.has(thigh)) hip = std::max(hip, points[map.joint(thigh)].y());
        }
        ankle_heights.push_back(ankle);
        if (std::isfinite(hip)) hip_drops.push_back(points[pelvis].y() - hip);
    }
    const double ankle = median(ankle_heights);
    return {ankle + leg + median(hip_drops) + trunk + head_end, ankle, StandingHeight::Method::chain_lengths};
}

bool is_upright(const BodyMap& map, const std::vector<Eigen::Vector3d>& points) {
    const Eigen::Vector3d pelvis = points[map.joint(BodyPart::pelvis)];
    const Eigen::Vector3d head = points[map.joint(BodyPart::head)];
    const int foot = map.has(BodyPart::foot_l) ? map.joint(BodyPart::foot_l) : map.joint(BodyPart::foot_r);
    const Eigen::Vector3d up_trunk = head - pelvis;
    const Eigen::Vector3d down_leg = pelvis - points[foot];
    return up_trunk.y() > 0.7 * up_trunk.norm() && down_leg.y() > 0.7 * down_leg.norm();
}

double percentile_10(std::vector<double> values) {
    const size_t rank = values.size() / 10;
    std::nth_element(values.begin(), values.begin() + rank, values.end());
    return values[rank];
}

} // namespace

FloorEstimate floor_estimate(const Clip& clip, const BodyMap& body_map) {
    const Skeleton& skeleton = clip.skeleton;
    const BodyRegions regions(skeleton, body_map);
    std::vector<double> soles, ankles;
    auto measure = [&](const std::vector<Eigen::Vector3d>& points) {
        soles.push_back(foot_bottom_y(skeleton, regions, points));
        double ankle = std::numeric_limits<double>::infinity();
        for (BodyPart foot : {BodyPart::foot_l, BodyPart::foot_r}) {
            if (body_map.has(foot)) ankle = std::min(ankle, points[body_map.joint(foot)].y());
        }
        ankles.push_back(ankle);
    };
    if (clip.frame_count() == 0) measure(pose_points(skeleton, clip.rest_pose().view()));
    for (int frame = 0; frame < clip.frame_count(); ++frame) measure(pose_points(skeleton, clip.pose(frame))); // every frame: the floor is a minimum
    FloorEstimate estimate;
    estimate.floor_y = *std::min_element(soles.begin(), soles.end());
    if (std::abs(estimate.floor_y) < k_floor_snap_m) estimate.floor_y = 0.0;
    estimate.ankle_height = percentile_10(ankles) - estimate.floor_y;
    return estimate;
}

StandingHeight standing_height(const Clip& clip, const BodyMap& body_map) {
    const Skeleton& skeleton = clip.skeleton;
    if (skeleton.joint_count() == 0) return {};
    const Pose rest = clip.rest_pose();
    const std::vector<Eigen::Vector3d> rest_points = pose_points(skeleton, rest.view());

    const bool humanoid = body_map.has(BodyPart::pelvis) && body_map.has(BodyPart::head) &&
                          (body_map.has(BodyPart::foot_l) || body_map.has(BodyPart::foot_r));
    if (!humanoid) {
        Eigen::Vector3d low = rest_points[0], high = rest_points[0];
        for (const Eigen::Vector3d& p : rest_points) {
            low = low.cwiseMin(p);
            high = high.cwiseMax(p);
        }
        return {(high - low).maxCoeff(), 0.0, StandingHeight::Method::rest_pose_extent};
    }
    const BodyRegions regions(skeleton, body_map);
    if (is_upright(body_map, rest_points) || clip.frame_count() == 0) {
        const double sole = foot_bottom_y(skeleton, regions, rest_points);
        double ankle = std::numeric_limits<double>::infinity();
        for (BodyPart foot : {BodyPart::foot_l, BodyPart::foot_r}) {
            if (body_map.has(foot)) ankle = std::min(ankle, rest_points[body_map.joint(foot)].y() - sole);
        }
        return {head_top_y(skeleton, regions, rest_points) - sole, ankle, StandingHeight::Method::rest_pose};
    }
    return chain_height(clip, body_map, regions);
}

} // namespace kumite
