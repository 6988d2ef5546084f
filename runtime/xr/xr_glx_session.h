#pragma once
// The OpenXR session on the current OpenGL context through XR_KHR_opengl_enable with Xlib/GLX (the context Qt made
// current: xr_gl_context.h). Kept apart so that X11 and GLX headers stay in one source file.

#include <openxr/openxr.h>

#include <string>

namespace kumite::view {

// Checks the runtime's OpenGL requirements against the current context and creates the session. False with
// `error` set when there is no current GLX context, the version is too old or xrCreateSession fails.
bool xr_glx_create_session(XrInstance instance, XrSystemId system, XrSession& session, std::string& error);

} // namespace kumite::view
