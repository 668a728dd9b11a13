#pragma once

#include <filesystem>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <vtkImageData.h>
#include <vtkSmartPointer.h>

#include "render/xml_series.h"

namespace sedem::render {

// The layer fields at one time (Sect. 4.5.1): the column cut into n_ly horizontal layers.
struct LayerFields {
  double time_s = 0;
  double column_height_m = 0.457;
  double section_width_m = 0.0635;
  // Per layer, counted from the free surface down (the paper's j = 1 .. n_ly).
  std::vector<double> suspension_density_kg_m3;  // Eq. 20
  std::vector<double> concentration_kg_m3;       // mass of particles per volume of suspension
  // Further per-layer arrays, same order and length (e.g. {"volume_fraction", ...}).
  std::vector<std::pair<std::string, std::vector<double>>> extra;
};

// The layers as image data: one cell per layer spanning the section's width (2 x (n+1) x 1
// points, origin (-B/2, 0, 0), y up as in the particle files), cell data
// suspension_density (kg/m^3), concentration (kg/m^3), depth (m, of the layer's centre) and
// the extras; field data TimeValue.
vtkSmartPointer<vtkImageData> layer_image(const LayerFields& fields);

// DIR/fields.pvd and DIR/fields/fields_NNNNNN.vti.
class FieldSeriesWriter {
 public:
  explicit FieldSeriesWriter(const std::filesystem::path& out_dir,
                             double keep_until = -std::numeric_limits<double>::infinity());
  std::filesystem::path write(const LayerFields& fields);

 private:
  XmlSeriesWriter series_;
};

}  // namespace sedem::render
