#include "render/hydrometer_writer.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkPoints.h>

namespace sedem::render {

vtkSmartPointer<vtkPolyData> bulb_surface(const BulbProfile& profile, double tip_y, int segments,
                                          BulbPart part) {
  const std::size_t n = profile.height_m.size();
  if (n < 2 || profile.radius_m.size() != n)
    throw std::invalid_argument("bulb_surface: need at least two (height, radius) pairs");
  if (segments < 3) throw std::invalid_argument("bulb_surface: at least 3 segments");
  const bool whole = part == BulbPart::whole;
  // The whole surface: `segments` points around, the last facet closing on the first. The
  // back half: angles pi .. 2 pi (z <= 0), segments / 2 facets, open on the plane z = 0.
  const int facets = whole ? segments : std::max(2, segments / 2);
  const int around = whole ? segments : facets + 1;
  const double start = whole ? 0.0 : std::numbers::pi;
  const double step = (whole ? 2.0 : 1.0) * std::numbers::pi / facets;
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  // One point for a ring of zero radius, `around` points otherwise.
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
    for (int k = 0; k < around; ++k) {
      const double a = start + step * k;
      const double z = r * std::sin(a);
      points->InsertNextPoint(r * std::cos(a), y, whole ? z : std::min(z, 0.0));  // sin(2 pi) > 0
    }
  }
  auto ring = [&](std::size_t i, int k) {
    return single[i] ? first[i] : first[i] + vtkIdType(k % around);
  };
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  for (std::size_t i = 0; i + 1 < n; ++i) {
    if (single[i] && single[i + 1]) continue;
    for (int k = 0; k < facets; ++k) {
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
  // Caps on open ends (half discs for the back half).
  for (std::size_t end : {std::size_t(0), n - 1}) {
    if (single[end]) continue;
    std::vector<vtkIdType> cap(static_cast<std::size_t>(around));
    for (int k = 0; k < around; ++k)
      cap[std::size_t(k)] = ring(end, end == 0 ? k : (whole ? segments - k : around - 1 - k));
    polys->InsertNextCell(vtkIdType(cap.size()), cap.data());
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(polys);
  if (!whole) {
    // The outline in the section's plane: up the side x < 0, down the side x > 0, closed.
    std::vector<vtkIdType> outline;
    for (std::size_t i = 0; i < n; ++i) outline.push_back(ring(i, 0));
    for (std::size_t i = n; i-- > 0;) outline.push_back(ring(i, around - 1));
    outline.push_back(outline.front());
    auto lines = vtkSmartPointer<vtkCellArray>::New();
    lines->InsertNextCell(vtkIdType(outline.size()), outline.data());
    poly->SetLines(lines);
  }
  return poly;
}

HydrometerSeriesWriter::HydrometerSeriesWriter(const std::filesystem::path& out_dir,
                                               BulbProfile profile, double column_height_m)
    : series_(out_dir, "hydrometer", "vtp"),
      profile_(std::move(profile)),
      height_(column_height_m) {}

std::filesystem::path HydrometerSeriesWriter::write(double time_s, double tip_depth_m) {
  auto poly = bulb_surface(profile_, height_ - tip_depth_m, 48, BulbPart::back_half);
  auto depth = vtkSmartPointer<vtkDoubleArray>::New();
  depth->SetName("tip_depth");
  depth->SetNumberOfTuples(1);
  depth->SetValue(0, tip_depth_m);
  poly->GetFieldData()->AddArray(depth);
  return series_.write(poly, time_s);
}

}  // namespace sedem::render
