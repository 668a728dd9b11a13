#include "render/pixel_canvas.h"

#include <cmath>
#include <numbers>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

namespace sedem::render {
namespace {

// Depths that keep the batches in drawing order under the depth test.
constexpr double kFillZ = 0.0, kDiscZ = 0.1, kLineZ = 0.2;

vtkSmartPointer<vtkActor> actor_of(vtkPoints* points, vtkCellArray* cells, bool polygons,
                                   vtkUnsignedCharArray* colors) {
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  if (polygons) {
    poly->SetPolys(cells);
  } else {
    poly->SetLines(cells);
  }
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(poly);
  if (colors) {
    poly->GetCellData()->SetScalars(colors);
    mapper->SetScalarModeToUseCellData();
    mapper->SetColorModeToDirectScalars();
    mapper->ScalarVisibilityOn();
  } else {
    mapper->ScalarVisibilityOff();
  }
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0, 0, 0);
  actor->GetProperty()->SetLighting(false);
  actor->GetProperty()->SetLineWidth(1.0);
  return actor;
}

}  // namespace

void PixelCanvas::polygon(Layer& layer, const double* xy, int n, Rgb fill, double z) {
  if (layer.colors->GetNumberOfComponents() != 3) layer.colors->SetNumberOfComponents(3);
  layer.cells->InsertNextCell(n);
  for (int i = 0; i < n; ++i)
    layer.cells->InsertCellPoint(layer.points->InsertNextPoint(xy[2 * i], xy[2 * i + 1], z));
  layer.colors->InsertNextTypedTuple(fill.data());
}

void PixelCanvas::rectangle(double x0, double y0, double x1, double y1, Rgb fill) {
  const double xy[] = {x0, y0, x1, y0, x1, y1, x0, y1};
  polygon(fills_, xy, 4, fill, kFillZ);
}

void PixelCanvas::disc(double cx, double cy, double radius, Rgb fill) {
  constexpr int n = 16;
  double xy[2 * n];
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n;
    xy[2 * i] = cx + radius * std::cos(a);
    xy[2 * i + 1] = cy + radius * std::sin(a);
  }
  polygon(discs_, xy, n, fill, kDiscZ);
}

void PixelCanvas::line(double x0, double y0, double x1, double y1) {
  const vtkIdType ids[] = {line_points_->InsertNextPoint(x0, y0, kLineZ),
                           line_points_->InsertNextPoint(x1, y1, kLineZ)};
  lines_->InsertNextCell(2, ids);
}

void PixelCanvas::frame(double x0, double y0, double x1, double y1) {
  line(x0, y0, x1, y0);
  line(x1, y0, x1, y1);
  line(x1, y1, x0, y1);
  line(x0, y1, x0, y0);
}

void PixelCanvas::text(const std::string& s, double x, double y, int size, bool centred,
                       bool bold) {
  texts_.push_back({s, x, y, size, centred, bold});
}

void PixelCanvas::draw(vtkRenderer* renderer, int width, int height) {
  if (fills_.cells->GetNumberOfCells() > 0)
    renderer->AddActor(actor_of(fills_.points, fills_.cells, true, fills_.colors));
  if (discs_.cells->GetNumberOfCells() > 0)
    renderer->AddActor(actor_of(discs_.points, discs_.cells, true, discs_.colors));
  if (lines_->GetNumberOfCells() > 0)
    renderer->AddActor(actor_of(line_points_, lines_, false, nullptr));
  for (const auto& t : texts_) {
    auto actor = vtkSmartPointer<vtkTextActor>::New();
    actor->SetInput(t.s.c_str());
    auto* prop = actor->GetTextProperty();
    prop->SetFontFamilyToArial();
    prop->SetFontSize(t.size);
    prop->SetBold(t.bold);
    prop->SetColor(0, 0, 0);
    if (t.centred) prop->SetJustificationToCentered();
    prop->SetVerticalJustificationToCentered();
    actor->SetDisplayPosition(int(std::lround(t.x)), int(std::lround(t.y)));
    renderer->AddActor2D(actor);
  }
  auto* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(0.5 * width, 0.5 * height, 0.0);
  camera->SetPosition(0.5 * width, 0.5 * height, 10.0);
  camera->SetViewUp(0, 1, 0);
  camera->SetParallelScale(0.5 * height);
  camera->SetClippingRange(1.0, 20.0);
}

}  // namespace sedem::render
