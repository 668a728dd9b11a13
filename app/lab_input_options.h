#pragma once

#include <optional>
#include <string>

namespace sedem::app {

// What `reduce` and `invert` both take of a laboratory's files (docs/lab.md): the readings'
// sheet of a workbook, and the sieve analysis of the same sample that makes the whole curve.
struct LabInputOptions {
  std::string sheet;                    // the readings' sheet; empty: the first
  std::string sieve;                    // the sieve analysis (ASTM D6913); empty: none
  std::string sieve_sheet;              // its sheet, when it is a workbook; empty: the first
  std::optional<double> sieve_total_g;  // the sample's total dry mass; default the file's
  double separating_sieve_mm = 2.0;     // the sieve the tested specimen passed (No. 10)
};

}  // namespace sedem::app
