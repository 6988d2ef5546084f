#include "scene_builder.h"

#include "kumite/core/forward_kinematics.h"

namespace kumite::annotate {
namespace {

const view::Color k_bone_color{0.78f, 0.80f, 0.84f};
const view::Color k_hit_bone_color{1.0f, 0.55f, 0.15f};
const view::Color k_trajectory_color{1.0f, 0.85f, 0.2f};
const view::Color k_proposal_color{0.45f, 0.95f, 0.45f};
const view::Color k_contact_color{1.0f, 0.2f, 0.2f};
const view::Color k_box_color{0.3f, 0.85f, 1.0f};

Eigen::Vector3f lowered(const Eigen::Vector3d& world, double floor_y) {
    return Eigen::Vector3f(float(world.x()), float(world.y() - floor_y), float(world.z()));
}

void add_skeleton(view::Scene& scene, const LoadedCapture& capture, int frame, double floor_y, std::optional<BodyPart> highlight) {
    const Skeleton& skeleton = capture.file.clip.skeleton;
    std::vector<Eigen::Vector3d> positions(size_t(skeleton.joint_count()));
    std::vector<Eigen::Quaterniond> rotations(size_t(skeleton.joint_count()));
    forward_kinematics(positions, rotations, skeleton, capture.file.clip.pose(frame));
    std::vector<Eigen::Vector3d> end_sites(skeleton.end_sites.size());
    end_site_positions(end_sites, skeleton, positions, rotations);

    const float radius = float(std::max(0.01, 0.022 * std::max(capture.file.height_m, 0.3) / 1.7));
    auto add_bone = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b, int start_joint) {
        view::Capsule capsule;
        capsule.a = lowered(a, floor_y);
        capsule.b = lowered(b, floor_y);
        capsule.radius_m = radius;
        capsule.id = start_joint;
        const std::optional<BodyPart> part = scene_part_of_pick(capture, start_joint);
        capsule.color = highlight && part == highlight ? k_hit_bone_color : k_bone_color;
        scene.capsules.push_back(capsule);
    };
    for (int joint = 1; joint < skeleton.joint_count(); ++joint) {
        const int parent = skeleton.parents[size_t(joint)];
        add_bone(positions[size_t(parent)], positions[size_t(joint)], parent);
    }
    for (size_t site = 0; site < skeleton.end_sites.size(); ++site) {
        const int joint = skeleton.end_sites[site].joint;
        add_bone(positions[size_t(joint)], end_sites[site], joint);
    }
}

void add_box_edges(view::Scene& scene, const std::array<Eigen::Vector3d, 8>& corners, double floor_y, const view::Color& color) {
    for (int a = 0; a < 8; ++a) {
        for (int bit = 1; bit < 8; bit <<= 1) {
            if (a & bit) continue; // each edge once: from the corner with the bit clear
            view::Polyline edge;
            edge.points = {lowered(corners[size_t(a)], floor_y), lowered(corners[size_t(a | bit)], floor_y)};
            edge.color = color;
            edge.width_px = 1.5f;
            scene.polylines.push_back(std::move(edge));
        }
    }
}

} // namespace

std::optional<BodyPart> scene_part_of_pick(const LoadedCapture& capture, int picked_joint) {
    const Skeleton& skeleton = capture.file.clip.skeleton;
    for (int joint = picked_joint; joint >= 0 && joint < skeleton.joint_count(); joint = skeleton.parents[size_t(joint)]) {
        if (const std::optional<BodyPart> part = capture.file.body_map.part_of(joint)) return part;
    }
    return std::nullopt;
}

const Result<ClipTrajectory>& TrajectoryCache::get(const LoadedCapture& capture, const StrikeOnShow& strike) {
    if (!m_trajectory || m_capture_path != capture.path || m_strike != strike) {
        m_trajectory.emplace(clip_trajectory_compute(capture, strike.block ? "block" : "strike", strike.segment, strike.first_frame, strike.hit_frame,
                                                     strike.last_frame));
        m_capture_path = capture.path;
        m_strike = strike;
    }
    return *m_trajectory;
}

void scene_build(view::Scene& scene, const LoadedCapture& capture, int frame, std::optional<BodyPart> highlight,
                 const ClipTrajectory* trajectory, bool proposal) {
    scene.clear();
    const int frame_count = capture.file.clip.frame_count();
    if (frame_count == 0) return;
    const double floor_y = capture.anatomy ? capture.anatomy->floor_y : 0.0;
    add_skeleton(scene, capture, std::clamp(frame, 0, frame_count - 1), floor_y, highlight);
    if (!trajectory) return;

    // The path to the hit (what the box holds) in full colour, the recovery after it dimmer and smaller.
    const view::Color color = proposal ? k_proposal_color : k_trajectory_color;
    view::Polyline to_hit, after_hit;
    to_hit.dots = after_hit.dots = true;
    to_hit.width_px = 5.0f;
    after_hit.width_px = 3.5f;
    to_hit.color = color;
    after_hit.color = color * 0.55f;
    for (size_t index = 0; index < trajectory->points_world.size(); ++index) {
        (int(index) <= trajectory->hit_index ? to_hit : after_hit).points.push_back(lowered(trajectory->points_world[index], floor_y));
    }
    scene.polylines.push_back(std::move(to_hit));
    if (!after_hit.points.empty()) scene.polylines.push_back(std::move(after_hit));
    view::Sphere contact;
    contact.center = lowered(trajectory->contact_world, floor_y);
    contact.radius_m = float(std::max(0.03, 0.055 * capture.file.height_m / 1.7));
    contact.color = k_contact_color;
    scene.spheres.push_back(contact);
    add_box_edges(scene, trajectory->box_corners_world, floor_y, proposal ? k_proposal_color : k_box_color);
}

} // namespace kumite::annotate
