#include "player_scene.h"

#include "kumite/core/forward_kinematics.h"

#include <Eigen/Geometry>

namespace kumite::view {
namespace {

const Color k_fighter_colors[] = {{0.86f, 0.55f, 0.25f}, {0.35f, 0.62f, 0.86f}, {0.55f, 0.78f, 0.40f}, {0.80f, 0.45f, 0.70f}};

} // namespace

void strike_path_world(const Fighter& fighter, const MotionDatabaseView& db, std::vector<Eigen::Vector3f>& path) {
    path.clear();
    const StrikePlan& plan = fighter.strike_plan();
    if (plan.clip < 0 || plan.clip >= int(db.clips.size())) return;
    const DbClip& clip = db.clips[plan.clip];
    const float actor_leg = db.actors[clip.actor].leg_length_m;
    const double scale = actor_leg > 0.0f ? fighter.leg_length() / actor_leg : 1.0;
    for (int frame = plan.start_frame; frame <= plan.contact_frame && frame < int(clip.frame_count); ++frame) {
        const DbPose& pose = db.poses[clip.first_pose + frame];
        const Eigen::Vector3d point(pose.hit_point[0], pose.hit_point[1], pose.hit_point[2]);
        path.push_back(plan.clip_to_world.apply(point * scale).cast<float>());
    }
}

void add_skeleton_capsules(Scene& scene, const Skeleton& skeleton, std::span<const Eigen::Vector3d> model_positions, float radius_m,
                           const Color& color, int id_base, bool of_body) {
    for (int joint = 1; joint < skeleton.joint_count() && joint < int(model_positions.size()); ++joint) {
        const int parent = skeleton.parents[joint];
        if (parent < 0) continue;
        Capsule bone;
        bone.a = model_positions[parent].cast<float>();
        bone.b = model_positions[joint].cast<float>();
        bone.radius_m = radius_m;
        bone.color = color;
        bone.id = id_base < 0 ? -1 : id_base + joint;
        bone.of_body = of_body;
        scene.capsules.push_back(bone);
    }
}

void add_skinned_body(Scene& scene, const std::shared_ptr<const SkinnedMesh>& mesh, const Skeleton& skeleton, const PoseView& pose) {
    const std::size_t joints = std::size_t(skeleton.joint_count());
    if (!mesh || mesh->bind_to_rest.size() != joints) return;
    std::vector<Eigen::Vector3d> positions(joints);
    std::vector<Eigen::Quaterniond> rotations(joints);
    forward_kinematics(positions, rotations, skeleton, pose);
    SkinnedBody body;
    body.mesh = mesh;
    body.skin.resize(joints);
    skin_matrices(body.skin, *mesh, positions, rotations);
    scene.bodies.push_back(std::move(body));
}

void player_scene_build(const Bout& bout, Scene& scene) {
    scene.clear();
    scene.floor_half_size_m = 3.0f;
    for (int f = 0; f < bout.fighter_count(); ++f) {
        const Fighter& fighter = bout.fighter(f);
        const Skeleton& skeleton = bout.character_skeleton(fighter.character());
        const auto positions = fighter.positions();
        const Color color = k_fighter_colors[f % 4];
        const std::shared_ptr<const SkinnedMesh>& body = bout.character_body(fighter.character());
        if (body) add_skinned_body(scene, body, skeleton, fighter.pose().view());
        // Under a body the capsules are its skeleton overlay (and what QPainter draws).
        add_skeleton_capsules(scene, skeleton, positions, float(0.045 * fighter.leg_length() / 0.9), color, f * 1000, bool(body));
        if (fighter.state() != FighterState::strike) continue;
        Sphere target;
        target.center = fighter.latched_target().cast<float>();
        target.radius_m = 0.12f;
        target.color = {1.0f, 0.25f, 0.2f};
        target.opacity = 0.35f;
        scene.spheres.push_back(target);
        Polyline path;
        path.dots = true;
        path.width_px = 3.0f;
        path.color = {1.0f, 0.85f, 0.2f};
        strike_path_world(fighter, bout.database(), path.points);
        if (!path.points.empty()) {
            // The path's box in the fighter's heading frame.
            const HeadingFrame heading = fighter.heading();
            const Eigen::Matrix3f to_world = Eigen::AngleAxisf(float(heading.yaw_rad), Eigen::Vector3f::UnitY()).toRotationMatrix();
            WireBox box;
            box.rotation = to_world;
            box.origin = heading.origin.cast<float>();
            box.min = box.max = to_world.transpose() * (path.points[0] - box.origin);
            for (const Eigen::Vector3f& p : path.points) {
                const Eigen::Vector3f local = to_world.transpose() * (p - box.origin);
                box.min = box.min.cwiseMin(local), box.max = box.max.cwiseMax(local);
            }
            scene.boxes.push_back(box);
            scene.polylines.push_back(std::move(path));
        }
    }
    if (const Eigen::Vector3d* head = bout.head()) {
        Sphere sphere;
        sphere.center = head->cast<float>();
        sphere.radius_m = 0.1f;
        sphere.color = {0.9f, 0.85f, 0.75f};
        scene.spheres.push_back(sphere);
    }
    const UserHands& hands = bout.hands();
    for (int side = 0; side < 2; ++side) {
        if (!hands.present[side]) continue;
        Sphere sphere;
        sphere.center = hands.world[side].cast<float>();
        sphere.radius_m = 0.05f;
        sphere.color = side == 0 ? Eigen::Vector3f(0.95f, 0.6f, 0.35f) : Eigen::Vector3f(0.35f, 0.75f, 0.95f);
        scene.spheres.push_back(sphere);
    }
}

} // namespace kumite::view
