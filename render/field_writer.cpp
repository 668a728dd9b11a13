#include "render/field_writer.h"

#include <cstdio>
#include <stdexcept>

#include <vtkCellData.h>
#include <vtkDoubleArray.h>

#include "render/vtk_xml.h"

namespace sedem::render {

vtkSmartPointer<vtkImageData> layer_image(const LayerFields& f) {
  const std::size_t n = f.suspension_density_kg_m3.size();
  if (n == 0) throw std::invalid_argument("layer_image: no layers");
  auto check = [n](const std::vector<double>& v, const std::string& name) {
    if (v.size() != n)
      throw std::invalid_argument("layer_image: " + name + " has " + std::to_string(v.size()) +
                                  " layers, suspension_density " + std::to_string(n));
  };
  check(f.concentration_kg_m3, "concentration");
  for (const auto& [name, values] : f.extra) check(values, name);

  const double h = f.column_height_m / double(n);
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(2, int(n) + 1, 1);
  image->SetOrigin(-0.5 * f.section_width_m, 0.0, 0.0);
  image->SetSpacing(f.section_width_m, h, 1.0);

  // Cells run from the bottom up; layer j (from the surface) is cell n - 1 - j.
  auto add = [&](const std::string& name, const std::vector<double>* values) {
    auto a = vtkSmartPointer<vtkDoubleArray>::New();
    a->SetName(name.c_str());
    a->SetNumberOfTuples(vtkIdType(n));
    for (std::size_t j = 0; j < n; ++j)
      a->SetValue(vtkIdType(n - 1 - j), values ? (*values)[j] : (double(j) + 0.5) * h);
    image->GetCellData()->AddArray(a);
  };
  add("suspension_density", &f.suspension_density_kg_m3);
  add("concentration", &f.concentration_kg_m3);
  add("depth", nullptr);
  for (const auto& [name, values] : f.extra) add(name, &values);
  image->GetCellData()->SetActiveScalars("suspension_density");
  return image;
}

FieldSeriesWriter::FieldSeriesWriter(const std::filesystem::path& out_dir, double keep_until)
    : series_(out_dir, "fields", "vti", keep_until) {}

std::filesystem::path FieldSeriesWriter::write(const LayerFields& fields) {
  return series_.write(layer_image(fields), fields.time_s);
}

}  // namespace sedem::render
