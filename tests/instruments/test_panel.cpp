// The instrument panel on the particles of a freshly built sample: a uniform suspension, so
// every test must read close to 100 % finer, and the hydrometer must float where the
// closed form puts it in the suspension's mean density.
#include <gtest/gtest.h>

#include <iostream>

#include <algorithm>

#include "core/instruments/instrument_panel.h"
#include "core/physics/stokes.h"
#include "core/reference/reference_readings.h"
#include "core/run/stage_setups.h"
#include "core/sample/sample_builder.h"
#include "core/scene/scene.h"

namespace sedem {
namespace {

TEST(InstrumentPanel, UniformStartReadsTheWholeSample) {
  Scene scene;
  scene.sample.simulated_count = 20000;
  scene.instruments.hydrometer_times = {60.0};
  scene.instruments.buoyancy_times = {60.0};
  scene.instruments.pipette_times = {30.0, 60.0};
  const Sample sample = build_sample(sample_setup(scene));
  InstrumentPanel panel(test_setup(scene), sample);
  EXPECT_EQ(panel.reading_times(), (std::vector<double>{30.0, 60.0}));
  // c_0 = (60 g / 180) / (B H h_z) = 41.457 kg/m^3.
  EXPECT_NEAR(panel.suspension().initial_concentration, 41.456985, 1e-5);
  panel.observe(30.0, sample.particles);
  panel.observe(45.0, sample.particles);  // nothing due
  panel.observe(60.0, sample.particles);
  const auto readings = panel.readings();
  ASSERT_EQ(readings.size(), 3u);
  EXPECT_EQ(readings[0].rows.size(), 1u);
  EXPECT_EQ(readings[1].rows.size(), 1u);
  EXPECT_EQ(readings[2].rows.size(), 2u);
  // The bulb spans ~1200 layers: its mean is within 1 % of the initial concentration.
  EXPECT_NEAR(readings[0].rows[0].percent_finer, 100.0, 2.0);
  // Equal-mass particles: the sphere's 2.5 cm band holds 5.5 % of them (~1100, a 3 % spread),
  // the pipette's circle (7.0e-4 of the section's 2.9e-2 m^2) 2.4 % (~480, a 4.5 % spread).
  EXPECT_NEAR(readings[1].rows[0].percent_finer, 100.0, 10.0);
  EXPECT_NEAR(readings[2].rows[0].percent_finer, 100.0, 15.0);
  const HydrometerReading& h = panel.hydrometer_readings()[0];
  EXPECT_TRUE(h.on_scale);
  EXPECT_NEAR(h.tip_depth, tip_depth_in_uniform(panel.hydrometer(), h.bulb_mean_density), 2e-3);
}

// Particles moved exactly as the reference moves them (each straight down at its Stokes
// velocity, stopping at the bottom) and read from their weighted positions must give the
// reference's readings up to the sampling noise of 20000 particles: the DEM read-out and the
// continuum agree when the dynamics do.
TEST(InstrumentPanel, KinematicSettlingMatchesTheReference) {
  Scene scene;
  scene.forces.drag = "stokes";
  scene.sample.simulated_count = 20000;
  scene.instruments.buoyancy_times = {60, 240, 900};
  scene.instruments.pipette_times = {60, 240, 900};
  const Sample sample = build_sample(sample_setup(scene));
  InstrumentPanel panel(test_setup(scene), sample);
  for (double t : panel.reading_times()) {
    Particles p = sample.particles;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double u =
          stokes::terminal_velocity(p.diameter[i], sample.particle_density, scene.fluid);
      p.y[i] = std::max(0.5 * p.diameter[i], p.y[i] - u * t);
    }
    panel.observe(t, p);
  }
  const auto dem = panel.readings();
  const auto reference = reference_readings(test_setup(scene), sample);
  const Granulometry g = compare(dem, reference, sample.classes);
  ASSERT_EQ(g.tests.size(), 3u);
  // Sampling noise only: the hydrometer's bulb holds ~6000 of the equal-mass particles
  // (a 1.3 % spread of the reading, correlated between times since the particles are the
  // same; over seeds 1-4 the largest error is 0.5-2.1 pp); the sphere's 2.5 cm band ~1100;
  // the pipette's 1.5 cm circle ~480 at the start.
  EXPECT_LT(g.tests[0].error, 3.0);
  EXPECT_LT(g.tests[1].error, 6.0);
  EXPECT_LT(g.tests[2].error, 12.0);
  for (const auto& t : g.tests)
    std::cout << t.test << ": error " << t.error << " pp, bias " << t.bias << " pp\n";
}

}  // namespace
}  // namespace sedem
