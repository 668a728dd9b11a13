#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace sedem {

// Above this many particles a scene is refused (memory, and no engine would finish).
inline constexpr std::int64_t kMaxSimulatedCount = 100'000'000;

// The grading curve: percent finer against diameter (Sect. 4.4, Fig. 5).
struct GradingConfig {
  // table | log_uniform | log_normal | rosin_rammler | single
  std::string family = "table";
  std::vector<double> diameters{2.5e-6, 70e-6};  // m, for "table", ascending
  std::vector<double> percent_finer{0, 100};     // %, non-decreasing, from 0 to 100
  double min_diameter = 2.5e-6;                  // m, for the named families
  double max_diameter = 70e-6;                   // m
  double median_diameter = 15e-6;                // m, log_normal d50 / rosin_rammler scale
  double spread = 0.6;      // log_normal sigma of ln d / rosin_rammler uniformity n
  double diameter = 30e-6;  // m, for "single": every grain this size
};

// Where the particles start (Fig. 6).
struct PlacementConfig {
  std::int64_t cells_per_side = 0;         // n_mt; 0: the paper's ceil(sqrt(particle count))
  double max_area_fraction = 0.4;          // above this a scene is refused as unplaceable
  std::string method = "low_discrepancy";  // low_discrepancy | stratified
};

// How the sample is discretised, weighted and placed (Sect. 4.4).
struct SampleConfig {
  double particle_density = 2500.0;  // kg/m^3
  double total_mass = 60e-3;         // kg poured into the whole cylinder
  std::int64_t size_count = 220;     // n_phi
  // Exactly one of these two is non-zero: the particle count, or the share of the section's
  // real grains (by mass, each simulated particle counted as one grain) to simulate.
  std::int64_t simulated_count = 5000;
  double mass_fraction = 0;
  std::string weighting = "equal_mass";  // equal_mass | uniform_count | equal_per_size
  std::int64_t seed = 1;
  GradingConfig grading;
  PlacementConfig placement;
};

}  // namespace sedem
