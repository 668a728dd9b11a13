#pragma once

#include <string>

namespace sedem::render {

// How frames are drawn: through an EGL surfaceless Mesa context (no display needed) or
// through VTK's own X window (when a display exists). SEDEM_GL=egl|x forces one;
// otherwise X when DISPLAY is set, EGL when it is not.
enum class GlBackend { egl, x };

GlBackend choose_backend();
std::string to_string(GlBackend backend);

}  // namespace sedem::render
