#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace sedem {

class Schema;

// The grading curve: percent finer against diameter (Sect. 4.4, Fig. 5).
struct GradingConfig {
  std::string family = "table";                  // table | log_uniform | log_normal | rosin_rammler
  std::vector<double> diameters{2.5e-6, 70e-6};  // m, for "table", ascending
  std::vector<double> percent_finer{0, 100};     // %, non-decreasing, ends at 100
  double min_diameter = 2.5e-6;                  // m, for the named families
  double max_diameter = 70e-6;                   // m
  double median_diameter = 15e-6;                // m, log_normal d50 / rosin_rammler scale
  double spread = 0.6;  // log_normal sigma of ln d / rosin_rammler uniformity n
};

// How the sample is discretised and placed (Sect. 4.4).
struct SampleConfig {
  double particle_density = 2500.0;  // kg/m^3
  double total_mass = 60e-3;         // kg poured into the whole cylinder
  std::int64_t size_count = 220;     // n_phi
  std::int64_t simulated_count = 5000;
  std::string weighting = "equal_mass";  // equal_mass | uniform_count
  std::int64_t seed = 1;
  GradingConfig grading;
};

void describe(SampleConfig& config, Schema& schema);

}  // namespace sedem
