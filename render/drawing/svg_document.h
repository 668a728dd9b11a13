#pragma once

#include <string>

#include "render/drawing/drawing.h"

namespace sedem::render {

// A drawing as an SVG document, shape for shape: text stays text (searchable, editable) in a
// font named with generic fallbacks, positioned by its baseline and anchor as cairo places
// it; clips are rectangles in the drawing's own coordinates, with no transform under them,
// so every renderer draws the data. `width`/`height` give the size the document asks to be
// shown at (with its unit, e.g. "576pt"); the view box is the drawing's logical pixels.
std::string svg_document(const Drawing& drawing, const std::string& width,
                         const std::string& height);

}  // namespace sedem::render
