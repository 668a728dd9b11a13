#pragma once

// Readings of a known sample from the reference solution, rounded to the instrument's
// resolution: the material of the inversion's round-trip tests.
#include <cmath>
#include <vector>

#include "core/instruments/granulometry.h"
#include "core/invert/inversion.h"
#include "core/reference/reference_readings.h"
#include "core/run/stage_setups.h"
#include "core/sample/grading_curve.h"
#include "core/sample/size_classes.h"
#include "core/scene/scene.h"

namespace sedem::test {

// The scene's sample as size classes only (the reference needs no particles).
inline Sample classes_only(const Scene& scene) {
  Sample s;
  s.particle_density = scene.sample.particle_density;
  s.section_mass = scene.sample.total_mass * scene.cylinder.section_fraction;
  s.classes = discretise(GradingCurve(scene.sample.grading), scene.sample.size_count,
                         s.section_mass, s.particle_density);
  return s;
}

// A sample whose true curve has a knee, as the paper's sample 4 (92 % between 25 and 35 um).
inline Scene knee_scene() {
  Scene s;
  s.sample.size_count = 220;
  s.sample.grading.diameters = {2.5e-6, 25e-6, 30e-6, 35e-6, 70e-6};
  s.sample.grading.percent_finer = {0, 5, 50, 97, 100};
  return s;
}

// A log-uniform sample, 2.5-70 um: percent finer linear in log d.
inline Scene log_uniform_scene() {
  Scene s;
  s.sample.size_count = 60;
  return s;
}

inline double round_to(double v, double step) {
  return std::round(v / step) * step;
}

struct SimulatedTest {
  std::vector<invert::Measurement> exact;  // in the laboratory's units, unrounded
  std::vector<double> raw;                 // the instrument's own value (152H: R, g/L)
  TestReadings reference;                  // with the standard reduction (Eqs. 16-22)
};

// The reference solution read by `test` at the scene's times.
inline SimulatedTest simulate_test(const Scene& scene, const Sample& sample, invert::Test test) {
  Scene only = scene;
  only.instruments.hydrometer = test == invert::Test::hydrometer;
  only.instruments.buoyancy = test == invert::Test::buoyancy;
  only.instruments.pipette = test == invert::Test::pipette;
  SimulatedTest out;
  out.reference = reference_readings(test_setup(only), sample).front();
  const invert::ForwardModel model(test_setup(only), test, invert::log_grid(1e-6, 1e-4, 2), {});
  for (const auto& r : out.reference.rows) {
    // readings_<test>.csv columns: reading_g_per_l; apparent_mass_kg; dry_mass_kg.
    const double raw = test == invert::Test::hydrometer ? r.extra[0]
                       : test == invert::Test::buoyancy ? r.extra[1] * 1e3
                                                        : r.extra[3] * 1e3;
    out.raw.push_back(raw);
    const double value =
        test == invert::Test::hydrometer ? raw - model.clear_liquid_reading() : raw;
    out.exact.push_back({r.time, value});
  }
  return out;
}

// The readings as a laboratory records them: the raw value rounded to the resolution (the
// 152H's R to its graduation; its clear-liquid correction is taken as exact), plus `shift`
// (an error added before rounding, for noisy copies).
inline std::vector<invert::Measurement> recorded(const Scene& scene, const SimulatedTest& t,
                                                 invert::Test test,
                                                 const std::vector<double>& shift = {}) {
  const invert::ForwardModel model(test_setup(scene), test, invert::log_grid(1e-6, 1e-4, 2), {});
  const double res = invert::default_resolution(test);
  const double offset = test == invert::Test::hydrometer ? model.clear_liquid_reading() : 0.0;
  std::vector<invert::Measurement> out;
  for (std::size_t i = 0; i < t.raw.size(); ++i) {
    const double raw = t.raw[i] + (shift.empty() ? 0.0 : shift[i]);
    out.push_back({t.exact[i].time, round_to(raw, res) - offset});
  }
  return out;
}

}  // namespace sedem::test
