#include "bench/validation/run_folder.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

#include "bench/validation/curve_checks.h"

namespace sedem::validation {
namespace fs = std::filesystem;

namespace {

// One CSV line into fields; a field may be double-quoted with "" for a quote.
std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else if (c != '\r') {
      fields.back() += c;
    }
  }
  return fields;
}

double to_number(const std::string& text, const std::string& where) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size())
    throw std::runtime_error(where + ": \"" + text + "\" is not a number");
  return v;
}

std::map<std::string, RunTest> tests_in_order(const CsvTable& csv,
                                              std::vector<std::string>& order) {
  std::map<std::string, RunTest> tests;
  const std::size_t test = csv.column("test"), source = csv.column("source"),
                    time = csv.column("time_s"), diameter = csv.column("diameter_m"),
                    finer = csv.column("percent_finer");
  for (const auto& row : csv.rows) {
    const std::string& name = row.at(test);
    if (name == "true") continue;
    if (!tests.count(name)) {
      order.push_back(name);
      tests[name].test = name;
      tests[name].dem.test = tests[name].reference.test = name;
    }
    RunTest& t = tests[name];
    const std::string& s = row.at(source);
    // A test that read nothing has empty error and bias cells: no number, not 0.
    const bool figure = s == "error_pp" || s == "bias_pp";
    const double w = figure && row.at(finer).empty() ? std::numeric_limits<double>::quiet_NaN()
                                                     : to_number(row.at(finer), csv.source);
    if (s == "error_pp") {
      t.error_pp = w;
    } else if (s == "bias_pp") {
      t.bias_pp = w;
    } else {
      Reading r{
          to_number(row.at(time), csv.source), to_number(row.at(diameter), csv.source), w, {}};
      (s == "dem" ? t.dem : t.reference).rows.push_back(r);
    }
  }
  return tests;
}

// The depth a test measured at, from its own readings' columns.
double measured_depth(const fs::path& dir, const std::string& test) {
  const fs::path file = dir / ("readings_" + test + ".csv");
  if (!fs::exists(file)) return 0;
  const CsvTable csv = read_csv(file);
  const std::string name = test == "hydrometer" ? "centre_depth_m" : "depth_m";
  const auto it = std::find(csv.header.begin(), csv.header.end(), name);
  if (it == csv.header.end() || csv.rows.empty()) return 0;
  const std::size_t k = std::size_t(it - csv.header.begin());
  double sum = 0;
  for (const auto& row : csv.rows) sum += to_number(row.at(k), csv.source);
  return sum / double(csv.rows.size());
}

// A "key=value" with the value as JSON (a bare word is taken as a string).
std::pair<std::string, nlohmann::json> parse_set(const std::string& set) {
  const auto eq = set.find('=');
  if (eq == std::string::npos || eq == 0) throw std::invalid_argument(set + ": expected key=value");
  const std::string value = set.substr(eq + 1);
  nlohmann::json j = nlohmann::json::parse(value, nullptr, false);
  if (j.is_discarded()) j = value;
  return {set.substr(0, eq), j};
}

}  // namespace

const RunTest* RunFolder::test(const std::string& wanted) const {
  for (const auto& t : tests)
    if (t.test == wanted) return &t;
  return nullptr;
}

double RunFolder::number(const std::string& key, double fallback) const {
  const auto it = scene.find(key);
  return it != scene.end() && it->is_number() ? it->get<double>() : fallback;
}

std::string RunFolder::text(const std::string& key, const std::string& fallback) const {
  const auto it = scene.find(key);
  return it != scene.end() && it->is_string() ? it->get<std::string>() : fallback;
}

std::size_t CsvTable::column(const std::string& name) const {
  const auto it = std::find(header.begin(), header.end(), name);
  if (it == header.end()) throw std::runtime_error(source + ": no column " + name);
  return std::size_t(it - header.begin());
}

CsvTable read_csv(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot read it");
  CsvTable t;
  t.source = file.string();
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(t.source + ": empty");
  t.header = split_csv_line(line);
  while (std::getline(in, line)) {
    if (line.empty() || line == "\r") continue;
    auto row = split_csv_line(line);
    row.resize(std::max(row.size(), t.header.size()));
    t.rows.push_back(std::move(row));
  }
  return t;
}

