#pragma once
// The scene drawn with QPainter, for when there is no OpenGL (offscreen screenshots, remote displays): the floor
// grid, then capsules and spheres sorted far to near with a simple head-light shading, then lines and boxes on top.

#include "scene.h"
#include "view_camera.h"

#include <QRect>

class QPainter;

namespace kumite::view {

void paint_scene(QPainter& painter, const Scene& scene, const ViewProjection& view_projection, const QRect& viewport);

} // namespace kumite::view
