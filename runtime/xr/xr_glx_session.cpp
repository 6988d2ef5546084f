#include "xr_glx_session.h"

#include <GL/glx.h>
#include <X11/Xlib.h>
#define XR_USE_PLATFORM_XLIB
#define XR_USE_GRAPHICS_API_OPENGL
#include <openxr/openxr_platform.h>

namespace kumite::view {

bool xr_glx_create_session(XrInstance instance, XrSystemId system, XrSession& session, std::string& error) {
    XrGraphicsBindingOpenGLXlibKHR binding{XR_TYPE_GRAPHICS_BINDING_OPENGL_XLIB_KHR};
    binding.xDisplay = glXGetCurrentDisplay();
    binding.glxContext = glXGetCurrentContext();
    binding.glxDrawable = glXGetCurrentDrawable();
    if (!binding.xDisplay || !binding.glxContext) {
        error = "no current GLX context: kumite play --xr renders with OpenGL through GLX, so it needs an X display "
                "(DISPLAY; without a screen, run it under xvfb-run -a)";
        return false;
    }
    int fbconfig_id = 0, screen = 0;
    glXQueryContext(binding.xDisplay, binding.glxContext, GLX_FBCONFIG_ID, &fbconfig_id);
    glXQueryContext(binding.xDisplay, binding.glxContext, GLX_SCREEN, &screen);
    const int attributes[] = {GLX_FBCONFIG_ID, fbconfig_id, None};
    int configs = 0;
    GLXFBConfig* config = glXChooseFBConfig(binding.xDisplay, screen, attributes, &configs);
    if (config && configs > 0) {
        binding.glxFBConfig = config[0];
        if (XVisualInfo* visual = glXGetVisualFromFBConfig(binding.xDisplay, config[0])) {
            binding.visualid = std::uint32_t(visual->visualid);
            XFree(visual);
        }
    }
    if (config) XFree(config);

    PFN_xrGetOpenGLGraphicsRequirementsKHR requirements_of = nullptr;
    if (XR_FAILED(xrGetInstanceProcAddr(instance, "xrGetOpenGLGraphicsRequirementsKHR", reinterpret_cast<PFN_xrVoidFunction*>(&requirements_of)))) {
        error = "the OpenXR runtime has no xrGetOpenGLGraphicsRequirementsKHR";
        return false;
    }
    XrGraphicsRequirementsOpenGLKHR requirements{XR_TYPE_GRAPHICS_REQUIREMENTS_OPENGL_KHR};
    if (XR_FAILED(requirements_of(instance, system, &requirements))) {
        error = "xrGetOpenGLGraphicsRequirementsKHR failed";
        return false;
    }
    int major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    const XrVersion have = XR_MAKE_VERSION(major, minor, 0);
    if (have < requirements.minApiVersionSupported) {
        error = "the OpenGL context is " + std::to_string(major) + "." + std::to_string(minor) + ", the OpenXR runtime needs at least " +
                std::to_string(XR_VERSION_MAJOR(requirements.minApiVersionSupported)) + "." + std::to_string(XR_VERSION_MINOR(requirements.minApiVersionSupported));
        return false;
    }
    XrSessionCreateInfo info{XR_TYPE_SESSION_CREATE_INFO};
    info.next = &binding;
    info.systemId = system;
    if (const XrResult created = xrCreateSession(instance, &info, &session); XR_FAILED(created)) {
        char name[XR_MAX_RESULT_STRING_SIZE] = {};
        xrResultToString(instance, created, name);
        error = std::string("xrCreateSession on the OpenGL (GLX) context failed: ") + name;
        session = XR_NULL_HANDLE;
        return false;
    }
    return true;
}

} // namespace kumite::view
