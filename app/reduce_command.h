#pragma once

#include <string>

namespace sedem::app {

struct ReduceOptions {
  std::string readings;          // CSV: time_min, reading_g_per_l, temperature_c[, ...]
  std::string out;               // CSV of the grading points; empty: standard output
  std::string method = "d7928";  // d7928 | d422 (withdrawn 2016)
  double specific_gravity = 2.65;
  double dry_mass_g = 50;
  double volume_ml = 1000;  // the suspension's: the percent finer is of the mass per litre
};

// `sedem reduce READINGS.csv`: a laboratory's hydrometer readings to diameters and percent
// finer, ASTM D7928 (default) or D422. Returns the exit status.
int reduce(const ReduceOptions& options);

}  // namespace sedem::app
