#include "render/egl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <stdexcept>
#include <string>

namespace sedem::render {
namespace {

[[noreturn]] void fail(const char* call) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", unsigned(eglGetError()));
  throw std::runtime_error(std::string("EGL: ") + call + " failed (error " + code +
                           "); is libegl-mesa0 installed?");
}

}  // namespace

EglContext::EglContext() {
  auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!get_platform_display) fail("eglGetProcAddress(eglGetPlatformDisplayEXT)");
  EGLDisplay dpy =
      get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (dpy == EGL_NO_DISPLAY) fail("eglGetPlatformDisplayEXT(SURFACELESS_MESA)");
  EGLint major = 0, minor = 0;
  if (!eglInitialize(dpy, &major, &minor)) fail("eglInitialize");
  display_ = dpy;
  if (!eglBindAPI(EGL_OPENGL_API)) fail("eglBindAPI(EGL_OPENGL_API)");

  // The surfaceless platform needs no framebuffer configuration: VTK renders into its own
  // framebuffer objects, so the context is created without one (EGL_KHR_no_config_context).
  EGLConfig config = EGL_NO_CONFIG_KHR;
  const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                    3,
                                    EGL_CONTEXT_MINOR_VERSION,
                                    2,
                                    EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                    EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                    EGL_NONE};
  EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, context_attribs);
  if (ctx == EGL_NO_CONTEXT) fail("eglCreateContext(OpenGL 3.2 core)");
  context_ = ctx;
  make_current();
}

void EglContext::make_current() {
  if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) fail("eglMakeCurrent");
}

EglContext::~EglContext() {
  if (context_) {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
  }
  if (display_) eglTerminate(display_);
}

}  // namespace sedem::render
