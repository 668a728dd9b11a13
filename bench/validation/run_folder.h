#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/instruments/granulometry.h"
#include "core/model/sample.h"

namespace sedem::validation {

// A test of one run: its DEM curve, the reference curve at the same times, and the depth it
// measured at (the buoyancy sphere's and pipette's fixed depth; the hydrometer bulb's centre,
// averaged over its readings).
struct RunTest {
  std::string test;
  TestReadings dem, reference;
  double error_pp = 0;  // DEM against reference, as the run reported it
  double bias_pp = 0;   // reference against the true curve
  double depth_m = 0;
};

// Fig. 12: the largest diameter above each depth at one time.
struct RunProfile {
  double time_s = 0;
  std::vector<double> depth_m, largest_diameter_m;
};

// What `sedem run` left in a folder, as the validation report needs it.
struct RunFolder {
  std::filesystem::path dir;
  std::string name;  // the scene's
  std::string status;
  nlohmann::json scene;  // every key, in the units of the scene file
  std::size_t particle_count = 0;
  double steps = 0;
  double simulated_time_s = 0;
  double wall_time_s = 0;
  double particle_steps_per_s = 0;
  std::vector<GradingPoint> true_curve;
  std::vector<SizeClass> classes;  // rebuilt from the true curve
  std::vector<RunTest> tests;
  std::vector<RunProfile> profiles;  // empty when the run drew no Fig. 12

  const RunTest* test(const std::string& name) const;
  // A scene key as a number or a string; `fallback` when the run did not record it.
  double number(const std::string& key, double fallback = 0) const;
  std::string text(const std::string& key, const std::string& fallback = "") const;
};

// Reads run.json, granulometry.csv, readings_<test>.csv and, when present,
// figures/fig12_largest_diameter.csv. Throws std::runtime_error naming the file.
RunFolder read_run_folder(const std::filesystem::path& dir);
// The folders that can be read; one that cannot is named on stderr and left out, so that one
// failed run of many does not lose the report.
std::vector<RunFolder> read_run_folders(const std::vector<std::filesystem::path>& dirs);

// A CSV with a header row, as columns of text (cells may be empty).
struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  // The column's index; throws naming the file and the column when it is missing.
  std::size_t column(const std::string& name) const;
  std::string source;
};
CsvTable read_csv(const std::filesystem::path& file);

// granulometry.csv -> the true curve and, per test, DEM and reference readings (in the order
// of the file) and the error and bias rows.
void parse_granulometry(const CsvTable& csv, RunFolder& run);
// figures/fig12_largest_diameter.csv (columns "t = <T> s/<sample>:depth_m" and
// ":diameter_um") -> one profile per time.
std::vector<RunProfile> parse_fig12(const CsvTable& csv, const std::string& sample);

// A copy of a run's folder for another instrument set-up: run.json with `sets` ("key=value",
// value as JSON) applied to its scene, and links to its particle files, so that
// `sedem render` takes the readings again from the same particles.
void make_variant(const std::filesystem::path& run_dir, const std::filesystem::path& variant_dir,
                  const std::vector<std::string>& sets);

}  // namespace sedem::validation
