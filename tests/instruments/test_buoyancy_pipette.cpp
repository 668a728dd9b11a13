// The buoyancy sphere (Eq. 22) and the pipette (Eq. 17) against hand computations.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/instruments/buoyancy_sphere.h"
#include "core/instruments/pipette.h"
#include "test_support.h"

namespace sedem {
namespace {

// Sphere of 2.5 cm and 20 g: V = pi/6 0.025^3 = 8.1812309e-6 m^3.
// Clear water: m_w = 0.02 - 1000 V = 0.0118187691 kg.
// Uniform 1015 kg/m^3: m_sp = 0.02 - 1015 V = 0.0116960507 kg (0.1227 g lighter).
// Eq. 22 with c_0 = 25 kg/m^3: 100 (1000/25) (m_w - m_sp) / ((0.4 - 1)(m_w - 0.02))
//   = 100 * 40 * 1.2271846e-4 / 4.9087385e-3 = 100 %.
TEST(Buoyancy, UniformSuspensionMatchesHandComputation) {
  Suspension s;
  s.initial_concentration = 25.0;
  const BuoyancySphere sphere{0.025, 0.020, 0.3 * s.cylinder.height};
  const LayerFields f = testing::fields_with_density([](double) { return 1015.0; }, s.cylinder,
                                                     s.fluid, 2500.0, 4000);
  const BuoyancyReading r = read_buoyancy(sphere, f, 60.0, s);
  EXPECT_NEAR(sphere.volume(), 8.1812309e-6, 1e-13);
  EXPECT_NEAR(r.clear_water_apparent_mass, 0.0118187691, 1e-10);
  EXPECT_NEAR(r.apparent_mass, 0.0116960507, 1e-10);
  EXPECT_NEAR(r.mean_density, 1015.0, 1e-7);
  EXPECT_NEAR(r.percent_finer, 100.0, 1e-6);
  // Eq. 16 at y_bt = 0.3 H = 0.1371 m after 60 s.
  EXPECT_NEAR(r.diameter, std::sqrt(18e-3 / (1500 * 9.81)) * std::sqrt(0.1371 / 60.0), 1e-12);
}

// rho(d) = 1000 + 100 d: the sphere is symmetric about y_bt = 0.1371 m, so the displaced
// liquid has the density at its centre, 1013.71 kg/m^3; m_sp = 0.02 - 1013.71 V
// = 0.0117066045 kg; with c_0 = 41.457 kg/m^3, w_o = 100 (13.71 / 0.6) / 41.457 = 55.118 %.
TEST(Buoyancy, LinearProfileMatchesHandComputation) {
  Suspension s;
  s.initial_concentration = 41.457;
  const BuoyancySphere sphere{0.025, 0.020, 0.1371};
  const LayerFields f = testing::fields_with_density([](double d) { return 1000.0 + 100.0 * d; },
                                                     s.cylinder, s.fluid, 2500.0, 4000);
  const BuoyancyReading r = read_buoyancy(sphere, f, 60.0, s);
  EXPECT_NEAR(r.mean_density, 1013.71, 1e-6);
  EXPECT_NEAR(r.apparent_mass, 0.0117066045, 1e-10);
  EXPECT_NEAR(r.percent_finer, 100.0 * (13.71 / 0.6) / 41.457, 1e-5);
}

// Pipette, default cylinder: h_z = pi/4 0.0635 / 180 = 2.7707102e-4 m; the circle stands for
// 35 mL / 180 = 1.9444444e-7 m^3, so r = sqrt(1.9444444e-7 / (pi h_z)) = 1.4946079e-2 m.
// Two particles of 1e-5 kg each (real mass, weights included) have centres inside, two just
// outside (1.5 cm from the centre): c = 2e-5 / 1.9444444e-7 = 102.857143 kg/m^3, the dry
// mass of 35 mL is 3.6e-3 kg (= 180 x 2e-5), and w_o = 100 c / c_0.
TEST(Pipette, HandPlacedParticles) {
  Suspension s;
  s.initial_concentration = 41.456985;
  const Pipette pipette{35e-6, 0.1371};
  const double r = pipette.radius(s.cylinder);
  EXPECT_NEAR(r, 1.4946079e-2, 1e-9);
  const double yc = s.cylinder.height - 0.1371;
  Particles p;
  const double xs[] = {0.0, 0.01, 0.0, 0.012}, ys[] = {yc, yc + 0.01, yc + 0.015, yc - 0.009};
  p.resize(4);
  const double d = 20e-6, grain = 2500.0 * std::numbers::pi / 6.0 * d * d * d;
  for (std::size_t i = 0; i < 4; ++i) {
    p.x[i] = xs[i];
    p.y[i] = ys[i];
    p.diameter[i] = d;
    p.weight[i] = 1e-5 / grain;
  }
  const PipetteReading reading = read_pipette(pipette, p, 300.0, s);
  EXPECT_NEAR(reading.concentration, 102.857143, 1e-5);
  EXPECT_NEAR(reading.dry_mass, 3.6e-3, 1e-12);
  EXPECT_NEAR(reading.percent_finer, 100.0 * 102.857143 / 41.456985, 1e-4);
  EXPECT_NEAR(reading.diameter, std::sqrt(18e-3 / (1500 * 9.81)) * std::sqrt(0.1371 / 300.0),
              1e-12);
}

// From a field uniform across the section with c(d) = 10 + 100 d kg/m^3: the circle is
// symmetric about its centre, so its mean is c(0.1371) = 23.71 kg/m^3.
TEST(Pipette, LinearConcentrationField) {
  Suspension s;
  s.initial_concentration = 23.71 * 2.0;
  const Pipette pipette{35e-6, 0.1371};
  // rho_s - rho_f = c (1 - rho_f / rho_p) = 0.6 c.
  const LayerFields f =
      testing::fields_with_density([](double d) { return 1000.0 + 0.6 * (10.0 + 100.0 * d); },
                                   s.cylinder, s.fluid, 2500.0, 4000);
  const PipetteReading reading = read_pipette(pipette, f, 300.0, s);
  EXPECT_NEAR(reading.concentration, 23.71, 1e-6);
  EXPECT_NEAR(reading.percent_finer, 50.0, 1e-5);
}

}  // namespace
}  // namespace sedem
