#include "core/invert/invert_input.h"

#include <stdexcept>

#include "core/lab/lab_csv.h"
#include "core/physics/stokes.h"

namespace sedem::invert {

std::string reading_column(Test test) {
  switch (test) {
    case Test::hydrometer:
      return "reading_g_per_l";
    case Test::buoyancy:
      return "apparent_mass_g";
    case Test::pipette:
      return "dry_mass_g";
  }
  return "";
}

std::vector<Measurement> read_measurements_csv(std::istream& in, Test test) {
  if (test == Test::hydrometer)
    throw std::invalid_argument("read_measurements_csv: the 152H's readings are read by core/lab");
  std::vector<Measurement> out;
  for (const auto& row : read_numeric_csv(in, {"time_min", reading_column(test)}))
    out.push_back({row[0] * 60.0, row[1]});
  return out;
}

std::vector<GradingPoint> standard_reduction(const Scene& scene, Test test,
                                             const std::vector<Measurement>& data) {
  if (test == Test::hydrometer)
    throw std::invalid_argument("standard_reduction: the 152H's is ASTM D422 (core/lab)");
  const ForwardModel model(scene, test, log_grid(1e-6, 1e-4, 2), {});
  const Suspension& s = model.suspension();
  const double empty = model.empty_reading(), full = model.full_reading();
  std::vector<GradingPoint> out;
  for (const auto& m : data) {
    GradingPoint p;
    p.diameter =
        stokes::limiting_diameter(model.nominal_depth(), m.time, s.particle_density, s.fluid);
    // Eq. 22 and Eq. 17 are both linear from the empty reading (0 %) to the full (100 %).
    p.percent_finer = 100.0 * (m.value - empty) / (full - empty);
    out.push_back(p);
  }
  return out;
}

}  // namespace sedem::invert
