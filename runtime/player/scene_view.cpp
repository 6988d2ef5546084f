#include "scene_view.h"

#include "scene_geometry.h"
#include "scene_gl_renderer.h"
#include "scene_painter.h"

#include <QGuiApplication>
#include <QMouseEvent>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLWidget>
#include <QPainter>
#include <QVBoxLayout>
#include <QWheelEvent>

namespace kumite::view {
namespace {

QSurfaceFormat scene_format() {
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    format.setSamples(4);
    return format;
}

} // namespace

bool opengl_available() {
    static const bool available = [] {
        if (QGuiApplication::platformName() == "offscreen" || QGuiApplication::platformName() == "minimal") return false;
        QOpenGLContext context;
        context.setFormat(scene_format());
        if (!context.create()) return false;
        const QSurfaceFormat got = context.format();
        return got.majorVersion() * 10 + got.minorVersion() >= 33;
    }();
    return available;
}

class SceneView::GlWidget : public QOpenGLWidget {
public:
    explicit GlWidget(SceneView* owner) : QOpenGLWidget(owner), m_owner(owner) {
        setFormat(scene_format());
        setAttribute(Qt::WA_TransparentForMouseEvents); // the owner handles the mouse
    }
    ~GlWidget() override {
        if (context()) {
            makeCurrent();
            m_renderer.release();
            doneCurrent();
        }
    }
    QString description;

protected:
    void initializeGL() override {
        QString error;
        if (!m_renderer.initialize(error)) qWarning("kumite viewer: OpenGL shaders failed: %s", qPrintable(error));
        const QSurfaceFormat got = context()->format();
        auto* functions = context()->functions();
        description = QString("OpenGL %1.%2 (%3)").arg(got.majorVersion()).arg(got.minorVersion())
                          .arg(reinterpret_cast<const char*>(functions->glGetString(GL_RENDERER)));
    }
    void paintGL() override {
        const qreal ratio = devicePixelRatioF();
        QPainter painter(this); // the GL drawing is native painting inside it, the HUD is painted after
        painter.beginNativePainting();
        const std::vector<QRect> viewports = m_owner->eye_viewports();
        for (int eye = 0; eye < int(viewports.size()); ++eye) {
            const QRect& r = viewports[eye];
            const QRect device(int(r.x() * ratio), int((height() - r.bottom() - 1) * ratio), int(r.width() * ratio), int(r.height() * ratio));
            m_renderer.render(m_owner->m_scene, m_owner->view_projection(float(r.width()) / std::max(1, r.height()), eye), device);
        }
        painter.endNativePainting();
        if (m_owner->m_overlay) m_owner->m_overlay(painter, rect());
    }

private:
    SceneView* m_owner;
    SceneGlRenderer m_renderer;

public:
    int body_mesh_uploads() const { return m_renderer.body_mesh_uploads(); }
};

SceneView::SceneView(QWidget* parent) : QWidget(parent) {
    setMinimumSize(200, 150);
    setFocusPolicy(Qt::StrongFocus);
    if (opengl_available()) {
        auto* layout = new QVBoxLayout(this);
        layout->setContentsMargins(0, 0, 0, 0);
        m_gl = new GlWidget(this);
        layout->addWidget(m_gl);
    }
}

SceneView::~SceneView() = default;

void SceneView::set_stereo(StereoMode mode) {
    // QOpenGLWidget renders into a framebuffer object: quad-buffer output needs Qt 6.5's stereoscopic
    // QOpenGLWidget, so on older Qt (Debian 12 has 6.4) the views go side by side.
    m_stereo = (mode == StereoMode::quad_buffer && !quad_buffer_available()) ? StereoMode::side_by_side : mode;
    update();
}

bool SceneView::quad_buffer_available() const { return false; }

int SceneView::body_mesh_uploads() const { return m_gl ? m_gl->body_mesh_uploads() : 0; }

QString SceneView::renderer_description() const {
    if (m_gl) {
        const QString base = m_gl->description.isEmpty() ? QString("OpenGL") : m_gl->description;
        const int uploads = m_gl->body_mesh_uploads();
        return uploads == 0 ? base : base + QString(", %1 body mesh%2 on the GPU").arg(uploads).arg(uploads == 1 ? "" : "es");
    }
    return "QPainter (no OpenGL on this display)";
}

std::vector<QRect> SceneView::eye_viewports() const {
    if (m_stereo == StereoMode::mono) return {rect()};
    const int half = width() / 2;
    return {QRect(0, 0, half, height()), QRect(half, 0, width() - half, height())};
}

ViewProjection SceneView::view_projection(float aspect, int eye) const {
    const float sign = m_stereo == StereoMode::mono ? 0.0f : (eye == 0 ? -0.5f : 0.5f);
    if (m_projection == Projection::head_coupled) {
        const Eigen::Vector3f position = m_coupling.eye_world + sign * m_coupling.eye_separation_m * m_coupling.right_world.normalized();
        return off_axis_view_projection(m_coupling.screen, position, 0.05f, 50.0f);
    }
    ViewProjection vp = m_orbit.view_projection(aspect);
    if (sign != 0.0f) { // parallel eyes: shift the view sideways
        const float shift = sign * m_coupling.eye_separation_m;
        Eigen::Matrix4f offset = Eigen::Matrix4f::Identity();
        offset(0, 3) = -shift;
        vp.eye += shift * vp.view.block<1, 3>(0, 0).transpose();
        vp.view = offset * vp.view;
    }
    return vp;
}

void SceneView::frame_scene() {
    Eigen::AlignedBox3f box;
    for (const Capsule& c : m_scene.capsules) box.extend(c.a), box.extend(c.b);
    for (const Sphere& s : m_scene.spheres) box.extend(s.center);
    for (const WireBox& b : m_scene.boxes) {
        for (const auto& [p, q] : wire_box_edges(b)) box.extend(p), box.extend(q);
    }
    if (box.isEmpty()) box = Eigen::AlignedBox3f(Eigen::Vector3f(-1, 0, -1), Eigen::Vector3f(1, 2, 1));
    m_orbit.frame(box);
    update();
    emit camera_changed();
}

int SceneView::pick(QPoint point) const {
    for (int eye = 0; const QRect& r : eye_viewports()) {
        if (r.contains(point)) {
            const Eigen::Vector2f ndc(2.0f * (point.x() - r.x() + 0.5f) / r.width() - 1.0f, 1.0f - 2.0f * (point.y() - r.y() + 0.5f) / r.height());
            return pick_capsule(m_scene, view_projection(float(r.width()) / std::max(1, r.height()), eye), ndc);
        }
        ++eye;
    }
    return -1;
}

void SceneView::update() {
    if (m_gl) m_gl->update();
    QWidget::update();
}

QImage SceneView::grab_image() { return m_gl ? m_gl->grabFramebuffer() : grab().toImage(); }

void SceneView::paintEvent(QPaintEvent*) {
    if (m_gl) return;
    QPainter painter(this);
    const std::vector<QRect> viewports = eye_viewports();
    for (int eye = 0; eye < int(viewports.size()); ++eye) {
        const QRect& r = viewports[eye];
        paint_scene(painter, m_scene, view_projection(float(r.width()) / std::max(1, r.height()), eye), r);
    }
    if (m_overlay) m_overlay(painter, rect());
}

void SceneView::mousePressEvent(QMouseEvent* event) {
    m_press_point = m_last_point = event->position().toPoint();
    m_button = event->button();
    m_dragged = false;
}

void SceneView::mouseMoveEvent(QMouseEvent* event) {
    if (m_button == Qt::NoButton) return;
    const QPoint point = event->position().toPoint();
    const QPoint delta = point - m_last_point;
    m_last_point = point;
    if ((point - m_press_point).manhattanLength() > 3) m_dragged = true;
    if (!m_dragged || m_projection == Projection::head_coupled) return;
    if (m_button == Qt::LeftButton) m_orbit.orbit(float(delta.x()), float(delta.y()));
    else m_orbit.pan(float(delta.x()), float(delta.y()), float(height()));
    update();
    emit camera_changed();
}

void SceneView::mouseReleaseEvent(QMouseEvent* event) {
    if (m_button == Qt::LeftButton && !m_dragged) {
        const int id = pick(event->position().toPoint());
        if (id >= 0) emit picked(id);
    }
    m_button = Qt::NoButton;
}

void SceneView::wheelEvent(QWheelEvent* event) {
    if (m_projection == Projection::head_coupled) return;
    m_orbit.zoom(float(event->angleDelta().y()) / 120.0f);
    update();
    emit camera_changed();
}

} // namespace kumite::view
