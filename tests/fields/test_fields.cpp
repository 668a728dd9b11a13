// Layer fields (Eq. 20), pressures, the concentration grid and Fig. 12's profile from a
// hand-placed set of weighted particles.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/fields/layer_fields.h"
#include "core/physics/stokes.h"

namespace sedem {
namespace {

// A column with round numbers: H = 1 m, B = 0.1 m and a section fraction that makes
// h_z = pi/4 B f = 0.01 m. With 4 layers each is 0.1 x 0.25 x 0.01 = 2.5e-4 m^3.
Cylinder round_cylinder() {
  Cylinder c;
  c.height = 1.0;
  c.diameter = 0.1;
  c.section_fraction = 0.4 / std::numbers::pi;
  return c;
}

constexpr double kLayerVolume = 2.5e-4;

// Adds a particle of diameter d at (x, y) whose weight makes its real volume `volume`.
void add(Particles& p, double x, double y, double d, double volume) {
  const std::size_t i = p.size();
  p.resize(i + 1);
  p.x[i] = x;
  p.y[i] = y;
  p.diameter[i] = d;
  p.weight[i] = volume / (std::numbers::pi / 6.0 * d * d * d);
}

// Layer 0 (depth 0-0.25): 1 % solids; layer 1: 2 % in two particles, one exactly on the
// boundary at depth 0.25 (it belongs to the layer below); layer 2: none; layer 3: 4 % from a
// particle whose centre is below the bottom (contact overlap), kept in the last layer.
Particles hand_placed() {
  Particles p;
  add(p, -0.04, 0.90, 0.010, 0.01 * kLayerVolume);
  add(p, 0.01, 0.75, 0.020, 0.015 * kLayerVolume);
  add(p, 0.03, 0.60, 0.005, 0.005 * kLayerVolume);
  add(p, 0.02, -0.001, 0.008, 0.04 * kLayerVolume);
  return p;
}

TEST(Fields, DensityConcentrationAndPressureOfHandPlacedParticles) {
  const Cylinder cyl = round_cylinder();
  ASSERT_NEAR(cyl.slab_thickness(), 0.01, 1e-15);
  const Fluid water;  // 1000 kg/m^3, g = 9.81
  const LayerFields f = compute_layer_fields(hand_placed(), cyl, water, 2500.0, 4);
  ASSERT_EQ(f.count(), 4u);
  EXPECT_NEAR(f.layer_volume(), kLayerVolume, 1e-18);
  // Eq. 20: rho_s = 2500 phi + 1000 (1 - phi) = 1000 + 1500 phi.
  const double density[] = {1015, 1030, 1000, 1060};
  // c = 2500 phi kg/m^3.
  const double concentration[] = {25, 50, 0, 100};
  // p^j = sum rho_s^n h_ly g, h_ly g = 0.25 * 9.81 = 2.4525:
  //   2489.2875, + 2526.075 = 5015.3625, + 2452.5 = 7467.8625, + 2599.65 = 10067.5125.
  const double pressure[] = {2489.2875, 5015.3625, 7467.8625, 10067.5125};
  for (std::size_t j = 0; j < 4; ++j) {
    EXPECT_NEAR(f.density()[j], density[j], 1e-9) << j;
    EXPECT_NEAR(f.concentration()[j], concentration[j], 1e-9) << j;
    EXPECT_NEAR(f.pressure()[j], pressure[j], 1e-8) << j;
  }
  // Within a layer the pressure is linear: half-way down layer 1, 2489.2875 + 1030 * 0.125 g.
  EXPECT_NEAR(f.pressure_at(0.375), 2489.2875 + 1030 * 0.125 * 9.81, 1e-8);
  EXPECT_NEAR(f.pressure_at(0.0), 0.0, 1e-12);
  // Mean over [0.125, 0.375]: half in layer 0, half in layer 1.
  EXPECT_NEAR(f.mean_density(0.125, 0.375), 0.5 * (1015 + 1030), 1e-9);
  // int_0.5^1 rho d dd = 1000 (0.75^2 - 0.5^2) / 2 + 1060 (1 - 0.75^2) / 2.
  EXPECT_NEAR(f.density_integral(0.5, 1.0, 0, 1, 0), 156.25 + 231.875, 1e-9);
}

TEST(Fields, ConcentrationGridOfHandPlacedParticles) {
  const Cylinder cyl = round_cylinder();
  const ConcentrationGrid g = concentration_grid(hand_placed(), cyl, 2500.0, 2, 2);
  // Cells of 0.5 x 0.05 x 0.01 = 2.5e-4 m^3, i.e. one layer's volume.
  // Top-left (x < 0, depth < 0.5): the 1 % particle -> 25 kg/m^3; top-right: 1.5 % + 0.5 %.
  EXPECT_NEAR(g.at(0, 0), 25.0, 1e-9);
  EXPECT_NEAR(g.at(0, 1), 50.0, 1e-9);
  EXPECT_NEAR(g.at(1, 0), 0.0, 1e-12);
  EXPECT_NEAR(g.at(1, 1), 100.0, 1e-9);
}

TEST(Fields, LargestDiameterAboveEachDepthAgainstEq16) {
  const Cylinder cyl = round_cylinder();
  const Fluid water;
  const double t = 600.0;
  const auto prof = largest_diameter_profile(hand_placed(), cyl, water, 2500.0, 4, t);
  const double largest[] = {0.010, 0.020, 0.020, 0.020};
  for (std::size_t j = 0; j < 4; ++j) {
    EXPECT_DOUBLE_EQ(prof.largest[j], largest[j]) << j;
    EXPECT_NEAR(prof.depth[j], 0.25 * double(j + 1), 1e-15);
    // Eq. 16: sqrt(18 mu / ((rho_p - rho_f) g)) sqrt(y / t).
    const double expected = std::sqrt(18e-3 / (1500 * 9.81)) * std::sqrt(prof.depth[j] / t);
    EXPECT_NEAR(prof.limiting[j], expected, 1e-12 * expected);
  }
}

TEST(Fields, TotalMassIsConservedWhateverTheLayerCount) {
  const Cylinder cyl = round_cylinder();
  const Fluid water;
  for (std::size_t n : {1u, 3u, 4u, 4000u}) {
    const LayerFields f = compute_layer_fields(hand_placed(), cyl, water, 2500.0, n);
    double mass = 0;
    for (double c : f.concentration()) mass += c * f.layer_volume();
    // 7 % of one 2.5e-4 m^3 layer volume of 2500 kg/m^3 solids.
    EXPECT_NEAR(mass, 0.07 * kLayerVolume * 2500.0, 1e-12) << n;
    // The bottom pressure is the weight of liquid and solids per unit area.
    EXPECT_NEAR(f.pressure().back(), (1000.0 * 1.0 + 1500.0 * 0.07 * 0.25) * 9.81, 1e-8) << n;
  }
}

}  // namespace
}  // namespace sedem
