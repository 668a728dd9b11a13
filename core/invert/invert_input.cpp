#include "core/invert/invert_input.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/lab/hydrometer_reduction.h"
#include "core/lab/lab_csv.h"
#include "core/physics/stokes.h"

namespace sedem::invert {

const ReadingFormat& reading_format(Test test) {
  static const ReadingFormat hydrometer{"reading_g_per_l", "reading_g_per_l", 1.0, "ASTM D7928"};
  static const ReadingFormat sphere{"apparent_mass_g", "apparent_mass_kg", 1e3, "Eq. 22 (sphere)"};
  static const ReadingFormat pipette{"dry_mass_g", "dry_mass_kg", 1e3, "Eq. 17 (pipette)"};
  return test == Test::hydrometer ? hydrometer : test == Test::buoyancy ? sphere : pipette;
}

std::vector<Measurement> read_measurements_csv(std::istream& in, Test test) {
  return read_measurements(read_lab_text(in), test);
}

std::vector<Measurement> read_measurements(const LabTable& table, Test test,
                                           std::vector<std::size_t>* lines_out) {
  if (test == Test::hydrometer)
    throw std::invalid_argument("read_measurements: the 152H's readings are read by core/lab");
  std::vector<Measurement> out;
  std::vector<std::size_t> lines;
  const auto rows = lab_columns(table, {"time_min", reading_format(test).lab_column}, {}, &lines);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    check_lab_time_min(lines[i], rows[i][0], table.place);
    out.push_back({rows[i][0] * 60.0, rows[i][1]});
  }
  if (lines_out) *lines_out = lines;
  return out;
}

std::vector<GradingPoint> standard_reduction(const TestSetup& setup, Test test,
                                             const std::vector<Measurement>& data) {
  if (test == Test::hydrometer)
    throw std::invalid_argument("standard_reduction: the 152H's is ASTM D7928/D422 (core/lab)");
  const ForwardModel model(setup, test, log_grid(1e-6, 1e-4, 2), {});
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

LabSpecimen lab_specimen(const TestSetup& setup) {
  const double volume = std::numbers::pi / 4.0 * setup.cylinder.diameter * setup.cylinder.diameter *
                        setup.cylinder.height;
  return {setup.particle_density / 1000.0, setup.total_mass, volume};
}

RecordedTest record_simulated(const TestSetup& setup, Test test, const std::vector<double>& times,
                              const std::vector<double>& raw, double resolution, LabMethod method) {
  if (times.size() != raw.size())
    throw std::invalid_argument("record_simulated: as many times as readings");
  const double step = resolution > 0 ? resolution : default_resolution(test);
  const ForwardModel model(setup, test, log_grid(1e-6, 1e-4, 2), {});
  const double clear = test == Test::hydrometer ? model.clear_liquid_reading() : 0.0;
  RecordedTest out;
  std::vector<LabReading> lab;
  for (std::size_t i = 0; i < times.size(); ++i) {
    const double r = std::round(raw[i] / step) * step;
    out.data.push_back({times[i], r - clear});
    lab.push_back({times[i], r, 20.0, clear, 0.0, 0});
  }
  if (test == Test::hydrometer) {
    for (const auto& p : reduce_lab_readings(lab, lab_specimen(setup), method))
      out.standard.push_back({p.diameter, p.percent_finer});
  } else {
    out.standard = standard_reduction(setup, test, out.data);
  }
  return out;
}

}  // namespace sedem::invert
