#pragma once
// Geometry of a scene shared by the renderers and picking (no Qt).

#include "scene.h"
#include "view_camera.h"

#include <array>
#include <utility>
#include <vector>

namespace kumite::view {

// The capsule nearest to the eye among those the ray through a viewport point passes within their radius times
// `slack` (bones are thin). `ndc`: the point in normalized device coordinates (-1..1, y up). Returns the capsule's id, or -1.
int pick_capsule(const Scene& scene, const ViewProjection& view_projection, Eigen::Vector2f ndc, float slack = 1.5f);

// The ray from the eye through a viewport point (normalized device coordinates), world; direction unit length.
void view_ray(const ViewProjection& view_projection, Eigen::Vector2f ndc, Eigen::Vector3f& origin, Eigen::Vector3f& direction);

// Where the ray through `ndc` meets the plane through `through` that faces the camera (for dragging a point in
// the view). False when it misses (behind the eye).
bool point_on_facing_plane(const ViewProjection& view_projection, Eigen::Vector2f ndc, const Eigen::Vector3f& through,
                           Eigen::Vector3f& point);

// World point -> normalized device coordinates and the eye-space depth (positive in front of the eye).
// Returns false behind the eye.
bool project_point(const ViewProjection& view_projection, const Eigen::Vector3f& world, Eigen::Vector2f& ndc, float& depth);

// The floor grid: lines every 0.5 m over the square of half side `half_size_m`; `axis` marks the two through
// the origin.
struct FloorLine {
    Eigen::Vector3f a, b;
    bool axis = false;
};
std::vector<FloorLine> floor_grid_lines(float half_size_m);

// The 12 edges of a wire box, in world.
std::array<std::pair<Eigen::Vector3f, Eigen::Vector3f>, 12> wire_box_edges(const WireBox& box);

} // namespace kumite::view
