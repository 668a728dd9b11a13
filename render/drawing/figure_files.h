#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <vtkImageData.h>
#include <vtkSmartPointer.h>

#include "render/drawing/drawing.h"

namespace sedem::render {

enum class FigureFormat { png, svg, pdf };

// How figures are written: which formats, and the size. A figure has one physical size,
// `width_px / dpi` inches wide (8 in by default, a page's width less its margins); the PNG
// has `width_px` pixels across it, the PDF and SVG that size in points, so the three are
// one picture at any zoom.
struct FigureOutput {
  std::vector<FigureFormat> formats = {FigureFormat::png};
  int width_px = 1600;  // wide enough for a slide
  double dpi = 200;
  // Non-empty: the figure is of a run that did not complete. Its title then ends in
  // " (partial)" and its CSV starts with this as a comment ("# partial: ...").
  std::string partial_note;
};

// "png,svg" (output.figure_formats) as formats, in that order; throws std::invalid_argument
// naming the unknown one.
std::vector<FigureFormat> parse_figure_formats(const std::string& names);
const char* extension(FigureFormat format);  // "png", "svg", "pdf"

// Writes `<base>.<ext>` for each format; returns the files written.
std::vector<std::filesystem::path> write_drawing(const Drawing& drawing,
                                                 const std::filesystem::path& base,
                                                 const FigureOutput& output);

// The drawing rasterised `scale` device pixels per logical pixel, as RGB.
vtkSmartPointer<vtkImageData> rasterize(const Drawing& drawing, double scale = 1);

}  // namespace sedem::render
