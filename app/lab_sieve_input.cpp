#include "app/lab_sieve_input.h"

#include <cmath>

#include "app/lab_file.h"
#include "app/lab_report.h"

namespace sedem::app {

namespace {

// A difference between the sieves' and the pan's sum and the total dry mass above this, %,
// is worth a look (material lost or a weighing slip); sedem's own threshold.
constexpr double kSieveMassWarningPercent = 1.0;

}  // namespace

SieveInput read_sieve_input(const std::string& file, const std::string& sheet,
                            std::optional<double> total_g, double separating_mm) {
  SieveInput out;
  out.analysis = read_sieve_analysis(read_lab_file(file, sheet));
  out.total_g = sieve_total_g(out.analysis, total_g);
  out.points = sieve_percent_passing(out.analysis, total_g);
  out.passing_separating = separating_sieve_passing(out.points, separating_mm);
  const double difference = sieve_mass_difference_percent(out.analysis, total_g);
  if (std::abs(difference) > kSieveMassWarningPercent)
    out.warnings.push_back("the sieves and the pan hold " + report_number(difference, 3) + " % " +
                           (difference < 0 ? "less" : "more") + " than the total dry mass " +
                           report_number(out.total_g, 6) + " g: material lost or a weighing slip?");
  return out;
}

LabReportTable sieve_report_table(const SieveInput& sieve) {
  LabReportTable t;
  t.id = "sieves";
  t.heading = "Sieve analysis (ASTM D6913)";
  t.columns = {"opening (mm)", "opening (µm)", "retained (g)", "cumulative retained (g)",
               "passing (%)"};
  for (const auto& p : sieve.points)
    t.rows.push_back({report_number(p.opening_mm), report_number(p.opening_mm * 1e3),
                      report_number(p.retained_g, 6), report_number(p.cumulative_retained_g, 6),
                      report_number(p.percent_passing)});
  if (sieve.analysis.pan_g) t.rows.push_back({"pan", "", report_number(*sieve.analysis.pan_g, 6)});
  t.note = "Total dry mass " + report_number(sieve.total_g, 6) +
           " g; passing = 100 (total - cumulative retained) / total.";
  return t;
}

LabReportTable whole_curve_report_table(const std::vector<CurvePoint>& curve) {
  LabReportTable t;
  t.id = "whole-curve";
  t.heading = "Whole grading curve";
  t.columns = {"source",     "diameter (mm)",      "diameter (µm)", "percent finer (%)",
               "time (min)", "of the fraction (%)"};
  for (const auto& p : curve)
    t.rows.push_back({p.source, report_number(p.diameter * 1e3), report_number(p.diameter * 1e6),
                      report_number(p.percent_finer), report_number(p.time / 60.0),
                      report_number(p.fraction_percent_finer)});
  t.note =
      "A sedimentation point's percent finer is of the fraction passing the separating sieve; "
      "of the whole sample it is that times the percent passing the separating sieve / 100.";
  return t;
}

}  // namespace sedem::app
