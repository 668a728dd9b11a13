#include "app/invert_command.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>

#include <nlohmann/json.hpp>

#include "app/exit_codes.h"
#include "app/invert_lab_report.h"
#include "app/lab_file.h"
#include "app/lab_sieve_input.h"
#include "app/progress.h"
#include "app/run_record.h"
#include "core/instruments/hydrometer.h"
#include "core/invert/invert_input.h"
#include "core/lab/hydrometer_reduction.h"
#include "core/lab/lab_csv.h"
#include "core/lab/water.h"
#include "core/lab/whole_curve.h"
#include "core/model/shortened.h"
#include "core/run/stage_setups.h"
#include "core/sample/sample_builder.h"
#include "core/scene/scene_loader.h"
#include "render/atomic_write.h"
#include "render/invert_figure.h"
#include "render/lab_curve_figure.h"

namespace sedem::app {

namespace {

namespace fs = std::filesystem;
using invert::Test;

// Thrown for a flag out of its range: exit 2 like an invalid reading.
struct InvalidSetup : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

std::string number(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.9g", v);
  return b;
}

void check_range(const char* flag, double value, double lo, double hi) {
  if (!(value >= lo && value <= hi))
    throw InvalidSetup(std::string(flag) + " = " + number(value) + " is out of range; allowed " +
                       number(lo) + " to " + number(hi));
}

// The flags' own ranges, checked before anything is read: a NaN or an absurd value is named
// by its flag, not by what it would break further on.
void check_flags(const InvertOptions& o) {
  // core/lab/water's formulas hold from 0 to 40 C.
  if (o.temperature_c) check_range("--temperature-c", *o.temperature_c, 0.0, 40.0);
  if (o.area_cm2) check_range("--area-cm2", *o.area_cm2, 1.0, 1000.0);
  if (o.volume_ml) check_range("--volume-ml", *o.volume_ml, 10.0, 10000.0);
  if (o.specific_gravity) check_range("--gs", *o.specific_gravity, 1.01, 10.0);
  if (o.dry_mass_g) check_range("--mass-g", *o.dry_mass_g, 1.0, 500.0);
  if (o.depth_cm) check_range("--depth-cm", *o.depth_cm, 2.0, 200.0);
  if (o.liquid_density) check_range("--liquid-density", *o.liquid_density, 950.0, 1100.0);
  if (o.blank_g) check_range("--blank-g", *o.blank_g, -1000.0, 1000.0);
  if (o.pipette_ml) check_range("--pipette-ml", *o.pipette_ml, 1.0, 100.0);
  if (o.blank_g && o.test != "buoyancy")
    throw InvalidSetup(
        "--blank-g is the sphere's apparent mass in the clear liquid: for --test "
        "buoyancy (use --liquid-density for the others)");
}

// The command's outputs in `dir`.
const std::vector<std::string> kOutputs = {
    "inverted_curve.csv", "readings_fit.csv", "invert.json",       "invert.png",       "invert.csv",
    "report.html",        "whole_curve.csv",  "grading_curve.png", "grading_curve.csv"};

// Where reading i stands in its file ("line 6: "), for a message that counts readings (rows):
// a note or a blank line moves the one from the other. Empty where the lines are not known.
std::string line_of(const std::vector<std::size_t>& lines, const std::string& place,
                    std::size_t i) {
  return i < lines.size() ? place + " " + std::to_string(lines[i]) + ": " : "";
}

// A standard reduction's diameter that is no number or coarser than any grain a sedimentation
// test sorts comes from a time that cannot be right: refused, naming the row (and its line).
void check_diameters(const std::vector<invert::Measurement>& data,
                     const std::vector<GradingPoint>& standard,
                     const std::vector<std::size_t>& lines, const std::string& place) {
  for (std::size_t i = 0; i < standard.size() && i < data.size(); ++i)
    if (!(standard[i].diameter > 0 && standard[i].diameter <= kMaxLabDiameter))
      throw InvalidSetup(line_of(lines, place, i) + "row " + std::to_string(i + 1) +
                         ", time_min = " + number(data[i].time / 60.0) +
                         ": the reduction gives a diameter of " + number(standard[i].diameter) +
                         " m, outside (0, " + number(kMaxLabDiameter) + "] m: check the time");
}

// The set-up: the scene's, or a laboratory's 152H test (ASTM cylinder of 27.8 cm^2 filled to
// 1000 mL, water at the readings' mean temperature, Stokes drag) from the flags.
Scene make_setup(const InvertOptions& o, double temperature_c) {
  Scene s;
  if (!o.run.empty()) {
    const fs::path record_file = fs::path(o.run) / "run.json";
    std::ifstream in(record_file);
    const auto record = nlohmann::json::parse(in, nullptr, false);
    if (!in || record.is_discarded() || !record.contains("scene") || !record["scene"].is_object())
      throw SceneError(record_file.string() + ": not a sedem run record");
    if (const std::string incomplete = incomplete_run(record, o.run); !incomplete.empty()) {
      if (!o.partial) throw SceneError(incomplete);
      std::fprintf(stderr, "sedem: warning: partial: %s\n", incomplete.c_str());
    }
    s = scene_from_json(record["scene"], record_file.string());
  } else if (!o.scene.empty()) {
    s = load_scene(o.scene);
  } else {
    s.fluid.density = water::density(temperature_c);
    s.fluid.viscosity = water::viscosity(temperature_c);
    s.forces.drag = "stokes";
    const double area = o.area_cm2.value_or(27.8) * 1e-4;
    s.cylinder.diameter = std::sqrt(4.0 * area / std::numbers::pi);
    s.cylinder.height = o.volume_ml.value_or(1000.0) * 1e-6 / area;
    s.sample.particle_density = o.specific_gravity.value_or(2.65) * 1000.0;
    s.sample.total_mass = o.dry_mass_g.value_or(50.0) * 1e-3;
  }
  const bool from_scene = !o.scene.empty() || !o.run.empty();
  if (o.area_cm2 && from_scene)
    s.cylinder.diameter = std::sqrt(4.0 * *o.area_cm2 * 1e-4 / std::numbers::pi);
  if (o.volume_ml && from_scene)
    s.cylinder.height =
        *o.volume_ml * 1e-6 / (std::numbers::pi / 4.0 * s.cylinder.diameter * s.cylinder.diameter);
  if (o.specific_gravity && from_scene) s.sample.particle_density = *o.specific_gravity * 1e3;
  if (o.dry_mass_g && from_scene) s.sample.total_mass = *o.dry_mass_g * 1e-3;
  if (o.pipette_ml) s.instruments.pipette_volume = *o.pipette_ml * 1e-6;
  if (o.liquid_density) s.fluid.density = *o.liquid_density;
  if (o.blank_g) {
    // The sphere weighs m - rho_L V in the clear liquid: the liquid's density from its blank.
    const double r = 0.5 * s.instruments.sphere_diameter;
    const double volume = 4.0 / 3.0 * std::numbers::pi * r * r * r;
    s.fluid.density = (s.instruments.sphere_mass - *o.blank_g * 1e-3) / volume;
    check_range("the clear liquid's density from --blank-g (kg/m^3)", s.fluid.density, 950.0,
                1100.0);
  }
  if (o.depth_cm) {
    check_range("--depth-cm", *o.depth_cm, 2.0, 0.9 * s.cylinder.height * 100.0);
    s.instruments.buoyancy_depth_fraction = *o.depth_cm * 1e-2 / s.cylinder.height;
    s.instruments.pipette_depth_fraction = s.instruments.buoyancy_depth_fraction;
  }
  check_range("--gs", s.sample.particle_density / 1000.0, 1.01, 10.0);
  check_range("--mass-g", s.sample.total_mass * 1e3, 1.0, 500.0);
  check_range("cylinder height (m)", s.cylinder.height, 0.1, 2.0);
  return s;
}

int run_invert(const InvertOptions& o) {
  const Test test = invert::parse_test(o.test);
  if (o.readings.empty() == o.run.empty()) {
    std::fprintf(stderr, "sedem invert: give READINGS.csv or --run DIR (one of them)\n");
    return exit_code::usage;
  }
  check_flags(o);
  // The outputs are checked before the inversion, which can take a while.
  std::error_code ec;
  fs::create_directories(o.out, ec);
  if (ec || !fs::is_directory(o.out)) {
    std::fprintf(stderr, "sedem: cannot create the output folder %s: %s\n",
                 shortened(o.out).c_str(), ec ? ec.message().c_str() : "not a folder");
    return exit_code::output_unwritable;
  }
  const fs::path dir(o.out);
  for (const auto& name : kOutputs)
    if (const std::string why = unfit_output_file(dir / name); !why.empty()) {
      std::fprintf(stderr, "sedem: %s\n", shortened(why).c_str());
      return exit_code::output_unwritable;
    }
  const std::string source =
      o.run.empty() ? o.readings
                    : (fs::path(o.run) / ("readings_" + test_name(test) + ".csv")).string();
  // A laboratory's file in any form it keeps (CSV, ';', tabs, .xlsx); a run's own CSV.
  LabTable table;
  if (o.run.empty()) {
    table = read_lab_file(source, o.lab.sheet);
  } else {
    std::ifstream in(source);
    if (!in || fs::is_directory(source)) {
      std::fprintf(stderr, "sedem: %s: cannot open the readings file\n", shortened(source).c_str());
      return exit_code::invalid_scene;
    }
    table = read_lab_text(in);
  }
  // The sieve analysis is read before the inversion, which can take a while.
  std::optional<SieveInput> sieve;
  if (!o.lab.sieve.empty()) {
    try {
      sieve = read_sieve_input(o.lab.sieve, o.lab.sieve_sheet, o.lab.sieve_total_g,
                               o.lab.separating_sieve_mm);
    } catch (const std::invalid_argument& e) {
      std::fprintf(stderr, "sedem: %s: %s\n", shortened(o.lab.sieve).c_str(), e.what());
      return exit_code::invalid_scene;
    }
    for (const auto& w : sieve->warnings)
      std::fprintf(stderr, "sedem: warning: %s: %s\n", shortened(o.lab.sieve).c_str(), w.c_str());
  }
  // The readings in the laboratory's units and, for the 152H, its standard reduction
  // (`reduce`'s: D7928 or D422).
  std::vector<invert::Measurement> data;
  std::vector<GradingPoint> standard;
  const LabMethod method = parse_lab_method(o.method);
  const std::string standard_name = test == Test::hydrometer
                                        ? lab_method_name(method)
                                        : invert::reading_format(test).standard_name;
  Scene scene;
  std::vector<LabReading> lab;     // the 152H's readings as the laboratory took them
  std::vector<std::size_t> lines;  // the sphere's or pipette's readings' lines in their file
  // A run's true curve: its sample's size classes, as the run drew them from its scene.
  std::vector<SizeClass> truth;
  if (!o.run.empty()) {
    scene = make_setup(o, 20.0);
    const auto& format = invert::reading_format(test);
    std::vector<double> times, raw;
    for (const auto& row : lab_columns(table, {"time_s", format.run_column})) {
      times.push_back(row[0]);
      raw.push_back(format.run_to_lab * row[1]);
    }
    auto recorded =
        invert::record_simulated(test_setup(scene), test, times, raw, o.resolution, method);
    data = std::move(recorded.data);
    standard = std::move(recorded.standard);
    truth = plan_sample(sample_setup(scene)).classes;
  } else if (test == Test::hydrometer) {
    lab = read_lab_readings(table);
    double mean_t = 20;
    if (!lab.empty()) {
      mean_t = 0;
      for (const auto& r : lab) mean_t += r.temperature / double(lab.size());
    }
    scene = make_setup(o, mean_t);
    // The clear liquid as its blank reads it (R + C_m of the 152H in water and dispersant:
    // g/L of Gs = 2.65 soil in water at 20 C), unless its density is given: the model's bulb
    // then floats where the laboratory's did.
    double blank = 0;
    for (const auto& r : lab)
      blank += (r.composite_correction + r.meniscus_correction) / double(lab.size());
    const bool corrected = std::any_of(lab.begin(), lab.end(), [](const LabReading& r) {
      return r.composite_correction != 0 || r.meniscus_correction != 0;
    });
    if (corrected && !o.liquid_density) {
      const HydrometerDesign design;
      scene.fluid.density = design.calibration_water_density +
                            blank * (1.0 - 1.0 / design.calibration_specific_gravity);
    }
    for (const auto& p : reduce_lab_readings(lab, invert::lab_specimen(test_setup(scene)), method))
      standard.push_back({p.diameter, p.percent_finer});  // validates the readings
    // The concentration from R - C, the bulb's depth from R + C_m (ASTM: the composite
    // correction is the concentration's only).
    for (const auto& r : lab)
      data.push_back(
          {r.time, r.reading - r.composite_correction, r.reading + r.meniscus_correction});
  } else {
    data = invert::read_measurements(table, test, &lines);
    scene = make_setup(o, o.temperature_c.value_or(20.0));
    try {
      invert::validate_measurements(test_setup(scene), test, data, {});
    } catch (const invert::InvalidInversionInput& e) {
      // The message counts readings; the laboratory looks for a line of its file.
      if (e.row() >= lines.size()) throw;
      throw InvalidSetup(line_of(lines, table.place, e.row()) + e.what());
    }
    standard = invert::standard_reduction(test_setup(scene), test, data);
  }
  check_diameters(data, standard, lines, table.place);
  invert::InversionOptions options;
  options.resolution = o.resolution;
  options.refine = o.refine;
  options.bootstrap = o.replicas;
  options.coverage = o.coverage;
  options.seed = o.seed;
  // A long inversion (many readings, a fine grid) says how far it is, as a run does.
  StageProgress progress("invert", o.quiet);
  options.progress = [&](const char* stage, double fraction) { progress.update(stage, fraction); };
  const auto curve = invert::invert_readings(test_setup(scene), test, data, options);
  progress.done();

  // Every output through a temporary file, its write and close checked (a full disk: exit 4,
  // no half file); a partial run's say so.
  const std::string partial_note =
      o.partial ? "partial: from a run that did not complete; its readings stop where it did" : "";
  write_atomically(dir / "inverted_curve.csv", [&](std::ostream& csv) {
    if (o.partial) csv << "# " << partial_note << '\n';
    // The diameter in µm too, as laboratories write it.
    csv << "diameter_m,percent_finer,percent_finer_low,percent_finer_high,readings_allow_low,"
           "readings_allow_high,diameter_um,readings_tell\n";
    for (std::size_t k = 0; k < curve.diameter.size(); ++k)
      csv << number(curve.diameter[k]) << ',' << number(curve.percent_finer[k]) << ','
          << (curve.lower.empty() ? "" : number(curve.lower[k])) << ','
          << (curve.upper.empty() ? "" : number(curve.upper[k])) << ','
          << (curve.bound_lower.empty() ? "" : number(curve.bound_lower_at(curve.diameter[k])))
          << ','
          << (curve.bound_upper.empty() ? "" : number(curve.bound_upper_at(curve.diameter[k])))
          << ',' << number(curve.diameter[k] * 1e6) << ','
          << (curve.open_at(curve.diameter[k]) ? "0" : "1") << '\n';
  });
  const std::string unit = test == Test::hydrometer ? "g_per_l" : "g";
  write_atomically(dir / "readings_fit.csv", [&](std::ostream& csv) {
    if (o.partial) csv << "# " << partial_note << '\n';
    csv << "time_s,measured_" << unit << ",fitted_" << unit << ",pinned_diameter_m,"
        << "inverted_percent_finer,standard_diameter_m,standard_percent_finer,"
        << "time_min,pinned_diameter_um,standard_diameter_um"  // the lab's units beside SI
        << (truth.empty() ? "" : ",true_percent_finer") << '\n';
    for (std::size_t i = 0; i < data.size(); ++i) {
      csv << number(data[i].time) << ',' << number(curve.measured[i]) << ','
          << number(curve.fitted[i]) << ',' << number(curve.reading_diameter[i]) << ','
          << number(curve.at(curve.reading_diameter[i])) << ',' << number(standard[i].diameter)
          << ',' << number(standard[i].percent_finer) << ',' << number(data[i].time / 60.0) << ','
          << number(curve.reading_diameter[i] * 1e6) << ',' << number(standard[i].diameter * 1e6);
      if (!truth.empty()) csv << ',' << number(true_percent_finer(truth, standard[i].diameter));
      csv << '\n';
    }
  });
  const auto open = curve.widest_open();
  // Against the run's true curve: the largest errors at the standard reduction's diameters.
  double inverted_error = 0, standard_error = 0;
  for (const auto& p : truth.empty() ? std::vector<GradingPoint>{} : standard) {
    const double t = true_percent_finer(truth, p.diameter);
    inverted_error = std::max(inverted_error, std::abs(curve.at(p.diameter) - t));
    standard_error = std::max(standard_error, std::abs(p.percent_finer - t));
  }
  {
    nlohmann::json j;
    j["test"] = o.test;
    if (o.partial) {
      j["partial"] = true;
      j["partial_note"] = partial_note;
    }
    j["readings"] = source;
    j["scene"] = o.scene;
    j["resolution"] = o.resolution > 0 ? o.resolution : invert::default_resolution(test);
    j["resolution_unit"] = invert::reading_unit(test);
    j["sigma"] = curve.sigma;
    j["lambda"] = curve.lambda;
    j["chi2"] = curve.chi2;
    j["chi2_target"] = curve.chi2_target;
    j["chi2_floor"] = curve.chi2_floor;
    j["gauss_newton_iterations"] = curve.iterations;
    j["band_coverage"] = curve.coverage;
    j["band_replicas"] = curve.replicas;
    j["band_prior_scale"] = curve.prior_scale;
    j["resolved_diameter_m"] = {curve.resolved_min, curve.resolved_max};
    j["standard_reduction"] = standard_name;
    if (!curve.bound_lower.empty())
      j["readings_allow"] = {{"widest_pp", open.width},
                             {"at_diameter_m", open.diameter},
                             {"tolerance", curve.bound_tolerance}};
    {
      nlohmann::json ranges = nlohmann::json::array();
      for (const auto& [from, to] : curve.open_ranges()) ranges.push_back({from, to});
      j["readings_cannot_tell"] = {{"rise_between_readings_over_pp", curve.open_rise},
                                   {"diameter_ranges_m", ranges}};
    }
    if (!truth.empty())
      j["true_curve_error_pp"] = {{"inverted", inverted_error}, {"standard", standard_error}};
    write_atomically(dir / "invert.json", [&](std::ostream& f) { f << j.dump(2) << '\n'; });
  }
  render::InvertFigureInput fig;
  fig.title = "Inverted grading curve (" + o.test + ") and " + standard_name +
              (curve.bound_lower.empty() ? "" : "; grey: what the readings allow") +
              (o.partial ? " (partial)" : "");
  fig.csv_note = partial_note;
  fig.diameter_m = curve.diameter;
  fig.percent_finer = curve.percent_finer;
  fig.lower = curve.lower;
  fig.upper = curve.upper;
  fig.band_name = std::to_string(int(std::lround(100 * curve.coverage))) + " % band";
  fig.bound_diameter_m = curve.bound_diameter;
  fig.bound_lower = curve.bound_lower;
  fig.bound_upper = curve.bound_upper;
  for (std::size_t k = 0; k < curve.diameter.size(); ++k)
    if (curve.open_at(curve.diameter[k])) {
      fig.open_diameter_m.push_back(curve.diameter[k]);
      fig.open_percent_finer.push_back(curve.percent_finer[k]);
    }
  fig.standard_name = standard_name;
  for (const auto& p : standard) {
    fig.standard_diameter_m.push_back(p.diameter);
    fig.standard_percent_finer.push_back(p.percent_finer);
  }
  for (const auto& p : true_grading_curve(truth)) {
    fig.true_diameter_m.push_back(p.diameter);
    fig.true_percent_finer.push_back(p.percent_finer);
  }
  render::write_invert_figure(fig, dir / "invert");

  // The whole curve: the sieves, the standard reduction and the inverted curve (within the
  // diameters the readings resolve) scaled by the percent passing the separating sieve.
  std::vector<CurvePoint> whole;
  if (sieve) {
    std::vector<SedimentationPoint> standard_points, inverted_points;
    for (std::size_t i = 0; i < standard.size(); ++i)
      standard_points.push_back({standard[i].diameter, standard[i].percent_finer, data[i].time});
    for (std::size_t k = 0; k < curve.diameter.size(); ++k)
      if (curve.diameter[k] >= curve.resolved_min * (1 - 1e-9) &&
          curve.diameter[k] <= curve.resolved_max * (1 + 1e-9))
        inverted_points.push_back({curve.diameter[k], curve.percent_finer[k], NAN});
    whole = whole_curve(sieve->points, o.lab.separating_sieve_mm, test_name(test), standard_points);
    add_to_whole_curve(whole, sieve->passing_separating, "inverted", inverted_points);
    if (const std::string conflict = whole_curve_conflict(whole); !conflict.empty()) {
      std::fprintf(stderr, "sedem: warning: %s\n", conflict.c_str());
      sieve->warnings.push_back(conflict);
    }
    write_atomically(dir / "whole_curve.csv",
                     [&](std::ostream& csv) { write_whole_curve_csv(csv, whole, partial_note); });
    render::write_lab_curve_figure("Whole grading curve: sieves (ASTM D6913), " + standard_name +
                                       " and the inversion" + (o.partial ? " (partial)" : ""),
                                   whole, dir / "grading_curve");
  }
  write_invert_lab_report(
      {o, test, standard_name, data, lab, standard, curve, sieve ? &*sieve : nullptr, whole},
      dir / "report.html");

  if (!o.quiet) {
    std::printf("%-8s %-12s %-10s %-10s %-10s %-12s %-10s\n", "time_min", "measured", "fitted",
                "d_um", "inverted_%", "standard_um", "standard_%");
    for (std::size_t i = 0; i < data.size(); ++i)
      std::printf("%-8.2f %-12.5g %-10.5g %-10.3f %-10.2f %-12.3f %-10.2f\n", data[i].time / 60,
                  curve.measured[i], curve.fitted[i], curve.reading_diameter[i] * 1e6,
                  curve.at(curve.reading_diameter[i]), standard[i].diameter * 1e6,
                  standard[i].percent_finer);
    std::printf("lambda %.3g, chi2 %.2f (target %.2f, floor %.2f), %d replicas; wrote %s\n",
                curve.lambda, curve.chi2, curve.chi2_target, curve.chi2_floor, curve.replicas,
                o.out.c_str());
    if (open.width > 0)
      std::printf(
          "the readings allow %.1f to %.1f %% finer at %.1f um (their widest, within the range "
          "they resolve): there the curve is the smoothing's choice\n",
          curve.bound_lower_at(open.diameter), curve.bound_upper_at(open.diameter),
          open.diameter * 1e6);
    for (const auto& [from, to] : curve.open_ranges()) {
      std::printf(
          "the readings cannot tell the curve from %.3g to %.3g um: it rises by more than "
          "%.0f pp between two readings there, and they do not say where",
          from * 1e6, to * 1e6, curve.open_rise);
      if (curve.bound_lower.empty())
        std::printf("\n");
      else
        std::printf(
            " (they allow %.1f to %.1f %% at %.3g um, %.1f to %.1f %% at %.3g um); the band "
            "there is what they allow\n",
            curve.bound_lower_at(from), curve.bound_upper_at(from), from * 1e6,
            curve.bound_lower_at(to), curve.bound_upper_at(to), to * 1e6);
    }
    if (!truth.empty())
      std::printf(
          "against the run's true curve: inverted %.2f pp, %s %.2f pp (largest, at the "
          "standard reduction's diameters)\n",
          inverted_error, standard_name.c_str(), standard_error);
  }
  return exit_code::ok;
}

}  // namespace

int invert(const InvertOptions& options) {
  try {
    return run_invert(options);
  } catch (const WriteError& e) {
    std::fprintf(stderr, "sedem: %s\n", e.what());
    return exit_code::io_failure;
  } catch (const SceneError& e) {
    std::fprintf(stderr, "sedem: %s\n", e.what());
    return exit_code::invalid_scene;
  } catch (const std::invalid_argument& e) {  // LabCsvError, InvalidLabReading, InvalidSetup,
                                              // InvalidInversionInput
    std::fprintf(stderr, "sedem: %s: %s\n",
                 shortened(options.run.empty() ? options.readings : options.run).c_str(), e.what());
    return exit_code::invalid_scene;
  } catch (const std::runtime_error& e) {  // the forward model: hydrometer off the column
    std::fprintf(stderr, "sedem: %s: the forward model failed: %s\n",
                 shortened(options.run.empty() ? options.readings : options.run).c_str(), e.what());
    return exit_code::invalid_scene;
  }
}

}  // namespace sedem::app
