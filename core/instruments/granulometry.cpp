#include "core/instruments/granulometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace sedem {

TestReadings to_readings(const std::vector<HydrometerReading>& readings) {
  TestReadings t;
  t.test = "hydrometer";
  t.extra_columns = {"reading_g_per_l",
                     "tip_depth_m",
                     "centre_depth_m",
                     "standard_effective_depth_m",
                     "density_eq19_kg_m3",
                     "bulb_mean_density_kg_m3",
                     "percent_finer_bulb_density",
                     "on_scale"};
  for (const auto& r : readings)
    t.rows.push_back(
        {r.time,
         r.diameter,
         r.percent_finer,
         {r.reading, r.tip_depth, r.centre_depth, r.standard_effective_depth, r.density_eq19,
          r.bulb_mean_density, r.percent_finer_bulb_density, r.on_scale ? 1.0 : 0.0}});
  return t;
}

TestReadings to_readings(const std::vector<BuoyancyReading>& readings) {
  TestReadings t;
  t.test = "buoyancy";
  t.extra_columns = {"depth_m", "apparent_mass_kg", "clear_water_apparent_mass_kg",
                     "mean_density_kg_m3"};
  for (const auto& r : readings)
    t.rows.push_back({r.time,
                      r.diameter,
                      r.percent_finer,
                      {r.depth, r.apparent_mass, r.clear_water_apparent_mass, r.mean_density}});
  return t;
}

TestReadings to_readings(const std::vector<PipetteReading>& readings) {
  TestReadings t;
  t.test = "pipette";
  t.extra_columns = {"depth_m", "radius_m", "concentration_kg_m3", "dry_mass_kg"};
  for (const auto& r : readings)
    t.rows.push_back(
        {r.time, r.diameter, r.percent_finer, {r.depth, r.radius, r.concentration, r.dry_mass}});
  return t;
}

std::vector<GradingPoint> true_grading_curve(const std::vector<SizeClass>& classes) {
  std::vector<SizeClass> sorted = classes;
  std::sort(sorted.begin(), sorted.end(),
            [](const SizeClass& a, const SizeClass& b) { return a.diameter < b.diameter; });
  std::vector<GradingPoint> curve;
  double total = 0, sum = 0;
  for (const auto& c : sorted) total += c.mass_fraction;
  for (const auto& c : sorted) {
    sum += c.mass_fraction;
    curve.push_back({c.diameter, 100.0 * sum / total});
  }
  return curve;
}

double true_percent_finer(const std::vector<SizeClass>& classes, double diameter) {
  double total = 0, finer = 0;
  for (const auto& c : classes) {
    total += c.mass_fraction;
    if (c.diameter <= diameter) finer += c.mass_fraction;
  }
  return total > 0 ? 100.0 * finer / total : 0.0;
}

double curve_error(const TestReadings& dem, const TestReadings& reference) {
  if (dem.rows.size() != reference.rows.size())
    throw std::invalid_argument("curve_error: " + dem.test + " has " +
                                std::to_string(dem.rows.size()) + " readings, the reference " +
                                std::to_string(reference.rows.size()));
  // No reading, no error: the maximum over nothing is unknown, not the 0 it would start at.
  if (dem.rows.empty()) return std::numeric_limits<double>::quiet_NaN();
  double worst = 0;
  for (std::size_t k = 0; k < dem.rows.size(); ++k) {
    const double t0 = dem.rows[k].time, t1 = reference.rows[k].time;
    if (std::abs(t0 - t1) > 1e-9 * std::max(1.0, std::abs(t0)))
      throw std::invalid_argument("curve_error: " + dem.test + " reading " + std::to_string(k) +
                                  " at " + std::to_string(t0) + " s, reference at " +
                                  std::to_string(t1) + " s");
    const double d = std::abs(dem.rows[k].percent_finer - reference.rows[k].percent_finer);
    // A reading that is no number makes the error unknown, not zero (std::max drops NaN).
    if (!std::isfinite(d)) return std::numeric_limits<double>::quiet_NaN();
    worst = std::max(worst, d);
  }
  return worst;
}

double curve_bias(const TestReadings& reference, const std::vector<SizeClass>& classes) {
  if (reference.rows.empty()) return std::numeric_limits<double>::quiet_NaN();
  double worst = 0;
  for (const auto& r : reference.rows) {
    const double d = std::abs(r.percent_finer - true_percent_finer(classes, r.diameter));
    if (!std::isfinite(d) || !std::isfinite(r.diameter))
      return std::numeric_limits<double>::quiet_NaN();
    worst = std::max(worst, d);
  }
  return worst;
}

Granulometry compare(const std::vector<TestReadings>& dem,
                     const std::vector<TestReadings>& reference,
                     const std::vector<SizeClass>& classes) {
  Granulometry g;
  g.true_curve = true_grading_curve(classes);
  for (const auto& d : dem) {
    auto it = std::find_if(reference.begin(), reference.end(),
                           [&](const TestReadings& r) { return r.test == d.test; });
    if (it == reference.end())
      throw std::invalid_argument("compare: no reference for test " + d.test);
    g.tests.push_back({d.test, d, *it, curve_error(d, *it), curve_bias(*it, classes)});
  }
  return g;
}

}  // namespace sedem
