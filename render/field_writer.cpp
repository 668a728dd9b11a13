#include "render/field_writer.h"

#include <algorithm>
#include <stdexcept>

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>

namespace sedem::render {

namespace {

constexpr double kStripZ = -0.001;  // m: just behind the particles' plane z = 0

vtkSmartPointer<vtkDoubleArray> point_array(const std::string& name, vtkIdType n) {
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name.c_str());
  a->SetNumberOfTuples(n);
  return a;
}

}  // namespace

vtkSmartPointer<vtkPolyData> layer_strip(const LayerFields& f) {
  const std::size_t n = f.suspension_density_kg_m3.size();
  if (n == 0) throw std::invalid_argument("layer_strip: no layers");
  auto check = [n](const std::vector<double>& v, const std::string& name) {
    if (v.size() != n)
      throw std::invalid_argument("layer_strip: " + name + " has " + std::to_string(v.size()) +
                                  " layers, suspension_density " + std::to_string(n));
  };
  check(f.concentration_kg_m3, "concentration");
  for (const auto& [name, values] : f.extra) check(values, name);

  const double h = f.column_height_m / double(n), half = 0.5 * f.section_width_m;
  const auto points_n = vtkIdType(2 * n);
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(points_n);
  auto density = point_array("suspension_density", points_n);
  auto concentration = point_array("concentration", points_n);
  auto fraction = point_array("solid_fraction", points_n);
  auto depth = point_array("depth", points_n);
  auto bed = vtkSmartPointer<vtkUnsignedCharArray>::New();
  bed->SetName("bed");
  bed->SetNumberOfTuples(points_n);
  std::vector<vtkSmartPointer<vtkDoubleArray>> extras;
  for (const auto& e : f.extra) extras.push_back(point_array(e.first, points_n));

  const double rho_p = f.particle_density_kg_m3, rho_f = f.fluid_density_kg_m3;
  for (std::size_t j = 0; j < n; ++j) {
    const double d = (double(j) + 0.5) * h;
    double phi = f.concentration_kg_m3[j] / rho_p;
    double rho_s = f.suspension_density_kg_m3[j];
    const bool clipped = phi > kBedSolidFraction;
    if (clipped) {
      phi = kBedSolidFraction;
      rho_s = rho_f + (rho_p - rho_f) * phi;
    }
    for (int side = 0; side < 2; ++side) {
      const auto k = vtkIdType(2 * j) + side;
      points->SetPoint(k, side ? half : -half, f.column_height_m - d, kStripZ);
      density->SetValue(k, rho_s);
      concentration->SetValue(k, phi * rho_p);
      fraction->SetValue(k, phi);
      depth->SetValue(k, d);
      bed->SetValue(k, clipped ? 1 : 0);
      for (std::size_t e = 0; e < extras.size(); ++e) extras[e]->SetValue(k, f.extra[e].second[j]);
    }
  }
  auto quads = vtkSmartPointer<vtkCellArray>::New();
  for (vtkIdType j = 0; j + 1 < vtkIdType(n); ++j) {
    const vtkIdType quad[] = {2 * j, 2 * j + 2, 2 * j + 3, 2 * j + 1};
    quads->InsertNextCell(4, quad);
  }
  if (n == 1) {  // one layer: a line across the section
    const vtkIdType line[] = {0, 1};
    quads->InsertNextCell(2, line);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  if (n == 1) {
    poly->SetLines(quads);
  } else {
    poly->SetPolys(quads);
  }
  auto* pd = poly->GetPointData();
  pd->AddArray(density);
  pd->AddArray(concentration);
  pd->AddArray(fraction);
  pd->AddArray(depth);
  pd->AddArray(bed);
  for (const auto& e : extras) pd->AddArray(e);
  pd->SetActiveScalars("suspension_density");
  return poly;
}

FieldSeriesWriter::FieldSeriesWriter(const std::filesystem::path& out_dir, double keep_until)
    : series_(out_dir, "fields", "vtp", keep_until) {}

std::filesystem::path FieldSeriesWriter::write(const LayerFields& fields) {
  return series_.write(layer_strip(fields), fields.time_s);
}

}  // namespace sedem::render
