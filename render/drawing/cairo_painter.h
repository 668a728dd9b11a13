#pragma once

#include <string>

#include <cairo.h>

#include "render/drawing/drawing.h"

namespace sedem::render {

// Paints a drawing with cairo onto any surface (image, PDF), in the drawing's logical
// pixels: the caller scales the context to the surface's resolution first.
void paint(const Drawing& drawing, cairo_t* cr);

// The advance width of `text` in logical pixels at `size`, in the pictures' font: what
// layouts measure before they place text.
double text_advance(const std::string& text, double size, bool bold = false);

}  // namespace sedem::render