void parse_granulometry(const CsvTable& csv, RunFolder& run) {
  const std::size_t test = csv.column("test"), diameter = csv.column("diameter_m"),
                    finer = csv.column("percent_finer");
  run.true_curve.clear();
  for (const auto& row : csv.rows)
    if (row.at(test) == "true")
      run.true_curve.push_back(
          {to_number(row.at(diameter), csv.source), to_number(row.at(finer), csv.source)});
  run.classes = classes_from_true_curve(run.true_curve);
  std::vector<std::string> order;
  auto tests = tests_in_order(csv, order);
  run.tests.clear();
  for (const auto& name : order) run.tests.push_back(tests[name]);
}

std::vector<RunProfile> parse_fig12(const CsvTable& csv, const std::string& sample) {
  std::vector<RunProfile> profiles;
  const std::string depth_suffix = "/" + sample + ":depth_m";
  for (std::size_t k = 0; k < csv.header.size(); ++k) {
    const std::string& h = csv.header[k];
    if (h.size() <= depth_suffix.size() ||
        h.compare(h.size() - depth_suffix.size(), depth_suffix.size(), depth_suffix) != 0)
      continue;
    const std::string panel = h.substr(0, h.size() - depth_suffix.size());  // "t = 60 s"
    const std::size_t d = csv.column(panel + "/" + sample + ":diameter_um");
    RunProfile p;
    std::istringstream title(panel);
    std::string t_word, eq;
    title >> t_word >> eq >> p.time_s;
    for (const auto& row : csv.rows) {
      if (row.at(k).empty() || row.at(d).empty()) continue;
      p.depth_m.push_back(to_number(row.at(k), csv.source));
      p.largest_diameter_m.push_back(1e-6 * to_number(row.at(d), csv.source));
    }
    profiles.push_back(std::move(p));
  }
  return profiles;
}

RunFolder read_run_folder(const fs::path& dir) {
  RunFolder run;
  run.dir = dir;
  const fs::path record = dir / "run.json";
  std::ifstream in(record);
  if (!in) throw std::runtime_error(record.string() + ": cannot read it (not a sedem run folder?)");
  const auto j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.contains("scene"))
    throw std::runtime_error(record.string() + ": not a sedem run record");
  run.scene = j["scene"];
  run.name = run.text("name", dir.filename().string());
  run.status = j.value("status", "");
  run.particle_count = j.value("particle_count", std::size_t(0));
  run.steps = j.value("steps", 0.0);
  run.simulated_time_s = j.value("simulated_time_s", 0.0);
  run.wall_time_s = j.value("wall_time_s", 0.0);
  run.particle_steps_per_s = j.value("particle_steps_per_s", 0.0);
  parse_granulometry(read_csv(dir / "granulometry.csv"), run);
  for (auto& t : run.tests) t.depth_m = measured_depth(dir, t.test);
  const fs::path fig12 = dir / "figures" / "fig12_largest_diameter.csv";
  if (fs::exists(fig12)) run.profiles = parse_fig12(read_csv(fig12), run.name);
  return run;
}

std::vector<RunFolder> read_run_folders(const std::vector<fs::path>& dirs) {
  std::vector<RunFolder> runs;
  for (const auto& d : dirs) {
    try {
      runs.push_back(read_run_folder(d));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "sedem_validation_report: left out: %s\n", e.what());
    }
  }
  return runs;
}

void make_variant(const fs::path& run_dir, const fs::path& variant_dir,
                  const std::vector<std::string>& sets) {
  std::ifstream in(run_dir / "run.json");
  if (!in) throw std::runtime_error((run_dir / "run.json").string() + ": cannot read it");
  auto j = nlohmann::json::parse(in);
  for (const auto& set : sets) {
    const auto [key, value] = parse_set(set);
    if (!j["scene"].contains(key))
      throw std::invalid_argument(set + ": the run's scene has no key " + key);
    j["scene"][key] = value;
  }
  fs::create_directories(variant_dir);
  for (const char* name : {"particles.pvd", "particles"}) {
    const fs::path link = variant_dir / name;
    if (fs::exists(fs::symlink_status(link))) fs::remove(link);
    fs::create_symlink(fs::absolute(run_dir / name), link);
  }
  std::ofstream out(variant_dir / "run.json");
  out << j.dump(2) << '\n';
  if (!out) throw std::runtime_error((variant_dir / "run.json").string() + ": cannot write it");
}

}  // namespace sedem::validation
