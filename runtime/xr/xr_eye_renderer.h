#pragma once
// Both eyes drawn into the runtime's swapchains: an OpenGL 3.3 core context of its own (Qt; GLX under X11), one
// swapchain per eye at the size the runtime recommends (sRGB when offered), a depth buffer per eye, and the
// desktop viewer's scene renderer (scene_gl_renderer.h) drawing the Scene from each eye's pose with its own
// asymmetric field of view. Lives on the thread that created it; release() before the session is destroyed.

#include "scene.h"
#include "scene_gl_renderer.h"
#include "xr_headset.h"

#include <QImage>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>

#include <array>
#include <memory>
#include <vector>

namespace kumite::view {

class XrEyeRenderer : protected QOpenGLExtraFunctions {
public:
    XrEyeRenderer();
    ~XrEyeRenderer();
    // The context, made current (a QGuiApplication must exist). Errors say why there is no OpenGL.
    Result<void> create_context();
    // The swapchains (width x height per eye) and the scene renderer, once the session exists. A render size larger
    // than the swapchains (a headset's size, benchmarked on a runtime whose images are smaller) draws into a
    // target of that size per eye, scaled down into the swapchain image.
    Result<void> create_swapchains(XrHeadset& headset, std::array<int, 2> swapchain_size, std::array<int, 2> render_size);
    // Draws `scene` for both eyes into the swapchain images and describes them in `layer_views` (poses, fovs,
    // image rectangles). `capture_eye` >= 0: that eye's image is read back into `captured` (top row first).
    bool render(XrHeadset& headset, const Scene& scene, const XrEyeViews& views, std::array<XrCompositionLayerProjectionView, 2>& layer_views,
                int capture_eye = -1, QImage* captured = nullptr);
    void release();
    void make_current() { m_context.makeCurrent(&m_surface); } // after another context was (the supervisor's window)
    std::array<int, 2> size() const { return {m_width, m_height}; }                       // drawn, per eye
    std::array<int, 2> swapchain_size() const { return {m_swapchain_width, m_swapchain_height}; }
    long long format() const { return m_format; }

private:
    struct Eye;
    QOffscreenSurface m_surface;
    QOpenGLContext m_context;
    SceneGlRenderer m_renderer;
    std::vector<std::unique_ptr<Eye>> m_eyes;
    int m_width = 0, m_height = 0, m_swapchain_width = 0, m_swapchain_height = 0;
    long long m_format = 0;
    bool m_renderer_ready = false;
};

} // namespace kumite::view
