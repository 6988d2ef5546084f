#pragma once
// A viewport widget that draws a Scene: OpenGL (3.3 core: shaded capsules, spheres, lines, boxes on a floor grid)
// when the platform offers it, otherwise the same scene painted with QPainter (QT_QPA_PLATFORM=offscreen, remote
// X without GLX) so screenshots and tests work everywhere. Mouse: left drag orbits, right or middle drag pans,
// wheel zooms, a click without drag picks the capsule under the cursor (signal `picked`). The owner edits
// `scene()` and calls `update()`.

#include "scene.h"
#include "view_camera.h"

#include <QImage>
#include <QWidget>

#include <vector>

#include <functional>

namespace kumite::view {

enum class Projection { orbit, head_coupled };
enum class StereoMode { mono, side_by_side, quad_buffer };

struct HeadCoupling {
    ScreenCorners screen;
    Eigen::Vector3f eye_world{0.0f, 1.65f, 1.5f}; // the tracked eye (between both eyes in stereo)
    float eye_separation_m = 0.064f;
    Eigen::Vector3f right_world = Eigen::Vector3f::UnitX(); // the line between the eyes, for stereo
};

class SceneView : public QWidget {
    Q_OBJECT
public:
    explicit SceneView(QWidget* parent = nullptr);
    ~SceneView() override;

    Scene& scene() { return m_scene; }
    const Scene& scene() const { return m_scene; }
    OrbitCamera& orbit_camera() { return m_orbit; }

    void set_projection(Projection projection) { m_projection = projection; update(); }
    Projection projection() const { return m_projection; }
    void set_head_coupling(const HeadCoupling& coupling) { m_coupling = coupling; update(); }
    const HeadCoupling& head_coupling() const { return m_coupling; }
    void set_stereo(StereoMode mode); // quad_buffer falls back to side_by_side when the context has no stereo
    StereoMode stereo() const { return m_stereo; }
    bool quad_buffer_available() const;

    void frame_scene(); // the orbit camera looks at everything in the scene
    bool uses_opengl() const { return m_gl != nullptr; }
    QString renderer_description() const; // "OpenGL 4.5 (llvmpipe)" or "QPainter (no OpenGL)"
    int body_mesh_uploads() const;        // skinned meshes the OpenGL renderer has uploaded (0 without OpenGL)

    // Picking: the id of the nearest pickable capsule under the widget point, or -1.
    int pick(QPoint point) const;
    // The view of one eye (or the only one), for a viewport of this aspect.
    ViewProjection view_projection(float aspect, int eye = 0) const;

    void update();
    // The view as drawn, overlay included (QWidget::grab() of a window leaves the overlay out of OpenGL views).
    QImage grab_image();

    // Drawn over the scene in widget coordinates after every frame (a HUD), in both renderers.
    void set_overlay(std::function<void(QPainter&, const QRect&)> overlay) { m_overlay = std::move(overlay); }

signals:
    void picked(int id);
    void camera_changed();

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

private:
    class GlWidget;
    friend class GlWidget;
    Scene m_scene;
    OrbitCamera m_orbit;
    Projection m_projection = Projection::orbit;
    HeadCoupling m_coupling;
    StereoMode m_stereo = StereoMode::mono;
    GlWidget* m_gl = nullptr; // child filling the widget, or null when painting
    std::function<void(QPainter&, const QRect&)> m_overlay;
    // The eye viewports (one in mono, two side by side) in widget pixels.
    std::vector<QRect> eye_viewports() const;
    QPoint m_press_point, m_last_point;
    Qt::MouseButton m_button = Qt::NoButton;
    bool m_dragged = false;
};

// Whether this process can create an OpenGL 3.3 context (false under QT_QPA_PLATFORM=offscreen).
bool opengl_available();

} // namespace kumite::view
