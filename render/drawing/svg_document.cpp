#include "render/drawing/svg_document.h"

#include <cstdio>
#include <sstream>

namespace sedem::render {
namespace {

// Must match cairo_painter.cpp's drop, so that SVG and PNG put text at the same place.
constexpr double kCentringDrop = 0.365;

std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&')
      out += "&amp;";
    else if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  std::string s = buf;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

std::string colour(Rgba c) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c.r, c.g, c.b);
  return buf;
}

std::string opacity(const char* what, Rgba c) {
  return c.a == 255 ? std::string() : std::string(" ") + what + "=\"" + num(c.a / 255.0) + "\"";
}

std::string stroke_attributes(const Stroke& s) {
  std::string out = " stroke=\"" + colour(s.color) + "\" stroke-width=\"" + num(s.width) + "\"" +
                    opacity("stroke-opacity", s.color);
  if (!s.dashes.empty()) {
    out += " stroke-dasharray=\"";
    for (std::size_t i = 0; i < s.dashes.size(); ++i) {
      if (i) out += ' ';
      out += num(s.dashes[i]);
    }
    out += "\"";
  }
  return out;
}

std::string points_of(const std::vector<Point>& points) {
  std::string out;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i) out += ' ';
    out += num(points[i].x);
    out += ',';
    out += num(points[i].y);
  }
  return out;
}

struct Writer {
  std::ostringstream& out;
  int clips = 0;

  void operator()(const Polyline& l) {
    if (l.points.size() < 2) return;
    out << "<polyline fill=\"none\" stroke-linejoin=\"round\"" << stroke_attributes(l.stroke)
        << " points=\"" << points_of(l.points) << "\"/>\n";
  }
  void operator()(const Polygon& p) {
    if (p.points.size() < 3) return;
    out << "<polygon fill=\"" << colour(p.fill) << "\"" << opacity("fill-opacity", p.fill)
        << (p.outline ? stroke_attributes(p.stroke) : std::string(" stroke=\"none\""))
        << " points=\"" << points_of(p.points) << "\"/>\n";
  }
  void operator()(const Circle& c) {
    out << "<circle cx=\"" << num(c.centre.x) << "\" cy=\"" << num(c.centre.y) << "\" r=\""
        << num(c.radius) << "\" fill=\"" << colour(c.fill) << "\""
        << opacity("fill-opacity", c.fill)
        << (c.outline ? stroke_attributes(c.stroke) : std::string()) << "/>\n";
  }
  void operator()(const Text& t) {
    if (t.text.empty()) return;
    const char* anchor = t.anchor == Anchor::start    ? "start"
                         : t.anchor == Anchor::middle ? "middle"
                                                      : "end";
    // The baseline drop is applied before the turn, along the text's own vertical.
    const double drop = t.centred_vertically ? kCentringDrop * t.size : 0;
    out << "<text x=\"" << num(t.at.x) << "\" y=\"" << num(t.at.y) << "\"";
    if (t.angle != 0)
      out << " transform=\"rotate(" << num(-t.angle) << " " << num(t.at.x) << " " << num(t.at.y)
          << ")\"";
    if (drop != 0) out << " dy=\"" << num(drop) << "\"";
    out << " font-size=\"" << num(t.size) << "\"" << (t.bold ? " font-weight=\"bold\"" : "")
        << " text-anchor=\"" << anchor << "\" fill=\"" << colour(t.color) << "\""
        << opacity("fill-opacity", t.color) << ">" << escaped(t.text) << "</text>\n";
  }
  void operator()(const ClipBegin& c) {
    const int id = ++clips;
    out << "<clipPath id=\"clip" << id << "\"><rect x=\"" << num(c.x0) << "\" y=\"" << num(c.y0)
        << "\" width=\"" << num(c.x1 - c.x0) << "\" height=\"" << num(c.y1 - c.y0)
        << "\"/></clipPath>\n<g clip-path=\"url(#clip" << id << ")\">\n";
  }
  void operator()(const ClipEnd&) { out << "</g>\n"; }
};

}  // namespace

std::string svg_document(const Drawing& drawing, const std::string& width,
                         const std::string& height) {
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" << width
      << "\" height=\"" << height << "\" viewBox=\"0 0 " << num(drawing.width) << " "
      << num(drawing.height) << "\" font-family=\"" << kSvgFontFamily << "\">\n";
  if (!drawing.title.empty()) out << "<title>" << escaped(drawing.title) << "</title>\n";
  out << "<rect width=\"" << num(drawing.width) << "\" height=\"" << num(drawing.height)
      << "\" fill=\"white\"/>\n";
  Writer writer{out};
  for (const auto& shape : drawing.shapes) std::visit(writer, shape);
  out << "</svg>\n";
  return out.str();
}

}  // namespace sedem::render
