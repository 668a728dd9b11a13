#include "render/pixel_canvas.h"

#include <algorithm>

// GCC 12 at -O3 takes the members of a shape moved into Drawing's variant for uninitialised
// (-Wmaybe-uninitialized, a false positive of its inliner); other compilers do not warn.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

namespace sedem::render {

PixelCanvas::PixelCanvas(double width, double height, std::string title) {
  drawing_.width = width;
  drawing_.height = height;
  drawing_.title = std::move(title);
}

void PixelCanvas::rectangle(double x0, double y0, double x1, double y1, Rgb fill) {
  drawing_.add(Polygon{{at(x0, y0), at(x1, y0), at(x1, y1), at(x0, y1)},
                       {fill[0], fill[1], fill[2], 255},
                       false,
                       {}});
}

void PixelCanvas::disc(double cx, double cy, double radius, Rgb fill) {
  drawing_.add(Circle{at(cx, cy), radius, {fill[0], fill[1], fill[2], 255}, false, {}});
}

void PixelCanvas::line(double x0, double y0, double x1, double y1) {
  drawing_.line(at(x0, y0), at(x1, y1));
}

void PixelCanvas::frame(double x0, double y0, double x1, double y1) {
  const auto a = at(x0, y0), b = at(x1, y1);
  drawing_.frame(a.x, std::min(a.y, b.y), b.x, std::max(a.y, b.y));
}

void PixelCanvas::text(const std::string& s, double x, double y, int size, bool centred,
                       bool bold) {
  Text t{s, at(x, y), double(size), bold, centred ? Anchor::middle : Anchor::start};
  t.centred_vertically = true;
  drawing_.add(t);
}

}  // namespace sedem::render
