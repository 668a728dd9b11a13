// Debian 12's VTK calls GLEW's glewInit(), which loads every GL entry point through glvnd
// (they reach our EGL context) and then reports GLEW_ERROR_NO_GLX_DISPLAY because there is
// no X display; VTK treats that as fatal. This definition, linked into each executable that
// renders and exported so that it takes precedence over libGLEW's, calls the real one and
// forgives that one error. With an X display the real glewInit succeeds and nothing changes.
#include <GL/glew.h>
#include <dlfcn.h>

extern "C" GLenum GLEWAPIENTRY glewInit(void) {
  using Fn = GLenum (*)(void);
  static Fn real = reinterpret_cast<Fn>(dlsym(RTLD_NEXT, "glewInit"));
  if (!real) return GLEW_ERROR_NO_GL_VERSION;
  GLenum result = real();
  return result == GLEW_ERROR_NO_GLX_DISPLAY ? GLEW_OK : result;
}
