#include "render/hydrometer_writer.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkPoints.h>

namespace sedem::render {

vtkSmartPointer<vtkPolyData> bulb_surface(const BulbProfile& profile, double tip_y, int segments) {
  const std::size_t n = profile.height_m.size();
  if (n < 2 || profile.radius_m.size() != n)
    throw std::invalid_argument("bulb_surface: need at least two (height, radius) pairs");
  if (segments < 3) throw std::invalid_argument("bulb_surface: at least 3 segments");
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  // One point for a ring of zero radius, `segments` points otherwise.
  std::vector<vtkIdType> first(n);
  std::vector<bool> single(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double y = tip_y + profile.height_m[i], r = profile.radius_m[i];
    first[i] = points->GetNumberOfPoints();
    single[i] = r <= 0;
    if (single[i]) {
      points->InsertNextPoint(0, y, 0);
      continue;
    }
    for (int k = 0; k < segments; ++k) {
      const double a = 2.0 * std::numbers::pi * k / segments;
      points->InsertNextPoint(r * std::cos(a), y, r * std::sin(a));
    }
  }
  auto ring = [&](std::size_t i, int k) {
    return single[i] ? first[i] : first[i] + vtkIdType(k % segments);
  };
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  for (std::size_t i = 0; i + 1 < n; ++i) {
    if (single[i] && single[i + 1]) continue;
    for (int k = 0; k < segments; ++k) {
      if (single[i]) {
        const vtkIdType tri[] = {ring(i, k), ring(i + 1, k), ring(i + 1, k + 1)};
        polys->InsertNextCell(3, tri);
      } else if (single[i + 1]) {
        const vtkIdType tri[] = {ring(i, k), ring(i + 1, k), ring(i, k + 1)};
        polys->InsertNextCell(3, tri);
      } else {
        const vtkIdType quad[] = {ring(i, k), ring(i + 1, k), ring(i + 1, k + 1), ring(i, k + 1)};
        polys->InsertNextCell(4, quad);
      }
    }
  }
  // Caps on open ends.
  for (std::size_t end : {std::size_t(0), n - 1}) {
    if (single[end]) continue;
    std::vector<vtkIdType> cap(static_cast<std::size_t>(segments));
    for (int k = 0; k < segments; ++k) cap[std::size_t(k)] = ring(end, end == 0 ? k : segments - k);
    polys->InsertNextCell(vtkIdType(cap.size()), cap.data());
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(polys);
  return poly;
}

HydrometerSeriesWriter::HydrometerSeriesWriter(const std::filesystem::path& out_dir,
                                               BulbProfile profile, double column_height_m)
    : series_(out_dir, "hydrometer", "vtp"),
      profile_(std::move(profile)),
      height_(column_height_m) {}

std::filesystem::path HydrometerSeriesWriter::write(double time_s, double tip_depth_m) {
  auto poly = bulb_surface(profile_, height_ - tip_depth_m);
  auto depth = vtkSmartPointer<vtkDoubleArray>::New();
  depth->SetName("tip_depth");
  depth->SetNumberOfTuples(1);
  depth->SetValue(0, tip_depth_m);
  poly->GetFieldData()->AddArray(depth);
  return series_.write(poly, time_s);
}

}  // namespace sedem::render
