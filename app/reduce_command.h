#pragma once

#include <string>

namespace sedem::app {

struct ReduceOptions {
  std::string readings;         // CSV: time_min, reading_g_per_l, temperature_c[, ...]
  std::string out;              // CSV of the grading points; empty: standard output
  std::string method = "d422";  // d422 | d7928
  double specific_gravity = 2.65;
  double dry_mass_g = 50;
};

// `sedem reduce READINGS.csv`: a laboratory's hydrometer readings to diameters and percent
// finer, ASTM D422 or D7928. Returns the exit status.
int reduce(const ReduceOptions& options);

}  // namespace sedem::app
