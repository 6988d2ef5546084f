#include "xr_eye_renderer.h"

#define XR_USE_GRAPHICS_API_OPENGL
#include <openxr/openxr_platform.h>

#include <QSurfaceFormat>

namespace kumite::view {

struct XrEyeRenderer::Eye {
    XrSwapchain swapchain = XR_NULL_HANDLE;
    std::vector<GLuint> images;
    GLuint framebuffer = 0, depth = 0;
    GLuint target = 0, target_color = 0; // the larger render target, when the render size exceeds the swapchain's
};

XrEyeRenderer::XrEyeRenderer() = default;
XrEyeRenderer::~XrEyeRenderer() { release(); }

Result<void> XrEyeRenderer::create_context() {
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    m_context.setFormat(format);
    if (!m_context.create()) return Error{ErrorCode::io, "no OpenGL 3.3 context could be created (on X11 with GLX; without a screen run under xvfb-run -a)"};
    m_surface.setFormat(m_context.format());
    m_surface.create();
    if (!m_context.makeCurrent(&m_surface)) return Error{ErrorCode::io, "the OpenGL context could not be made current"};
    initializeOpenGLFunctions();
    return {};
}

Result<void> XrEyeRenderer::create_swapchains(XrHeadset& headset, std::array<int, 2> swapchain_size, std::array<int, 2> render_size) {
    const int width = swapchain_size[0], height = swapchain_size[1];
    m_swapchain_width = width, m_swapchain_height = height;
    m_width = render_size[0], m_height = render_size[1];
    const bool scaled = render_size != swapchain_size;
    std::uint32_t count = 0;
    headset.check(xrEnumerateSwapchainFormats(headset.session(), 0, &count, nullptr), "xrEnumerateSwapchainFormats");
    std::vector<std::int64_t> formats(count);
    headset.check(xrEnumerateSwapchainFormats(headset.session(), count, &count, formats.data()), "xrEnumerateSwapchainFormats");
    // sRGB first: the scene's colours are written as the desktop viewer writes them to its screen.
    for (const std::int64_t wanted : {std::int64_t(GL_SRGB8_ALPHA8), std::int64_t(GL_RGBA8)}) {
        for (const std::int64_t offered : formats) {
            if (offered == wanted && m_format == 0) m_format = wanted;
        }
    }
    if (m_format == 0) return Error{ErrorCode::unsupported, "the OpenXR runtime offers neither GL_SRGB8_ALPHA8 nor GL_RGBA8 swapchains"};
    for (int e = 0; e < 2; ++e) {
        auto eye = std::make_unique<Eye>();
        XrSwapchainCreateInfo info{XR_TYPE_SWAPCHAIN_CREATE_INFO};
        info.usageFlags = XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT | XR_SWAPCHAIN_USAGE_SAMPLED_BIT;
        info.format = m_format;
        info.sampleCount = 1, info.width = std::uint32_t(width), info.height = std::uint32_t(height);
        info.faceCount = 1, info.arraySize = 1, info.mipCount = 1;
        if (!headset.check(xrCreateSwapchain(headset.session(), &info, &eye->swapchain), "xrCreateSwapchain")) {
            return Error{ErrorCode::io, headset.error_messages().back()};
        }
        std::uint32_t images = 0;
        headset.check(xrEnumerateSwapchainImages(eye->swapchain, 0, &images, nullptr), "xrEnumerateSwapchainImages");
        std::vector<XrSwapchainImageOpenGLKHR> gl_images(images, {XR_TYPE_SWAPCHAIN_IMAGE_OPENGL_KHR, nullptr, 0});
        headset.check(xrEnumerateSwapchainImages(eye->swapchain, images, &images, reinterpret_cast<XrSwapchainImageBaseHeader*>(gl_images.data())),
                      "xrEnumerateSwapchainImages");
        for (const XrSwapchainImageOpenGLKHR& image : gl_images) eye->images.push_back(image.image);
        glGenFramebuffers(1, &eye->framebuffer);
        glGenRenderbuffers(1, &eye->depth);
        glBindRenderbuffer(GL_RENDERBUFFER, eye->depth);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, m_width, m_height);
        if (scaled) {
            glGenRenderbuffers(1, &eye->target_color);
            glBindRenderbuffer(GL_RENDERBUFFER, eye->target_color);
            glRenderbufferStorage(GL_RENDERBUFFER, GLenum(m_format), m_width, m_height);
            glGenFramebuffers(1, &eye->target);
            glBindFramebuffer(GL_FRAMEBUFFER, eye->target);
            glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, eye->target_color);
            glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, eye->depth);
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
        }
        m_eyes.push_back(std::move(eye));
    }
    QString error;
    if (!m_renderer.initialize(error)) return Error{ErrorCode::io, "the scene renderer: " + error.toStdString()};
    m_renderer_ready = true;
    return {};
}

