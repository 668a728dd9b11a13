#include "render/gl_backend.h"

#include <cstdlib>
#include <stdexcept>
#include <string_view>

namespace sedem::render {

GlBackend choose_backend() {
  if (const char* forced = std::getenv("SEDEM_GL"); forced && *forced) {
    std::string_view f(forced);
    if (f == "egl") return GlBackend::egl;
    if (f == "x") return GlBackend::x;
    throw std::runtime_error("SEDEM_GL=" + std::string(f) + " is not one of: egl, x");
  }
  const char* display = std::getenv("DISPLAY");
  return display && *display ? GlBackend::x : GlBackend::egl;
}

std::string to_string(GlBackend backend) {
  return backend == GlBackend::egl ? "egl" : "x";
}

}  // namespace sedem::render
