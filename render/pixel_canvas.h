#pragma once

#include <array>
#include <filesystem>
#include <string>

#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>

namespace sedem::render {

// Flat 2D drawing in pixel coordinates (origin bottom-left) on a renderer: filled polygons
// with their own colours, black lines and text. Everything is batched into a few actors.
// Draw order: fills, then discs, then lines, then text.
class PixelCanvas {
 public:
  using Rgb = std::array<unsigned char, 3>;

  void rectangle(double x0, double y0, double x1, double y1, Rgb fill);
  void disc(double cx, double cy, double radius, Rgb fill);
  void line(double x0, double y0, double x1, double y1);
  void frame(double x0, double y0, double x1, double y1);  // a rectangle's outline
  void text(const std::string& s, double x, double y, int size, bool centred = true,
            bool bold = false);

  // Adds the actors to `renderer` and sets a camera that maps one unit to one pixel of a
  // `width` x `height` viewport.
  void draw(vtkRenderer* renderer, int width, int height);

  // The same drawing as an SVG file of `width` x `height` pixels: vector graphics for papers.
  void write_svg(const std::filesystem::path& file, int width, int height) const;

 private:
  struct Layer {
    vtkSmartPointer<vtkPoints> points = vtkSmartPointer<vtkPoints>::New();
    vtkSmartPointer<vtkCellArray> cells = vtkSmartPointer<vtkCellArray>::New();
    vtkSmartPointer<vtkUnsignedCharArray> colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
  };
  void polygon(Layer& layer, const double* xy, int n, Rgb fill, double z);
  struct Text {
    std::string s;
    double x, y;
    int size;
    bool centred, bold;
  };
  Layer fills_, discs_;
  vtkSmartPointer<vtkPoints> line_points_ = vtkSmartPointer<vtkPoints>::New();
  vtkSmartPointer<vtkCellArray> lines_ = vtkSmartPointer<vtkCellArray>::New();
  std::vector<Text> texts_;
};

}  // namespace sedem::render
