#include "render/drawing/figure_files.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <cairo-pdf.h>
#include <cairo.h>

#include "render/atomic_write.h"
#include "render/drawing/cairo_painter.h"
#include "render/drawing/svg_document.h"

namespace sedem::render {
namespace {

void check(cairo_status_t status, const std::filesystem::path& file) {
  if (status != CAIRO_STATUS_SUCCESS)
    throw WriteError("cannot write " + file.string() + ": " + cairo_status_to_string(status));
}

// Device pixels per logical pixel for a PNG of `output.width_px` pixels.
double png_scale(const Drawing& d, const FigureOutput& output) {
  return output.width_px > 0 && d.width > 0 ? double(output.width_px) / d.width : 1.0;
}

// Points per logical pixel: the figure's physical width (width_px / dpi inches) in points.
double point_scale(const Drawing& d, const FigureOutput& output) {
  const double inches = double(output.width_px) / output.dpi;
  return d.width > 0 ? 72.0 * inches / d.width : 1.0;
}

cairo_surface_t* raster_surface(const Drawing& d, double scale) {
  const int w = std::max(1, int(std::lround(d.width * scale)));
  const int h = std::max(1, int(std::lround(d.height * scale)));
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h);
  cairo_t* cr = cairo_create(surface);
  cairo_scale(cr, double(w) / d.width, double(h) / d.height);
  paint(d, cr);
  cairo_destroy(cr);
  cairo_surface_flush(surface);
  return surface;
}

// cairo's output callback onto a stream.
cairo_status_t to_stream(void* closure, const unsigned char* data, unsigned int length) {
  auto& out = *static_cast<std::ostream*>(closure);
  out.write(reinterpret_cast<const char*>(data), std::streamsize(length));
  return out ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

void write_png(const Drawing& d, std::ostream& out, const std::filesystem::path& file,
               double scale) {
  cairo_surface_t* surface = raster_surface(d, scale);
  const auto status = cairo_surface_write_to_png_stream(surface, to_stream, &out);
  cairo_surface_destroy(surface);
  check(status, file);
}

void write_pdf(const Drawing& d, std::ostream& out, const std::filesystem::path& file,
               double scale) {
  cairo_surface_t* surface =
      cairo_pdf_surface_create_for_stream(to_stream, &out, d.width * scale, d.height * scale);
  if (!d.title.empty())
    cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_TITLE, d.title.c_str());
  cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR, "sedem");
  cairo_t* cr = cairo_create(surface);
  cairo_scale(cr, scale, scale);
  paint(d, cr);
  cairo_show_page(cr);
  cairo_destroy(cr);
  cairo_surface_finish(surface);
  const auto status = cairo_surface_status(surface);
  cairo_surface_destroy(surface);
  check(status, file);
}

void write_svg(const Drawing& d, std::ostream& out, double scale) {
  std::ostringstream w, h;
  w << std::lround(d.width * scale) << "pt";
  h << std::lround(d.height * scale) << "pt";
  out << svg_document(d, w.str(), h.str());
}

}  // namespace

std::vector<FigureFormat> parse_figure_formats(const std::string& names) {
  std::vector<FigureFormat> formats;
  std::istringstream in(names);
  std::string name;
  while (std::getline(in, name, ',')) {
    const auto b = name.find_first_not_of(" \t"), e = name.find_last_not_of(" \t");
    name = b == std::string::npos ? "" : name.substr(b, e - b + 1);
    FigureFormat f;
    if (name == "png")
      f = FigureFormat::png;
    else if (name == "svg")
      f = FigureFormat::svg;
    else if (name == "pdf")
      f = FigureFormat::pdf;
    else
      throw std::invalid_argument("unknown figure format '" + name + "' (png, svg, pdf)");
    if (std::find(formats.begin(), formats.end(), f) == formats.end()) formats.push_back(f);
  }
  if (formats.empty()) throw std::invalid_argument("no figure format given (png, svg, pdf)");
  return formats;
}

const char* extension(FigureFormat format) {
  switch (format) {
    case FigureFormat::png:
      return "png";
    case FigureFormat::svg:
      return "svg";
    case FigureFormat::pdf:
      return "pdf";
  }
  return "";
}

std::vector<std::filesystem::path> write_drawing(const Drawing& drawing,
                                                 const std::filesystem::path& base,
                                                 const FigureOutput& output) {
  if (!(drawing.width > 0 && drawing.height > 0))
    throw std::invalid_argument("an empty drawing cannot be written: " + base.string());
  if (base.has_parent_path()) std::filesystem::create_directories(base.parent_path());
  std::vector<std::filesystem::path> written;
  for (auto format : output.formats) {
    auto file = base;
    file += std::string(".") + extension(format);
    // Through a temporary file: a reader never sees half a figure, a full disk throws
    // WriteError and leaves nothing behind.
    write_atomically(file, [&](std::ostream& out) {
      if (format == FigureFormat::png) write_png(drawing, out, file, png_scale(drawing, output));
      if (format == FigureFormat::svg) write_svg(drawing, out, point_scale(drawing, output));
      if (format == FigureFormat::pdf) write_pdf(drawing, out, file, point_scale(drawing, output));
    });
    written.push_back(file);
  }
  return written;
}

vtkSmartPointer<vtkImageData> rasterize(const Drawing& drawing, double scale) {
  cairo_surface_t* surface = raster_surface(drawing, scale);
  const int w = cairo_image_surface_get_width(surface), h = cairo_image_surface_get_height(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(w, h, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  // cairo's rows run down, VTK's up; RGB24 keeps each pixel as a native-endian 0x00RRGGBB.
  for (int j = 0; j < h; ++j) {
    const auto* row = reinterpret_cast<const std::uint32_t*>(data + std::size_t(j) * stride);
    auto* out = static_cast<unsigned char*>(image->GetScalarPointer(0, h - 1 - j, 0));
    for (int i = 0; i < w; ++i) {
      out[3 * i] = (row[i] >> 16) & 0xff;
      out[3 * i + 1] = (row[i] >> 8) & 0xff;
      out[3 * i + 2] = row[i] & 0xff;
    }
  }
  cairo_surface_destroy(surface);
  return image;
}

}  // namespace sedem::render
