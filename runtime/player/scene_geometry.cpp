#include "scene_geometry.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>

namespace kumite::view {

bool project_point(const ViewProjection& vp, const Eigen::Vector3f& world, Eigen::Vector2f& ndc, float& depth) {
    const Eigen::Vector4f eye = vp.view * world.homogeneous();
    depth = -eye.z();
    const Eigen::Vector4f clip = vp.projection * eye;
    if (clip.w() <= 1e-6f) return false;
    ndc = clip.head<2>() / clip.w();
    return true;
}

void view_ray(const ViewProjection& vp, Eigen::Vector2f ndc, Eigen::Vector3f& origin, Eigen::Vector3f& direction) {
    const Eigen::Matrix4f inverse = (vp.projection * vp.view).inverse();
    const Eigen::Vector4f near_h = inverse * Eigen::Vector4f(ndc.x(), ndc.y(), -1.0f, 1.0f);
    const Eigen::Vector4f far_h = inverse * Eigen::Vector4f(ndc.x(), ndc.y(), 1.0f, 1.0f);
    origin = near_h.head<3>() / near_h.w();
    direction = (far_h.head<3>() / far_h.w() - origin).normalized();
}

bool point_on_facing_plane(const ViewProjection& vp, Eigen::Vector2f ndc, const Eigen::Vector3f& through, Eigen::Vector3f& point) {
    Eigen::Vector3f origin, direction;
    view_ray(vp, ndc, origin, direction);
    const Eigen::Vector3f normal = -vp.view.block<1, 3>(2, 0).transpose(); // where the camera looks
    const float along = direction.dot(normal);
    if (std::abs(along) < 1e-6f) return false;
    const float s = (through - origin).dot(normal) / along;
    if (!(s > 0.0f)) return false;
    point = origin + s * direction;
    return true;
}

int pick_capsule(const Scene& scene, const ViewProjection& vp, Eigen::Vector2f ndc, float slack) {
    Eigen::Vector3f origin, direction;
    view_ray(vp, ndc, origin, direction);
    int best = -1;
    float best_along = std::numeric_limits<float>::max();
    for (const Capsule& capsule : scene.capsules) {
        if (capsule.id < 0) continue;
        // Closest points between the ray origin + s d (s >= 0) and the segment a + t (b - a), t in 0..1.
        const Eigen::Vector3f u = capsule.b - capsule.a, w0 = origin - capsule.a;
        const float a = u.dot(u), b = u.dot(direction), c = 1.0f, d = u.dot(w0), e = direction.dot(w0);
        const float denominator = a * c - b * b;
        float t = denominator > 1e-9f ? std::clamp((d * c - b * e) / denominator, 0.0f, 1.0f) : 0.0f;
        float s = std::max(0.0f, b * t - e);
        // Re-project t for the clamped s.
        if (a > 1e-12f) t = std::clamp((s * b + d) / a, 0.0f, 1.0f);
        const Eigen::Vector3f on_ray = origin + s * direction, on_segment = capsule.a + t * u;
        if ((on_ray - on_segment).norm() <= capsule.radius_m * slack && s < best_along) {
            best_along = s;
            best = capsule.id;
        }
    }
    return best;
}

std::vector<FloorLine> floor_grid_lines(float half) {
    std::vector<FloorLine> lines;
    const int cells = std::max(1, int(std::lround(half / 0.5f)));
    for (int i = -cells; i <= cells; ++i) {
        const float v = i * 0.5f;
        lines.push_back({{v, 0, -half}, {v, 0, half}, i == 0});
        lines.push_back({{-half, 0, v}, {half, 0, v}, i == 0});
    }
    return lines;
}

std::array<std::pair<Eigen::Vector3f, Eigen::Vector3f>, 12> wire_box_edges(const WireBox& box) {
    std::array<std::pair<Eigen::Vector3f, Eigen::Vector3f>, 12> edges;
    for (int edge = 0; edge < 12; ++edge) { // for each axis, the 4 edges along it
        const int axis = edge / 4, corner = edge % 4;
        Eigen::Vector3f a, b;
        for (int k = 0, bit = 0; k < 3; ++k) {
            if (k == axis) {
                a[k] = box.min[k], b[k] = box.max[k];
            } else {
                a[k] = b[k] = ((corner >> bit++) & 1) ? box.max[k] : box.min[k];
            }
        }
        edges[edge] = {box.rotation * a + box.origin, box.rotation * b + box.origin};
    }
    return edges;
}

} // namespace kumite::view
