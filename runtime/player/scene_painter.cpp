#include "scene_painter.h"

#include "scene_geometry.h"

#include <QPainter>
#include <QRadialGradient>

#include <algorithm>
#include <cmath>
#include <vector>

namespace kumite::view {
namespace {

QColor to_qcolor(const Color& color, float shade = 1.0f, float opacity = 1.0f) {
    auto channel = [&](float v) { return std::clamp(int(std::lround(255.0f * std::clamp(v * shade, 0.0f, 1.0f))), 0, 255); };
    return QColor(channel(color.x()), channel(color.y()), channel(color.z()), std::clamp(int(opacity * 255.0f), 0, 255));
}

struct Projector {
    const ViewProjection& vp;
    QRect viewport;
    float focal_px; // pixels per metre at one metre depth

    bool to_screen(const Eigen::Vector3f& world, QPointF& point, float& depth) const {
        Eigen::Vector2f ndc;
        if (!project_point(vp, world, ndc, depth) || depth < 0.02f) return false;
        point = QPointF(viewport.left() + (ndc.x() * 0.5f + 0.5f) * viewport.width(), viewport.top() + (0.5f - ndc.y() * 0.5f) * viewport.height());
        return true;
    }
};

void draw_segment(QPainter& painter, const Projector& projector, const Eigen::Vector3f& a, const Eigen::Vector3f& b, const QPen& pen) {
    QPointF pa, pb;
    float da, db;
    // Clip to the front of the eye by bisection: enough for a floor grid and boxes.
    Eigen::Vector3f first = a, second = b;
    bool ok_a = projector.to_screen(first, pa, da), ok_b = projector.to_screen(second, pb, db);
    if (!ok_a && !ok_b) return;
    if (!ok_a || !ok_b) {
        Eigen::Vector3f inside = ok_a ? first : second, outside = ok_a ? second : first;
        for (int i = 0; i < 20; ++i) {
            const Eigen::Vector3f middle = 0.5f * (inside + outside);
            QPointF p;
            float d;
            (projector.to_screen(middle, p, d) ? inside : outside) = middle;
        }
        (ok_a ? second : first) = inside;
        projector.to_screen(first, pa, da);
        projector.to_screen(second, pb, db);
    }
    painter.setPen(pen);
    painter.drawLine(pa, pb);
}

} // namespace

void paint_scene(QPainter& painter, const Scene& scene, const ViewProjection& vp, const QRect& viewport) {
    painter.save();
    painter.setClipRect(viewport);
    painter.setRenderHint(QPainter::Antialiasing, true);
    QLinearGradient sky(viewport.topLeft(), viewport.bottomLeft());
    sky.setColorAt(0.0, QColor(46, 52, 64));
    sky.setColorAt(1.0, QColor(24, 26, 32));
    painter.fillRect(viewport, sky);
    const Projector projector{vp, viewport, vp.projection(1, 1) * 0.5f * float(viewport.height())};

    // The floor grid.
    for (const FloorLine& line : floor_grid_lines(scene.floor_half_size_m)) {
        const QPen pen(line.axis ? QColor(110, 118, 135) : QColor(70, 76, 90), line.axis ? 1.5 : 1.0);
        draw_segment(painter, projector, line.a, line.b, pen);
    }

    // Solids far to near.
    struct Solid {
        float depth;
        int capsule = -1, sphere = -1;
    };
    std::vector<Solid> solids;
    const Eigen::Vector3f eye = vp.eye;
    for (int i = 0; i < int(scene.capsules.size()); ++i) {
        const Capsule& c = scene.capsules[i];
        solids.push_back({(0.5f * (c.a + c.b) - eye).norm(), i, -1});
    }
    for (int i = 0; i < int(scene.spheres.size()); ++i) solids.push_back({(scene.spheres[i].center - eye).norm(), -1, i});
    std::sort(solids.begin(), solids.end(), [](const Solid& x, const Solid& y) { return x.depth > y.depth; });
    const Eigen::Vector3f view_direction = -vp.view.block<1, 3>(2, 0).transpose(); // where the camera looks
    for (const Solid& solid : solids) {
        if (solid.capsule >= 0) {
            const Capsule& c = scene.capsules[solid.capsule];
            QPointF pa, pb;
            float da, db;
            if (!projector.to_screen(c.a, pa, da) || !projector.to_screen(c.b, pb, db)) continue;
            const float width = 2.0f * c.radius_m * projector.focal_px / (0.5f * (da + db));
            // Bones across the view are lit fully, bones pointing at the eye a little darker.
            const Eigen::Vector3f axis = (c.b - c.a).normalized();
            const float across = std::sqrt(std::max(0.0f, 1.0f - std::pow(axis.dot(view_direction), 2.0f)));
            QPen body(to_qcolor(c.color, 0.55f + 0.3f * across), width, Qt::SolidLine, Qt::RoundCap);
            painter.setPen(body);
            painter.drawLine(pa, pb);
            QPen highlight(to_qcolor(c.color, 1.1f, 0.8f), width * 0.35f, Qt::SolidLine, Qt::RoundCap);
            painter.setPen(highlight);
            const QPointF lift(-width * 0.15f, -width * 0.15f);
            painter.drawLine(pa + lift, pb + lift);
        } else {
            const Sphere& s = scene.spheres[solid.sphere];
            QPointF center;
            float depth;
            if (!projector.to_screen(s.center, center, depth)) continue;
            const float radius = s.radius_m * projector.focal_px / depth;
            QRadialGradient gradient(center - QPointF(radius * 0.35f, radius * 0.35f), radius * 1.3f);
            gradient.setColorAt(0.0, to_qcolor(s.color, 1.25f, s.opacity));
            gradient.setColorAt(1.0, to_qcolor(s.color, 0.45f, s.opacity));
            painter.setPen(Qt::NoPen);
            painter.setBrush(gradient);
            painter.drawEllipse(center, radius, radius);
        }
    }

    // Lines, dots and boxes on top.
    painter.setBrush(Qt::NoBrush);
    for (const Polyline& line : scene.polylines) {
        const QColor color = to_qcolor(line.color);
        if (line.dots) {
            painter.setPen(Qt::NoPen);
            painter.setBrush(color);
            for (const Eigen::Vector3f& p : line.points) {
                QPointF point;
                float depth;
                if (projector.to_screen(p, point, depth)) painter.drawEllipse(point, line.width_px, line.width_px);
            }
            painter.setBrush(Qt::NoBrush);
        } else {
            const QPen pen(color, line.width_px);
            for (std::size_t i = 1; i < line.points.size(); ++i) draw_segment(painter, projector, line.points[i - 1], line.points[i], pen);
        }
    }
    for (const WireBox& box : scene.boxes) {
        const QPen pen(to_qcolor(box.color), 1.5);
        for (const auto& [a, b] : wire_box_edges(box)) draw_segment(painter, projector, a, b, pen);
    }
    painter.restore();
}

} // namespace kumite::view
