#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/lab_report.h"
#include "core/lab/sieve_analysis.h"
#include "core/lab/whole_curve.h"

namespace sedem::app {

// The sieve analysis `reduce --sieve` and `invert --sieve` read, with its percent passing and
// what the report shows of it.
struct SieveInput {
  SieveAnalysis analysis;
  std::vector<SievePoint> points;
  double total_g = 0;
  double passing_separating = 0;  // % of the sample passing the separating sieve
  std::vector<std::string> warnings;
};

// Reads `file` (text or .xlsx, app/lab_file.h) and works out its percent passing (D6913) and
// the separating sieve's. Throws std::invalid_argument (LabCsvError) for what is wrong.
SieveInput read_sieve_input(const std::string& file, const std::string& sheet,
                            std::optional<double> total_g, double separating_mm);

// The sieve table of a lab report: opening (mm, µm), mass retained, cumulative, % passing;
// the pan and the total.
LabReportTable sieve_report_table(const SieveInput& sieve);

// The whole curve's table of a lab report.
LabReportTable whole_curve_report_table(const std::vector<CurvePoint>& curve);

}  // namespace sedem::app
