#pragma once

#include <filesystem>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "render/xml_series.h"

namespace sedem::render {

// The layer fields at one time (Sect. 4.5.1): the column cut into n_ly horizontal layers.
struct LayerFields {
  double time_s = 0;
  double column_height_m = 0.457;
  double section_width_m = 0.0635;
  double particle_density_kg_m3 = 2500;
  double fluid_density_kg_m3 = 1000;
  // Per layer, counted from the free surface down (the paper's j = 1 .. n_ly).
  std::vector<double> suspension_density_kg_m3;  // Eq. 20
  std::vector<double> concentration_kg_m3;       // mass of particles per volume of suspension
  // Further per-layer arrays, same order and length (e.g. {"volume_fraction", ...}).
  std::vector<std::pair<std::string, std::vector<double>>> extra;
};

// The densest packing a layer is shown with: random close packing of spheres. In the bed the
// weighted grains of the 2D section overfill their layers (a solid fraction above 1, a
// "suspension" denser than the grains themselves); the files show those layers at this
// solid fraction and flag them as bed.
inline constexpr double kBedSolidFraction = 0.64;

// The layers as a strip of quads across the section, one row of two points (x = -B/2 and
// x = +B/2) per layer at the height of the layer's centre (y up, bottom at 0), 1 mm behind
// the particles' plane (z = -0.001) so that they draw over it. Point data, so that ParaView
// colours it with no further step: suspension_density (kg/m^3, active scalars),
// concentration (kg/m^3), solid_fraction (-), depth (m below the free surface), bed (1
// where the layer was clipped to kBedSolidFraction, 0 elsewhere), and the extras; field
// data TimeValue. Point ids run from the free surface down: points 2j and 2j + 1 are layer j.
vtkSmartPointer<vtkPolyData> layer_strip(const LayerFields& fields);

// DIR/fields.pvd and DIR/fields/fields_NNNNNN.vtp.
class FieldSeriesWriter {
 public:
  explicit FieldSeriesWriter(const std::filesystem::path& out_dir,
                             double keep_until = -std::numeric_limits<double>::infinity());
  std::filesystem::path write(const LayerFields& fields);

 private:
  XmlSeriesWriter series_;
};

}  // namespace sedem::render
