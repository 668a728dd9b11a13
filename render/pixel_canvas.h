#pragma once

#include <array>
#include <string>

#include "render/drawing/drawing.h"

namespace sedem::render {

// Flat 2D drawing in pixel coordinates with the origin at the bottom left (as the column's
// height runs up), recorded into a Drawing that is written as PNG, SVG or PDF.
class PixelCanvas {
 public:
  using Rgb = std::array<unsigned char, 3>;

  PixelCanvas(double width, double height, std::string title = {});

  void rectangle(double x0, double y0, double x1, double y1, Rgb fill);
  void disc(double cx, double cy, double radius, Rgb fill);
  void line(double x0, double y0, double x1, double y1);
  void frame(double x0, double y0, double x1, double y1);  // a rectangle's outline
  // `y` is the text's vertical middle; `centred` centres it on `x`, else it starts there.
  void text(const std::string& s, double x, double y, int size, bool centred = true,
            bool bold = false);

  const Drawing& drawing() const { return drawing_; }

 private:
  Point at(double x, double y) const { return {x, drawing_.height - y}; }
  Drawing drawing_;
};

}  // namespace sedem::render