bool XrEyeRenderer::render(XrHeadset& headset, const Scene& scene, const XrEyeViews& views, std::array<XrCompositionLayerProjectionView, 2>& layer_views,
                           int capture_eye, QImage* captured) {
    for (int e = 0; e < 2; ++e) {
        Eye& eye = *m_eyes[std::size_t(e)];
        std::uint32_t index = 0;
        XrSwapchainImageAcquireInfo acquire{XR_TYPE_SWAPCHAIN_IMAGE_ACQUIRE_INFO};
        if (!headset.check(xrAcquireSwapchainImage(eye.swapchain, &acquire, &index), "xrAcquireSwapchainImage")) return false;
        XrSwapchainImageWaitInfo wait{XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO};
        wait.timeout = XR_INFINITE_DURATION;
        if (!headset.check(xrWaitSwapchainImage(eye.swapchain, &wait), "xrWaitSwapchainImage")) return false;
        glBindFramebuffer(GL_FRAMEBUFFER, eye.framebuffer);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, eye.images[index], 0);
        if (eye.target == 0) glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, eye.depth);
        else glBindFramebuffer(GL_FRAMEBUFFER, eye.target);
        const ViewProjection view_projection = xr_eye_view_projection(views.pose[std::size_t(e)], views.fov[std::size_t(e)], 0.05f, 100.0f);
        m_renderer.render(scene, view_projection, QRect(0, 0, m_width, m_height));
        if (e == capture_eye && captured) {
            QImage image(m_width, m_height, QImage::Format_RGBA8888);
            glPixelStorei(GL_PACK_ALIGNMENT, 1);
            glReadPixels(0, 0, m_width, m_height, GL_RGBA, GL_UNSIGNED_BYTE, image.bits());
            *captured = image.mirrored(false, true).convertToFormat(QImage::Format_RGB888);
        }
        if (eye.target != 0) {
            glBindFramebuffer(GL_READ_FRAMEBUFFER, eye.target);
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, eye.framebuffer);
            glBlitFramebuffer(0, 0, m_width, m_height, 0, 0, m_swapchain_width, m_swapchain_height, GL_COLOR_BUFFER_BIT, GL_LINEAR);
        }
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        XrSwapchainImageReleaseInfo release_info{XR_TYPE_SWAPCHAIN_IMAGE_RELEASE_INFO};
        if (!headset.check(xrReleaseSwapchainImage(eye.swapchain, &release_info), "xrReleaseSwapchainImage")) return false;

        XrCompositionLayerProjectionView& view = layer_views[std::size_t(e)];
        view = {XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW};
        const XrPoseWorld& pose = views.pose[std::size_t(e)];
        view.pose.orientation = {pose.orientation.x(), pose.orientation.y(), pose.orientation.z(), pose.orientation.w()};
        view.pose.position = {pose.position.x(), pose.position.y(), pose.position.z()};
        const XrFovRad& fov = views.fov[std::size_t(e)];
        view.fov = {fov.left, fov.right, fov.up, fov.down};
        view.subImage.swapchain = eye.swapchain;
        view.subImage.imageRect = {{0, 0}, {m_swapchain_width, m_swapchain_height}};
        view.subImage.imageArrayIndex = 0;
    }
    return true;
}

void XrEyeRenderer::release() {
    if (!m_context.isValid()) return;
    m_context.makeCurrent(&m_surface);
    if (m_renderer_ready) m_renderer.release();
    m_renderer_ready = false;
    for (const std::unique_ptr<Eye>& eye : m_eyes) {
        glDeleteFramebuffers(1, &eye->framebuffer);
        glDeleteRenderbuffers(1, &eye->depth);
        if (eye->target != 0) glDeleteFramebuffers(1, &eye->target), glDeleteRenderbuffers(1, &eye->target_color);
        if (eye->swapchain != XR_NULL_HANDLE) xrDestroySwapchain(eye->swapchain);
    }
    m_eyes.clear();
}

} // namespace kumite::view
