#include "render/drawing/cairo_painter.h"

#include <cmath>
#include <numbers>

namespace sedem::render {
namespace {

// The baseline sits this far below a vertically centred text's anchor: half the height of
// the font's capitals (DejaVu Sans: 0.73 em), so that digits and capitals centre on it.
constexpr double kCentringDrop = 0.365;

void set_colour(cairo_t* cr, Rgba c) {
  cairo_set_source_rgba(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0, c.a / 255.0);
}

void set_stroke(cairo_t* cr, const Stroke& s) {
  set_colour(cr, s.color);
  cairo_set_line_width(cr, s.width);
  cairo_set_dash(cr, s.dashes.data(), int(s.dashes.size()), 0);
}

void path_through(cairo_t* cr, const std::vector<Point>& points) {
  cairo_new_path(cr);
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i == 0)
      cairo_move_to(cr, points[i].x, points[i].y);
    else
      cairo_line_to(cr, points[i].x, points[i].y);
  }
}

void select_font(cairo_t* cr, double size, bool bold) {
  cairo_select_font_face(cr, kFontFamily, CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
}

struct Painter {
  cairo_t* cr;

  void operator()(const Polyline& l) {
    if (l.points.size() < 2) return;
    path_through(cr, l.points);
    set_stroke(cr, l.stroke);
    cairo_stroke(cr);
  }
  void operator()(const Polygon& p) {
    if (p.points.size() < 3) return;
    path_through(cr, p.points);
    cairo_close_path(cr);
    set_colour(cr, p.fill);
    if (!p.outline) {
      cairo_fill(cr);
      return;
    }
    cairo_fill_preserve(cr);
    set_stroke(cr, p.stroke);
    cairo_stroke(cr);
  }
  void operator()(const Circle& c) {
    cairo_new_path(cr);
    cairo_arc(cr, c.centre.x, c.centre.y, c.radius, 0, 2 * std::numbers::pi);
    set_colour(cr, c.fill);
    if (!c.outline) {
      cairo_fill(cr);
      return;
    }
    cairo_fill_preserve(cr);
    set_stroke(cr, c.stroke);
    cairo_stroke(cr);
  }
  void operator()(const Text& t) {
    if (t.text.empty()) return;
    cairo_save(cr);
    select_font(cr, t.size, t.bold);
    cairo_text_extents_t e;
    cairo_text_extents(cr, t.text.c_str(), &e);
    cairo_translate(cr, t.at.x, t.at.y);
    if (t.angle != 0) cairo_rotate(cr, -t.angle * std::numbers::pi / 180);
    const double shift = t.anchor == Anchor::start    ? 0
                         : t.anchor == Anchor::middle ? -0.5 * e.x_advance
                                                      : -e.x_advance;
    cairo_move_to(cr, shift, t.centred_vertically ? kCentringDrop * t.size : 0);
    set_colour(cr, t.color);
    cairo_show_text(cr, t.text.c_str());
    cairo_restore(cr);
  }
  void operator()(const ClipBegin& c) {
    cairo_save(cr);
    cairo_new_path(cr);
    cairo_rectangle(cr, c.x0, c.y0, c.x1 - c.x0, c.y1 - c.y0);
    cairo_clip(cr);
  }
  void operator()(const ClipEnd&) { cairo_restore(cr); }
};

}  // namespace

void paint(const Drawing& drawing, cairo_t* cr) {
  cairo_save(cr);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_rectangle(cr, 0, 0, drawing.width, drawing.height);
  cairo_fill(cr);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
  Painter painter{cr};
  for (const auto& shape : drawing.shapes) std::visit(painter, shape);
  cairo_restore(cr);
}

double text_advance(const std::string& text, double size, bool bold) {
  // One small surface per thread: figures are drawn on the observers' thread and in tests.
  thread_local cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_A8, 1, 1);
  thread_local cairo_t* cr = cairo_create(surface);
  select_font(cr, size, bold);
  cairo_text_extents_t e;
  cairo_text_extents(cr, text.c_str(), &e);
  return e.x_advance;
}

}  // namespace sedem::render
