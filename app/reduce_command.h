#pragma once

#include <string>

#include "app/lab_input_options.h"

namespace sedem::app {

struct ReduceOptions {
  std::string readings;          // CSV (',' or ';', decimal comma), tab-separated text or .xlsx
  std::string out;               // CSV of the grading points; empty: standard output
  std::string method = "d7928";  // d7928 | d422 (withdrawn 2016)
  double specific_gravity = 2.65;
  double dry_mass_g = 50;
  double volume_ml = 1000;  // the suspension's: the percent finer is of the mass per litre
  // The readings' sheet and the sieve analysis: with it the output is the whole curve.
  LabInputOptions lab;
  std::string report;  // a lab report page (.html) to write; empty: none
};

// `sedem reduce READINGS`: a laboratory's hydrometer readings to diameters and percent
// finer, ASTM D7928 (default) or D422; with --sieve, merged with the sieve analysis into the
// whole grading curve; with --report, a one-page report beside. Returns the exit status.
int reduce(const ReduceOptions& options);

}  // namespace sedem::app
