#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "render/pixel_canvas.h"

namespace sedem::render {
namespace {

std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&') {
      out += "&amp;";
    } else if (c == '<') {
      out += "&lt;";
    } else if (c == '>') {
      out += "&gt;";
    } else {
      out += c;
    }
  }
  return out;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

}  // namespace

// The same drawing as draw(), element for element: fills, discs, lines, then text, so the
// SVG stacks them as the picture does. SVG's y runs down, the canvas' up.
void PixelCanvas::write_svg(const std::filesystem::path& file, int width, int height) const {
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  std::ofstream out(file);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << " " << height << "\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for (const Layer* layer : {&fills_, &discs_}) {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    cells->DeepCopy(layer->cells);
    cells->InitTraversal();
    for (vtkIdType c = 0; cells->GetNextCell(n, ids); ++c) {
      unsigned char rgb[3];
      layer->colors->GetTypedTuple(c, rgb);
      out << "<polygon fill=\"rgb(" << int(rgb[0]) << "," << int(rgb[1]) << "," << int(rgb[2])
          << ")\" points=\"";
      for (vtkIdType k = 0; k < n; ++k) {
        double p[3];
        layer->points->GetPoint(ids[k], p);
        out << (k ? " " : "") << number(p[0]) << "," << number(height - p[1]);
      }
      out << "\"/>\n";
    }
  }
  out << "<g stroke=\"black\" stroke-width=\"1\" fill=\"none\">\n";
  for (vtkIdType k = 0; k + 1 < line_points_->GetNumberOfPoints(); k += 2) {
    double a[3], b[3];
    line_points_->GetPoint(k, a);
    line_points_->GetPoint(k + 1, b);
    out << "<line x1=\"" << number(a[0]) << "\" y1=\"" << number(height - a[1]) << "\" x2=\""
        << number(b[0]) << "\" y2=\"" << number(height - b[1]) << "\"/>\n";
  }
  out << "</g>\n";
  for (const auto& t : texts_) {
    out << "<text x=\"" << number(t.x) << "\" y=\"" << number(height - t.y)
        << "\" font-family=\"Arial, Helvetica, sans-serif\" font-size=\"" << t.size << "\""
        << (t.bold ? " font-weight=\"bold\"" : "") << (t.centred ? " text-anchor=\"middle\"" : "")
        << " dominant-baseline=\"central\">" << escaped(t.s) << "</text>\n";
  }
  out << "</svg>\n";
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

}  // namespace sedem::render
