#include "app/batch_summary.h"

#include <cmath>
#include <fstream>

#include "render/atomic_write.h"

namespace sedem::app {
namespace fs = std::filesystem;

namespace {

const std::vector<std::string> kFigures{"error_pp", "bias_pp"};

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + '"';
}

// Not a number (a result the run does not have) is an empty cell.
std::string number(double x) {
  if (std::isnan(x)) return "";
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

// Without rounding: summary_stats.csv's figures are compared with those recomputed from it.
std::string exact(double x) {
  if (std::isnan(x)) return "";
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

// The columns that name a row: `names`, then the swept key when there is one.
std::string naming_columns(const std::string& names, const std::string& sweep_key) {
  return sweep_key.empty() ? names : names + ',' + csv_field(sweep_key);
}

std::string seed_text(const BatchRun& r) {
  return r.seed ? std::to_string(*r.seed) : "";
}

// A figure with its half-width for the terminal: "1.23 ± 0.45", "1.23" (one run), "-".
std::string with_half_width(const Interval& i) {
  char text[48];
  if (i.n == 0) return "-";
  if (i.n == 1)
    std::snprintf(text, sizeof text, "%.2f", i.mean);
  else
    std::snprintf(text, sizeof text, "%.2f \u00b1 %.2f", i.mean, i.half_width());
  return text;
}

void add_figures(SeedGroup& group, const fs::path& out_dir) {
  std::vector<nlohmann::json> complete;
  for (const auto& r : group.runs) {
    auto record = read_run_record(out_dir / r.folder);
    if (record.is_null() || record.value("status", "") != "complete") continue;
    complete.push_back(std::move(record));
    group.complete.push_back(r.folder);
  }
  for (const auto& test : batch_tests())
    for (const auto& figure : kFigures) {
      std::vector<double> values;
      for (const auto& record : complete) values.push_back(run_figure(record, test, figure));
      group.figures.emplace_back(test + "_" + figure, mean_interval(values));
    }
}

}  // namespace

const std::vector<std::string>& batch_tests() {
  static const std::vector<std::string> tests{"hydrometer", "buoyancy", "pipette"};
  return tests;
}

nlohmann::json read_run_record(const fs::path& dir) {
  std::ifstream in(dir / "run.json");
  if (!in) return nullptr;
  auto j = nlohmann::json::parse(in, nullptr, false);
  return j.is_discarded() ? nullptr : j;
}

double run_figure(const nlohmann::json& record, const std::string& test,
                  const std::string& figure) {
  if (!record.is_object() || !record.contains("results")) return NAN;
  const auto& results = record["results"];
  if (!results.is_object() || !results.contains(test) || !results[test].is_object()) return NAN;
  // A test that took no reading reports 0: nothing to average.
  if (results[test].value("readings", nlohmann::json(1)) == 0) return NAN;
  const auto& value = results[test].value(figure, nlohmann::json());
  return value.is_number() ? value.get<double>() : NAN;
}

void write_summary_csv(const std::vector<BatchRun>& runs, const std::string& sweep_key,
                       const fs::path& out_dir) {
  write_atomically(out_dir / "summary.csv", [&](std::ostream& out) {
    out << naming_columns("run,scene", sweep_key) << ",seed";
    for (const auto& t : batch_tests()) out << ',' << t << "_error_pp," << t << "_bias_pp";
    out << ",wall_time_s,particle_count,status\n";
    for (const auto& r : runs) {
      const auto record = read_run_record(out_dir / r.folder);
      out << csv_field(r.folder) << ',' << csv_field(r.scene);
      if (!sweep_key.empty()) out << ',' << csv_field(r.value);
      out << ',' << seed_text(r);
      for (const auto& t : batch_tests())
        for (const auto& figure : kFigures) out << ',' << number(run_figure(record, t, figure));
      if (record.is_null())
        out << ",,,missing\n";
      else
        out << ',' << number(record.value("wall_time_s", 0.0)) << ','
            << record.value("particle_count", 0) << ',' << record.value("status", "") << '\n';
    }
  });
}

std::vector<SeedGroup> seed_groups(const std::vector<BatchRun>& runs, const fs::path& out_dir) {
  std::vector<SeedGroup> groups;
  for (const auto& r : runs) {
    if (groups.empty() || groups.back().label != r.group) {
      groups.emplace_back();
      groups.back().scene = r.scene;
      groups.back().label = r.group;
      groups.back().value = r.value;
    }
    groups.back().runs.push_back(r);
  }
  for (auto& g : groups) add_figures(g, out_dir);
  return groups;
}

void write_summary_stats_csv(const std::vector<SeedGroup>& groups, const std::string& sweep_key,
                             const fs::path& out_dir) {
  write_atomically(out_dir / "summary_stats.csv", [&](std::ostream& out) {
    out << naming_columns("scene", sweep_key) << ",runs";
    for (const auto& t : batch_tests())
      for (const auto& figure : kFigures)
        for (const char* stat : {"mean", "sd", "ci95_low", "ci95_high"})
          out << ',' << t << '_' << figure << '_' << stat;
    out << '\n';
    for (const auto& g : groups) {
      out << csv_field(g.scene);
      if (!sweep_key.empty()) out << ',' << csv_field(g.value);
      out << ',' << g.complete.size();
      for (const auto& [name, i] : g.figures)
        out << ',' << exact(i.mean) << ',' << exact(i.sd) << ',' << exact(i.low) << ','
            << exact(i.high);
      out << '\n';
    }
  });
}

void print_summary_stats(const std::vector<SeedGroup>& groups, std::FILE* out) {
  for (const auto& g : groups) {
    std::fprintf(out, "  %s: %zu of %zu runs complete\n", g.label.c_str(), g.complete.size(),
                 g.runs.size());
    std::fprintf(out, "    %-12s %16s %16s\n", "test", "error (pp)", "bias (pp)");
    for (std::size_t k = 0; k < batch_tests().size(); ++k) {
      const Interval& error = g.figures[2 * k].second;
      const Interval& bias = g.figures[2 * k + 1].second;
      if (error.n == 0 && bias.n == 0) continue;
      // "±" is two bytes in one column: one byte more keeps the columns aligned.
      std::fprintf(out, "    %-12s %*s %*s\n", batch_tests()[k].c_str(), error.n > 1 ? 17 : 16,
                   with_half_width(error).c_str(), bias.n > 1 ? 17 : 16,
                   with_half_width(bias).c_str());
    }
  }
}

}  // namespace sedem::app
