// The ASTM 152H: geometry derived from its published data, equilibrium in a uniform and in
// a linear density profile, each against a hand computation.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/instruments/hydrometer.h"
#include "test_support.h"

namespace sedem {
namespace {

constexpr double kPi = std::numbers::pi;

// Derivation by hand (docs/instruments.md). The scale reads g/L of Gs = 2.65 soil in water
// at 20 C (998.2067 kg/m^3): rho(R) = 998.2067 + R (1 - 1/2.65) = 998.2067 + 0.6226415 R;
// rho(50) = 1029.338775.
// Floating at R = 0 (mark 10.5 cm above the bulb) and at R = 50 (2.3 cm):
//   A = V_B (rho50 - rho0) / (rho0 0.105 - rho50 0.023)
//     = 67e-6 * 31.132075 / (104.811704 - 23.674792) = 2.5707770e-5 m^2 (stem 5.72 mm wide)
//   M = rho0 (V_B + 0.105 A) = 998.2067 * 6.96993e-5 = 0.069574324 kg
// Bulb with 2 cm cones at both ends: pi [r^2 (0.10 + 0.02/3 + 0.02/3) + 0.02 (r r_s + r_s^2)/3]
//   = 67e-6 with r_s = 2.8606e-3 m gives r = 1.36163e-2 m.
TEST(Hydrometer, GeometryFromThePublishedData) {
  const HydrometerGeometry h = make_hydrometer();
  EXPECT_NEAR(h.stem_area(), 2.5707770e-5, 1e-11);
  EXPECT_NEAR(h.mass, 0.069574324, 1e-9);
  EXPECT_NEAR(h.radii[1], 1.36163405e-2, 1e-9);
  EXPECT_NEAR(h.volume_below(h.bulb_length), 67e-6, 1e-15);
  // The marks: 0.164 cm per g/L, R = 0 at 10.5 cm.
  EXPECT_NEAR(h.mark_of(0), 0.105, 1e-15);
  EXPECT_NEAR(h.mark_of(50), 0.023, 1e-15);
  EXPECT_NEAR(h.reading_at(0.105 - 0.00164 * 27), 27.0, 1e-12);
}

// Uniform suspension of 1 % solids: rho_s = 1000 + 1500 * 0.01 = 1015 kg/m^3.
//   V_sub = M / 1015 = 6.8546132e-5 m^3; stem submerged l = (V_sub - V_B) / A = 0.0601426 m
//   tip = l + 0.14 = 0.2001426 m; centre = tip - 0.07 = 0.1301426 m
//   R = (0.105 - 0.0601426) / 0.00164 = 27.35207
//   standard L = 16.29 - 0.164 R = 11.80426 cm (the simulated centre is 17.5 - 0.164 R cm:
//   the 1.21 cm between them is D422's V_B / (2 A_cylinder) for the inserted hydrometer).
// Clear water (1000): V = 6.9574324e-5, l = 0.1001380, tip y_ow = 0.2401380 m, so Eq. 19
//   r_s = M / (M - A (0.2401380 - 0.2001426) 1000) = 1.015 exactly as for a uniform liquid.
TEST(Hydrometer, UniformSuspensionMatchesHandComputation) {
  const HydrometerGeometry h = make_hydrometer();
  Suspension s;
  s.initial_concentration = 25.0;  // so that 1 % solids (25 kg/m^3) is 100 %
  const LayerFields f = testing::fields_with_density([](double) { return 1015.0; }, s.cylinder,
                                                     s.fluid, 2500.0, 4000);
  const HydrometerReading r = read_hydrometer(h, f, 120.0, s);
  EXPECT_NEAR(r.tip_depth, 0.2001426, 2e-7);
  EXPECT_NEAR(r.centre_depth, 0.1301426, 2e-7);
  EXPECT_NEAR(r.reading, 27.35207, 1e-4);
  EXPECT_NEAR(r.standard_effective_depth, 0.1180426, 2e-7);
  EXPECT_NEAR(r.clear_water_tip_depth, 0.2401380, 2e-7);
  EXPECT_NEAR(r.density_eq19, 1015.0, 1e-6);
  EXPECT_NEAR(r.bulb_mean_density, 1015.0, 1e-9);
  EXPECT_NEAR(r.percent_finer, 100.0, 1e-4);
  EXPECT_NEAR(r.percent_finer_bulb_density, 100.0, 1e-6);
  // Eq. 16 at the centre after 2 min: sqrt(18e-3 / (1500 9.81)) sqrt(0.1301426 / 120).
  EXPECT_NEAR(r.diameter, std::sqrt(18e-3 / (1500 * 9.81)) * std::sqrt(0.1301426 / 120.0), 1e-10);
  // Fig. 13: one density per layer along the 14 cm bulb, all 1015.
  ASSERT_NEAR(double(r.profile_density.size()), 0.14 / f.layer_height(), 2.0);
  for (double rho : r.profile_density) EXPECT_NEAR(rho, 1015.0, 1e-9);
  EXPECT_NEAR(r.profile_offset.back(), 0.14, f.layer_height());
  // The closed form agrees.
  EXPECT_NEAR(tip_depth_in_uniform(h, 1015.0), 0.2001426, 2e-7);
}

// A cylindrical bulb (no cones: r_b = sqrt(V_B / (pi L)) = 1.234237e-2 m) in
// rho(d) = 1000 + 100 d (kg/m^3, d in m). With the stem submerged by s, the tip at s + L:
//   M = pi r_b^2 int_s^{s+L} rho + A int_0^s rho
//     = V_B [1000 + 100 (s + L/2)] + A (1000 s + 50 s^2)
// i.e. (50 A) s^2 + (100 V_B + 1000 A) s + V_B (1000 + 7) - M = 0:
//   1.2853885e-3 s^2 + 3.2407770e-2 s + (6.7469e-5 - 6.9574324e-5) = 0 -> s = 0.0647970 m
//   tip = 0.2047970 m, R = (0.105 - 0.0647970) / 0.00164 = 24.51401,
//   mean density along the bulb = 1000 + 100 (s + 0.07) = 1013.4797 kg/m^3.
TEST(Hydrometer, LinearDensityProfileMatchesHandComputation) {
  HydrometerDesign d;
  d.tip_length = 0;
  d.shoulder_length = 0;
  const HydrometerGeometry h = make_hydrometer(d);
  EXPECT_NEAR(h.radii[1], 1.234237e-2, 1e-8);
  Suspension s;
  s.initial_concentration = 41.457;
  const LayerFields f = testing::fields_with_density(
      [](double depth) { return 1000.0 + 100.0 * depth; }, s.cylinder, s.fluid, 2500.0, 4000);
  const HydrometerReading r = read_hydrometer(h, f, 900.0, s);
  EXPECT_NEAR(r.tip_depth, 0.2047970, 2e-7);
  EXPECT_NEAR(r.reading, 24.51401, 2e-4);
  EXPECT_NEAR(r.bulb_mean_density, 1013.4797, 1e-4);
  // Eq. 19 assumes a uniform liquid: it reads the density of the uniform liquid that floats
  // the hydrometer at the same depth, rho_f M / (M - A (y_ow - y_o) rho_f), which is not
  // the bulb's mean in a graded suspension (Fig. 14).
  const double expected19 =
      1000.0 * h.mass / (h.mass - h.stem_area() * (r.clear_water_tip_depth - r.tip_depth) * 1000.0);
  EXPECT_NEAR(r.density_eq19, expected19, 1e-9);
  EXPECT_GT(std::abs(r.density_eq19 - r.bulb_mean_density), 0.05);
}

TEST(Hydrometer, SinksDeeperAsTheSuspensionClears) {
  const HydrometerGeometry h = make_hydrometer();
  Suspension s;
  double previous = 0;
  for (double rho : {1030.0, 1020.0, 1010.0, 1000.0}) {
    const LayerFields f = testing::fields_with_density([rho](double) { return rho; }, s.cylinder,
                                                       s.fluid, 2500.0, 400);
    const double tip = equilibrium_tip_depth(h, f);
    EXPECT_GT(tip, previous);
    EXPECT_NEAR(tip, tip_depth_in_uniform(h, rho), 1e-9);
    previous = tip;
  }
}

// Sect. 4.5.1's pressure sum and the displaced-weight sum are the same integral (by parts,
// p = 0 at the surface): they agree to the one-sided pressure's O(h_ly) error, at most one
// layer's pressure step on the bulb's cross-section, rho g h_ly pi r_b^2 / W
// = 1015 * 9.81 * 1.1425e-4 * 4.79e-4 / 0.6825 = 8e-4 of the force.
TEST(Hydrometer, PaperPressureSumAgreesWithDisplacedWeight) {
  Suspension s;
  const LayerFields f = testing::fields_with_density([](double d) { return 1000.0 + 100.0 * d; },
                                                     s.cylinder, s.fluid, 2500.0, 4000);
  for (double tip_length : {0.0, 0.02}) {
    HydrometerDesign d;
    d.tip_length = tip_length;
    d.shoulder_length = tip_length;
    const HydrometerGeometry h = make_hydrometer(d);
    for (std::size_t j : {1500u, 1800u, 2100u}) {
      const double exact = hydrostatic_force(h, f, double(j) * f.layer_height());
      const double summed = hydrostatic_force_pressure_sum(h, f, j);
      EXPECT_NEAR(summed, exact, 8e-4 * exact) << tip_length << " " << j;
    }
  }
}

TEST(Hydrometer, StandardEffectiveDepth) {
  EXPECT_NEAR(astm_152h_effective_depth(0), 0.1629, 1e-15);
  EXPECT_NEAR(astm_152h_effective_depth(50), 0.0809, 1e-15);
}

}  // namespace
}  // namespace sedem
