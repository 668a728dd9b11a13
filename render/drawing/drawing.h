#pragma once

#include <array>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace sedem::render {

// A picture as a list of shapes in logical pixels (origin top left, y down, as in SVG and
// cairo), so that one drawing is written as PNG, SVG and PDF with the same data in each:
// the formats differ only in how they are encoded, never in what is drawn.

struct Rgba {
  unsigned char r = 0, g = 0, b = 0, a = 255;
};
inline constexpr Rgba kBlack{0, 0, 0, 255};
inline constexpr Rgba kWhite{255, 255, 255, 255};

struct Point {
  double x = 0, y = 0;
};

struct Stroke {
  Rgba color = kBlack;
  double width = 1;
  std::vector<double> dashes;  // on, off, ... in logical pixels; empty: solid
};

// Open line through the points.
struct Polyline {
  std::vector<Point> points;
  Stroke stroke;
};

// Closed polygon, filled; with `outline` also stroked.
struct Polygon {
  std::vector<Point> points;
  Rgba fill;
  bool outline = false;
  Stroke stroke;
};

struct Circle {
  Point centre;
  double radius = 1;
  Rgba fill;
  bool outline = false;
  Stroke stroke;
};

enum class Anchor { start, middle, end };

// One line of text: `at` is the anchor point on the baseline, unless `centred_vertically`
// (then it is the middle of the text's x-height band). `angle` turns it counter-clockwise in
// degrees (90: read from bottom to top, as a y-axis title).
struct Text {
  std::string text;  // UTF-8
  Point at;
  double size = 12;  // logical pixels
  bool bold = false;
  Anchor anchor = Anchor::start;
  bool centred_vertically = false;
  double angle = 0;
  Rgba color = kBlack;
};

// Everything until the matching ClipEnd is cut to the rectangle.
struct ClipBegin {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};
struct ClipEnd {};

using Shape = std::variant<Polyline, Polygon, Circle, Text, ClipBegin, ClipEnd>;

struct Drawing {
  double width = 0, height = 0;  // logical pixels
  std::string title;             // the document's title (SVG <title>, PDF metadata)
  std::vector<Shape> shapes;     // painted in order on a white ground

  void add(Shape shape) { shapes.push_back(std::move(shape)); }
  // A shape of one kind, built in place (moving a whole variant trips GCC 12's
  // -Wmaybe-uninitialized on the kinds it does not hold).
  template <class S>
  requires(!std::is_same_v<std::decay_t<S>, Shape>) void add(S&& shape) {
    shapes.emplace_back(std::in_place_type<std::decay_t<S>>, std::forward<S>(shape));
  }
  void line(Point a, Point b, Stroke stroke = {}) { add(Polyline{{a, b}, std::move(stroke)}); }
  void rectangle(double x0, double y0, double x1, double y1, Rgba fill) {
    add(Polygon{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, fill, false, {}});
  }
  void frame(double x0, double y0, double x1, double y1, Stroke stroke = {}) {
    add(Polyline{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}, {x0, y0}}, std::move(stroke)});
  }
};

// The font every picture uses: a family Debian ships in fonts-dejavu-core, named in SVG with
// generic fallbacks so that a viewer without it still draws the text.
inline constexpr const char* kFontFamily = "DejaVu Sans";
inline constexpr const char* kSvgFontFamily = "'DejaVu Sans', Verdana, Arial, sans-serif";

}  // namespace sedem::render
