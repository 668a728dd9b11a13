#include "app/invert_lab_report.h"

#include <cmath>

#include "app/lab_report.h"

namespace sedem::app {

namespace {

LabReportTable readings_table(const InvertReportInput& in) {
  const bool hydrometer = in.test == invert::Test::hydrometer;
  const std::string unit = hydrometer ? "g/L" : "g";
  LabReportTable t;
  t.id = "readings";
  t.heading = "Readings and results";
  t.columns = {"time (min)"};
  if (!in.lab.empty()) t.columns.insert(t.columns.end(), {"R (g/L)", "T (°C)", "C (g/L)"});
  t.columns.insert(t.columns.end(),
                   {"measured (" + unit + ")", "fitted (" + unit + ")", "pinned diameter (µm)",
                    "inverted (%)", in.standard_name + " diameter (µm)",
                    in.standard_name + " diameter (mm)", in.standard_name + " (%)"});
  for (std::size_t i = 0; i < in.data.size(); ++i) {
    std::vector<std::string> row{report_number(in.data[i].time / 60.0)};
    if (i < in.lab.size())
      row.insert(row.end(), {report_number(in.lab[i].reading), report_number(in.lab[i].temperature),
                             report_number(in.lab[i].composite_correction)});
    const double pinned = in.curve.reading_diameter[i];
    row.insert(
        row.end(),
        {report_number(in.curve.measured[i], 6), report_number(in.curve.fitted[i], 6),
         report_number(pinned * 1e6), report_number(in.curve.at(pinned)),
         report_number(in.standard[i].diameter * 1e6), report_number(in.standard[i].diameter * 1e3),
         report_number(in.standard[i].percent_finer)});
    t.rows.push_back(std::move(row));
  }
  t.note =
      "The inverted curve's percent finer where each reading pins it, beside the "
      "standard reduction's diameter and percent finer (docs/invert.md).";
  return t;
}

}  // namespace

void write_invert_lab_report(const InvertReportInput& in, const std::filesystem::path& file) {
  const InvertOptions& o = in.options;
  LabReport report;
  report.title = "sedem invert (" + o.test + "): " +
                 std::filesystem::path(o.run.empty() ? o.readings : o.run).filename().string();
  report.standard = in.standard_name + " beside the inversion" +
                    (in.sieve ? ", with ASTM D6913 (sieve analysis)" : "");
  if (o.run.empty())
    report.inputs.push_back({"readings", o.readings});
  else
    report.inputs.push_back({"run", o.run});
  if (!o.lab.sheet.empty()) report.inputs.push_back({"sheet", o.lab.sheet});
  report.inputs.push_back({"test", o.test});
  if (!o.scene.empty()) report.inputs.push_back({"scene", o.scene});
  auto optional = [&](const char* name, const std::optional<double>& v) {
    if (v) report.inputs.push_back({name, report_number(*v, 6)});
  };
  optional("specific gravity Gs", o.specific_gravity);
  optional("dry mass (g)", o.dry_mass_g);
  optional("suspension volume (mL)", o.volume_ml);
  optional("cylinder area (cm²)", o.area_cm2);
  optional("depth (cm)", o.depth_cm);
  optional("temperature (°C)", o.temperature_c);
  optional("clear liquid's density (kg/m³)", o.liquid_density);
  optional("sphere's blank (g)", o.blank_g);
  optional("pipette volume (mL)", o.pipette_ml);
  report.inputs.push_back({"band", in.curve.replicas > 0
                                       ? report_number(100 * in.curve.coverage, 3) + " % of " +
                                             std::to_string(in.curve.replicas) + " replicas"
                                       : std::string("none (--replicas 0)")});
  if (in.sieve) {
    report.inputs.push_back({"sieve analysis", o.lab.sieve});
    report.inputs.push_back({"total dry mass (g)", report_number(in.sieve->total_g, 6)});
    report.inputs.push_back({"separating sieve (mm)", report_number(o.lab.separating_sieve_mm)});
    report.inputs.push_back(
        {"passing the separating sieve (%)", report_number(in.sieve->passing_separating)});
    report.warnings = in.sieve->warnings;
  }
  if (o.partial)
    report.warnings.push_back(
        "partial: from a run that did not complete; its readings stop "
        "where it did");
  report.figure_stem = in.sieve ? "grading_curve" : "invert";
  report.tables.push_back(readings_table(in));
  if (in.sieve) {
    report.tables.push_back(sieve_report_table(*in.sieve));
    report.tables.push_back(whole_curve_report_table(in.whole));
  }
  report.files = {"inverted_curve.csv", "readings_fit.csv", "invert.json"};
  if (in.sieve) report.files.insert(report.files.end(), {"whole_curve.csv", "invert.png"});
  write_lab_report(report, file);
}

}  // namespace sedem::app
