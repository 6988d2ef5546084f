#pragma once
// What the player shows of a bout, as a Scene: every fighter as its skinned body (with its skeleton's capsules as
// the overlay) or, for a character without a body, as capsules on its current skeleton; the user's head,
// and for a striking fighter the latched target (a see-through sphere of the hit radius), the retrieved hit
// trajectory (the database path of the hit segment from the strike's start to its contact, scaled to the
// character and placed where the retrieval put it), and its bounding box in the fighter's heading frame.

#include "scene.h"

#include "kumite/runtime/bout.h"

namespace kumite::view {

// A skeleton's bones as capsules: one per joint with a parent, from the parent to the joint, picking id
// `id_base + joint`. `model_positions`: world metres, [joint].
void add_skeleton_capsules(Scene& scene, const Skeleton& skeleton, std::span<const Eigen::Vector3d> model_positions, float radius_m,
                           const Color& color, int id_base = -1, bool of_body = false);

// A body in a pose: its skin matrices from forward kinematics, its base colour.
void add_skinned_body(Scene& scene, const std::shared_ptr<const SkinnedMesh>& mesh, const Skeleton& skeleton, const PoseView& pose);

// Rebuilds `scene` from the bout's current frame.
void player_scene_build(const Bout& bout, Scene& scene);

// The retrieved strike's hit path in world metres, from its start to its contact (empty when not striking).
void strike_path_world(const Fighter& fighter, const MotionDatabaseView& database, std::vector<Eigen::Vector3f>& path);

} // namespace kumite::view
