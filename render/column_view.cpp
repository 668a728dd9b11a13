#include "render/column_view.h"

#include <algorithm>
#include <cstdio>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include "render/offscreen_view.h"

namespace sedem::render {
namespace {

vtkSmartPointer<vtkActor> outline_actor(const Cylinder& c) {
  const double h = c.half_width();
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->InsertNextPoint(-h, c.height, 0);
  points->InsertNextPoint(-h, 0, 0);
  points->InsertNextPoint(h, 0, 0);
  points->InsertNextPoint(h, c.height, 0);
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  vtkIdType ids[] = {0, 1, 2, 3};
  lines->InsertNextCell(4, ids);
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetLines(lines);
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(poly);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.1, 0.1, 0.1);
  actor->GetProperty()->SetLineWidth(2);
  return actor;
}

}  // namespace

void render_column_png(const Snapshot& snapshot, const Cylinder& cylinder, const std::string& title,
                       int width, int height, const std::filesystem::path& file) {
  const auto& p = snapshot.particles;
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetNumberOfPoints(vtkIdType(p.size()));
  auto diameter_um = vtkSmartPointer<vtkDoubleArray>::New();
  diameter_um->SetName("diameter_um");
  diameter_um->SetNumberOfTuples(vtkIdType(p.size()));
  auto verts = vtkSmartPointer<vtkCellArray>::New();
  double dmin = 1e300, dmax = 0;
  for (vtkIdType i = 0; i < vtkIdType(p.size()); ++i) {
    points->SetPoint(i, p.x[std::size_t(i)], p.y[std::size_t(i)], 0.0);
    const double d = p.diameter[std::size_t(i)] * 1e6;
    diameter_um->SetValue(i, d);
    dmin = std::min(dmin, d);
    dmax = std::max(dmax, d);
    verts->InsertNextCell(1, &i);
  }
  if (p.empty()) dmin = 0, dmax = 1;
  if (dmax <= dmin) dmax = dmin + 1;
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetVerts(verts);
  poly->GetPointData()->SetScalars(diameter_um);

  auto lut = vtkSmartPointer<vtkLookupTable>::New();
  lut->SetHueRange(0.62, 0.0);  // small: blue, large: red
  lut->SetTableRange(dmin, dmax);
  lut->Build();
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(poly);
  mapper->SetLookupTable(lut);
  mapper->SetScalarRange(dmin, dmax);
  mapper->ScalarVisibilityOn();
  auto particles = vtkSmartPointer<vtkActor>::New();
  particles->SetMapper(mapper);
  particles->GetProperty()->SetPointSize(2);

  OffscreenView view(width, height);
  auto* ren = view.renderer();
  ren->AddActor(outline_actor(cylinder));
  ren->AddActor(particles);

  auto bar = vtkSmartPointer<vtkScalarBarActor>::New();
  bar->SetLookupTable(lut);
  bar->SetTitle("diameter (um)");
  bar->SetNumberOfLabels(4);
  bar->SetPosition(0.78, 0.1);
  bar->SetWidth(0.2);
  bar->SetHeight(0.5);
  bar->GetTitleTextProperty()->SetColor(0, 0, 0);
  bar->GetLabelTextProperty()->SetColor(0, 0, 0);
  bar->GetTitleTextProperty()->SetFontSize(12);
  ren->AddActor2D(bar);

  auto text = vtkSmartPointer<vtkTextActor>::New();
  char when[64];
  std::snprintf(when, sizeof when, "  t = %.1f s", snapshot.time);
  text->SetInput((title + when).c_str());
  text->GetTextProperty()->SetColor(0, 0, 0);
  text->GetTextProperty()->SetFontSize(16);
  text->SetDisplayPosition(8, height - 24);
  ren->AddActor2D(text);

  auto* cam = ren->GetActiveCamera();
  cam->ParallelProjectionOn();
  cam->SetFocalPoint(0.15 * cylinder.diameter, 0.5 * cylinder.height, 0);
  cam->SetPosition(0.15 * cylinder.diameter, 0.5 * cylinder.height, 1.0);
  cam->SetViewUp(0, 1, 0);
  cam->SetParallelScale(0.53 * cylinder.height);
  ren->ResetCameraClippingRange();
  view.save_png(file);
}

}  // namespace sedem::render
