#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "app/invert_command.h"
#include "app/lab_sieve_input.h"
#include "core/instruments/granulometry.h"
#include "core/invert/inversion.h"
#include "core/lab/hydrometer_reduction.h"
#include "core/lab/whole_curve.h"

namespace sedem::app {

// What `sedem invert`'s report.html shows: the inputs, the standard followed, the figure
// (the whole curve's with a sieve analysis, else invert.png), the readings with the fit and
// the standard reduction, the sieve analysis and the whole curve.
struct InvertReportInput {
  const InvertOptions& options;
  invert::Test test;
  const std::string& standard_name;
  const std::vector<invert::Measurement>& data;
  const std::vector<LabReading>& lab;  // the 152H's readings as taken; empty otherwise
  const std::vector<GradingPoint>& standard;
  const invert::InvertedCurve& curve;
  const SieveInput* sieve;  // null: none
  const std::vector<CurvePoint>& whole;
};

void write_invert_lab_report(const InvertReportInput& in, const std::filesystem::path& file);

}  // namespace sedem::app
