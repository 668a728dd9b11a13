#include "app/reduce_command.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "app/exit_codes.h"
#include "app/lab_file.h"
#include "app/lab_report.h"
#include "app/lab_sieve_input.h"
#include "core/lab/hydrometer_reduction.h"
#include "core/lab/lab_csv.h"
#include "core/lab/whole_curve.h"
#include "core/model/shortened.h"
#include "render/atomic_write.h"
#include "render/lab_curve_figure.h"

namespace sedem::app {

namespace {

namespace fs = std::filesystem;

// `text` to the standard output, or to `file` through a temporary file renamed into place (a
// failed write leaves no half file). Returns the exit status.
int write_output(const std::string& file, const std::string& text) {
  if (file.empty()) {
    // Checked after a flush: a full disk or a closed pipe is an error, not a silent loss.
    errno = 0;
    std::cout << text;
    std::cout.flush();
    if (!std::cout || std::fflush(stdout) != 0) {
      std::fprintf(stderr, "sedem: cannot write the standard output: %s\n",
                   errno ? std::strerror(errno) : "write error");
      return exit_code::io_failure;
    }
    return exit_code::ok;
  }
  const std::string tmp = file + ".tmp";
  FILE* f = std::fopen(tmp.c_str(), "w");
  if (!f) {
    std::fprintf(stderr, "sedem: cannot write %s: %s\n", shortened(file).c_str(),
                 std::strerror(errno));
    return exit_code::output_unwritable;
  }
  errno = 0;
  const bool written = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  const int write_errno = errno;
  const bool closed = std::fclose(f) == 0;
  const int close_errno = errno;
  if (!written || !closed || std::rename(tmp.c_str(), file.c_str()) != 0) {
    const int e = !written ? write_errno : !closed ? close_errno : errno;
    std::fprintf(stderr, "sedem: cannot write %s: %s\n", shortened(file).c_str(),
                 e ? std::strerror(e) : "write error");
    std::remove(tmp.c_str());
    return exit_code::io_failure;
  }
  return exit_code::ok;
}

// The report's figure beside the page: <page without .html>_curve.png and .csv.
fs::path figure_base(const std::string& report) {
  fs::path base(report);
  return base.parent_path() / (base.stem().string() + "_curve");
}

LabReportTable readings_table(const std::vector<LabReading>& readings,
                              const std::vector<LabPoint>& points, const std::string& standard) {
  LabReportTable t;
  t.id = "readings";
  t.heading = "Readings and results (" + standard + ")";
  t.columns = {"time (min)",  "R (g/L)",    "T (°C)",        "C (g/L)",       "Cm (g/L)",
               "R - C (g/L)", "depth (cm)", "diameter (µm)", "diameter (mm)", "percent finer (%)"};
  for (std::size_t i = 0; i < points.size() && i < readings.size(); ++i) {
    const auto& r = readings[i];
    const auto& p = points[i];
    t.rows.push_back({report_number(r.time / 60.0), report_number(r.reading),
                      report_number(r.temperature), report_number(r.composite_correction),
                      report_number(r.meniscus_correction), report_number(p.corrected_reading),
                      report_number(p.effective_depth * 100), report_number(p.diameter * 1e6),
                      report_number(p.diameter * 1e3), report_number(p.percent_finer)});
  }
  return t;
}

int run_reduce(const ReduceOptions& options) {
  // --out and --report are checked first: a folder, a pipe or a device (as root, renaming over
  // /dev/full would replace the device) is refused before anything is read or written.
  std::vector<std::string> outputs;
  if (!options.out.empty()) outputs = {options.out, options.out + ".tmp"};
  if (!options.report.empty())
    for (const std::string& f :
         {options.report, options.report + ".tmp", figure_base(options.report).string() + ".png",
          figure_base(options.report).string() + ".csv"})
      outputs.push_back(f);
  for (const auto& file : outputs)
    if (const std::string why = unfit_output_file(file); !why.empty()) {
      std::fprintf(stderr, "sedem: %s\n", shortened(why).c_str());
      return exit_code::output_unwritable;
    }
  const LabMethod method = parse_lab_method(options.method);
  const LabSpecimen specimen{options.specific_gravity, options.dry_mass_g * 1e-3,
                             options.volume_ml * 1e-6};
  std::vector<LabReading> readings;
  std::vector<LabPoint> points;
  try {
    readings = read_lab_readings(read_lab_file(options.readings, options.lab.sheet));
    points = reduce_lab_readings(readings, specimen, method);
  } catch (const std::invalid_argument& e) {  // LabCsvError, InvalidLabReading
    std::fprintf(stderr, "sedem: %s: %s\n", shortened(options.readings).c_str(), e.what());
    return exit_code::invalid_scene;
  }
  for (const auto& p : points)
    if (p.percent_finer > 100)
      std::fprintf(stderr, "sedem: warning: percent finer %.1f %% at %.0f s is above 100 %%\n",
                   p.percent_finer, p.time);
  std::optional<SieveInput> sieve;
  std::vector<CurvePoint> curve;
  if (!options.lab.sieve.empty()) {
    try {
      sieve = read_sieve_input(options.lab.sieve, options.lab.sieve_sheet,
                               options.lab.sieve_total_g, options.lab.separating_sieve_mm);
    } catch (const std::invalid_argument& e) {
      std::fprintf(stderr, "sedem: %s: %s\n", shortened(options.lab.sieve).c_str(), e.what());
      return exit_code::invalid_scene;
    }
    for (const auto& w : sieve->warnings)
      std::fprintf(stderr, "sedem: warning: %s: %s\n", shortened(options.lab.sieve).c_str(),
                   w.c_str());
    std::vector<SedimentationPoint> sedimentation;
    for (const auto& p : points) sedimentation.push_back({p.diameter, p.percent_finer, p.time});
    curve =
        whole_curve(sieve->points, options.lab.separating_sieve_mm, "hydrometer", sedimentation);
    if (const std::string conflict = whole_curve_conflict(curve); !conflict.empty()) {
      std::fprintf(stderr, "sedem: warning: %s\n", conflict.c_str());
      sieve->warnings.push_back(conflict);
    }
  } else {
    for (const auto& p : points)
      curve.push_back({"hydrometer", p.diameter, p.percent_finer, p.time, p.percent_finer, NAN});
  }
  std::ostringstream text;
  if (sieve)
    write_whole_curve_csv(text, curve);
  else
    write_lab_points_csv(text, points);
  if (const int status = write_output(options.out, text.str()); status != exit_code::ok)
    return status;
  if (options.report.empty()) return exit_code::ok;

  const std::string standard =
      lab_method_name(method) + (sieve ? " with ASTM D6913 (sieve analysis)" : "");
  LabReport report;
  report.title = "sedem reduce: " + fs::path(options.readings).filename().string();
  report.standard = standard;
  report.inputs = {{"readings", options.readings},
                   {"method", lab_method_name(method)},
                   {"specific gravity Gs", report_number(options.specific_gravity)},
                   {"dry mass (g)", report_number(options.dry_mass_g, 6)},
                   {"suspension volume (mL)", report_number(options.volume_ml, 6)}};
  if (!options.lab.sheet.empty()) report.inputs.push_back({"sheet", options.lab.sheet});
  if (sieve) {
    report.inputs.push_back({"sieve analysis", options.lab.sieve});
    report.inputs.push_back({"total dry mass (g)", report_number(sieve->total_g, 6)});
    report.inputs.push_back(
        {"separating sieve (mm)", report_number(options.lab.separating_sieve_mm)});
    report.inputs.push_back(
        {"passing the separating sieve (%)", report_number(sieve->passing_separating)});
    report.warnings = sieve->warnings;
  }
  report.tables.push_back(readings_table(readings, points, lab_method_name(method)));
  if (sieve) {
    report.tables.push_back(sieve_report_table(*sieve));
    report.tables.push_back(whole_curve_report_table(curve));
  }
  const fs::path base = figure_base(options.report);
  report.figure_stem = base.filename().string();
  if (!options.out.empty()) {
    std::error_code ec;
    const fs::path out = fs::relative(fs::absolute(options.out, ec),
                                      fs::absolute(options.report, ec).parent_path(), ec);
    if (!ec && !out.empty()) report.files.push_back(out.generic_string());
  }
  try {
    render::write_lab_curve_figure("Grading curve: " + standard, curve, base);
    write_lab_report(report, options.report);
  } catch (const WriteError& e) {
    std::fprintf(stderr, "sedem: %s\n", e.what());
    return exit_code::io_failure;
  }
  return exit_code::ok;
}

}  // namespace

int reduce(const ReduceOptions& options) {
  try {
    return run_reduce(options);
  } catch (const std::invalid_argument& e) {  // parse_lab_method
    std::fprintf(stderr, "sedem: %s\n", e.what());
    return exit_code::invalid_scene;
  }
}

}  // namespace sedem::app
