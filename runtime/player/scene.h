#pragma once
// What a viewport draws, in world metres (Y up): a floor, skinned bodies, shaded capsules (bones), spheres (heads,
// targets, contact points), points and polylines (hit trajectories) and wire boxes (hit-path boxes). Plain data,
// rebuilt by the owner whenever it changes; the renderers (OpenGL, or QPainter when there is no OpenGL) only read it.

#include "kumite/core/skinned_mesh.h"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace kumite::view {

using Color = Eigen::Vector3f; // linear 0..1 RGB

struct Capsule {
    Eigen::Vector3f a = Eigen::Vector3f::Zero(), b = Eigen::Vector3f::Zero();
    float radius_m = 0.04f;
    Color color{0.8f, 0.8f, 0.8f};
    int id = -1; // returned by picking (e.g. the joint the bone ends at); -1: not pickable
    bool of_body = false; // the skeleton of a skinned body: OpenGL draws it only as the overlay; QPainter always
};

// A body skinned on the GPU (OpenGL only): the mesh is uploaded once per SkinnedMesh and shared by every body
// that points to it; `skin` are this frame's skin matrices (kumite/core/skinned_mesh.h), one per joint.
struct SkinnedBody {
    std::shared_ptr<const SkinnedMesh> mesh;
    std::vector<Eigen::Matrix4f> skin; // the mesh's own colours are on its vertices
};

struct Sphere {
    Eigen::Vector3f center = Eigen::Vector3f::Zero();
    float radius_m = 0.05f;
    Color color{1.0f, 0.3f, 0.3f};
    float opacity = 1.0f;
};

struct Polyline {
    std::vector<Eigen::Vector3f> points;
    Color color{1.0f, 0.8f, 0.2f};
    bool dots = false;      // draw the points as dots instead of a connected line
    float width_px = 2.0f;
};

struct WireBox {
    Eigen::Vector3f min = Eigen::Vector3f::Zero(), max = Eigen::Vector3f::Zero(); // in the box's own frame
    Color color{0.3f, 0.9f, 1.0f};
    Eigen::Matrix3f rotation = Eigen::Matrix3f::Identity(); // box frame -> world: rotation * p + origin
    Eigen::Vector3f origin = Eigen::Vector3f::Zero();
};

struct Scene {
    float floor_half_size_m = 3.0f; // the floor grid: a square around the origin, 0.5 m cells
    std::vector<SkinnedBody> bodies;
    bool skeleton_overlay = false; // OpenGL: draw the bodies' capsules (of_body) over them, seen through
    std::vector<Capsule> capsules;
    std::vector<Sphere> spheres;
    std::vector<Polyline> polylines;
    std::vector<WireBox> boxes;

    void clear() { bodies.clear(), capsules.clear(), spheres.clear(), polylines.clear(), boxes.clear(); }
};

} // namespace kumite::view
