#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace sedem {

// The three laboratory tests of Sect. 4.5 and the layered field they read (Eq. 20).
struct InstrumentsConfig {
  std::int64_t layers = 4000;  // n_ly
  // Fig. 12: times of the largest-diameter-above-depth profiles (paper: 60, 120, 300, 900 s).
  std::vector<double> profile_times{60, 120, 300, 900};
  // Fig. 13: times of the density profiles along the hydrometer's bulb (paper: 0, 60, 180,
  // 300, 900 s), apart from its reading times so that its first minute can be compared.
  std::vector<double> bulb_profile_times{0, 60, 180, 300, 900};

  bool hydrometer = true;
  std::vector<double> hydrometer_times{120, 300, 900, 1800, 3600, 15000, 86400};  // s

  bool buoyancy = true;
  double buoyancy_depth_fraction = 0.3;  // sphere centre depth / H
  double sphere_diameter = 0.025;        // m
  double sphere_mass = 20e-3;            // kg
  std::vector<double> buoyancy_times{30, 60, 120, 240, 900, 1800, 3600, 7200, 14400, 28800};

  bool pipette = true;
  double pipette_depth_fraction = 0.3;
  double pipette_volume = 35e-6;  // m^3 of the whole cylinder
  std::vector<double> pipette_times{30, 60, 120, 240, 900, 1800, 3600, 7200, 14400, 28800};

  // Shape of the 152H bulb's ends (the published data fix its length and volume only).
  double hydrometer_tip_length = 0.020;       // m
  double hydrometer_shoulder_length = 0.020;  // m

  // The continuum reference solution.
  std::string reference_settling = "local_voidage";
  double reference_richardson_zaki_exponent = 4.65;
  double reference_bed_packing = 0.6;
};

// The height (m above the bottom of a column `height` tall) below which none of the enabled
// instruments reads, less a 1 cm margin: the bottom of the hydrometer's bulb at its deepest
// reading (effective depth 16.29 cm at R = 0 plus half the 14 cm bulb), the buoyancy sphere,
// the pipette's sample (a sphere of its volume).
double lowest_measured_height(const InstrumentsConfig& config, double height);

// Whether any of the three tests is enabled.
bool any_instrument(const InstrumentsConfig& config);

}  // namespace sedem
