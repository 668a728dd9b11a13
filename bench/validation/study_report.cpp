#include "bench/validation/study_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>

#include "bench/validation/markdown.h"

namespace sedem::validation {
namespace fs = std::filesystem;

namespace {

std::string pp(double v) {
  return std::isnan(v) ? "-" : fixed(v, 2);
}

// "1.20 [0.40, 2.00]"; the mean alone from one seed, "-" from none.
std::string with_interval(const Interval& i, int decimals = 2) {
  if (i.n == 0) return "-";
  if (i.n < 2) return fixed(i.mean, decimals);
  return fixed(i.mean, decimals) + " [" + fixed(i.low, decimals) + ", " + fixed(i.high, decimals) +
         "]";
}

// A number for the CSV files: empty for NaN, full precision otherwise.
std::string cell(double v) {
  if (std::isnan(v)) return "";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", v);
  return buffer;
}

std::string quoted(const std::string& s) {
  std::string q = "\"";
  for (const char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::ofstream open_for_writing(const fs::path& file) {
  std::ofstream out(file);
  if (!out) throw std::runtime_error(file.string() + ": cannot write it");
  return out;
}

std::string regime_note(const std::vector<SeedRuns>& seeds) {
  std::size_t samples = 0, lowest = 0, highest = 0;
  double simulated = 0;
  for (const auto& s : seeds) {
    samples = std::max(samples, s.runs.size());
    for (const auto& r : s.runs) {
      lowest = lowest == 0 ? r.particle_count : std::min(lowest, r.particle_count);
      highest = std::max(highest, r.particle_count);
      simulated = std::max(simulated, r.simulated_time_s);
    }
  }
  const std::string particles = lowest == highest
                                    ? std::to_string(lowest)
                                    : std::to_string(lowest) + "-" + std::to_string(highest);
  return std::to_string(seeds.size()) + " seeds of " + std::to_string(samples) + " samples, " +
         particles + " particles, " + fixed(simulated, 0) + " s simulated";
}

}  // namespace

std::vector<RunFolder> read_batch(const fs::path& batch_dir) {
  if (!fs::is_directory(batch_dir)) throw std::runtime_error(batch_dir.string() + ": not a folder");
  std::vector<fs::path> dirs;
  for (const auto& entry : fs::directory_iterator(batch_dir))
    if (entry.is_directory() && fs::exists(entry.path() / "run.json")) dirs.push_back(entry.path());
  std::sort(dirs.begin(), dirs.end());
  return read_run_folders(dirs);
}

std::vector<SeedRuns> group_by_seed(const std::vector<RunFolder>& runs,
                                    const std::vector<RunFolder>& shallow,
                                    const std::vector<RunFolder>& deep) {
  std::map<double, SeedRuns> seeds;
  for (const auto& r : runs) seeds[r.number("sample.seed")].runs.push_back(r);
  const auto beside = [&](const std::vector<RunFolder>& depth,
                          std::vector<RunFolder> SeedRuns::*to) {
    for (const auto& r : depth) {
      const auto it = seeds.find(r.number("sample.seed"));
      if (it != seeds.end()) (it->second.*to).push_back(r);
    }
  };
  beside(shallow, &SeedRuns::shallow);
  beside(deep, &SeedRuns::deep);
  std::vector<SeedRuns> out;
  for (auto& [seed, s] : seeds) {
    s.seed = seed;
    out.push_back(std::move(s));
  }
  return out;
}

StudyRegime read_regime(const std::string& label, const fs::path& dir, double early_s) {
  const bool layout = fs::is_directory(dir / "main");
  const auto runs = read_batch(layout ? dir / "main" : dir);
  if (runs.empty()) throw std::runtime_error(dir.string() + ": no run folder to read");
  std::vector<RunFolder> shallow, deep;
  if (layout && fs::is_directory(dir / "shallow") && fs::is_directory(dir / "deep")) {
    shallow = read_batch(dir / "shallow");
    deep = read_batch(dir / "deep");
  }
  const auto seeds = group_by_seed(runs, shallow, deep);
  std::vector<SeedEffects> effects;
  bool depth_run = false;
  for (const auto& s : seeds) {
    effects.push_back(seed_effects(s, early_s));
    depth_run = depth_run || (!s.shallow.empty() && !s.deep.empty());
  }
  StudyRegime regime = study_regime(label, effects, depth_run);
  regime.note = regime_note(seeds);
  return regime;
}

std::string study_markdown(const std::vector<StudyRegime>& regimes) {
  std::string s =
      "The rule, written before the runs: over the seeds, the 95 % interval of the mean effect "
      "*supports* the paper when it lies above zero, *contradicts* it when it lies below zero, "
      "finds *no effect* when it lies within ±" +
      fixed(kPracticalMargin, 1) +
      " pp (the practical margin), and is otherwise *inconclusive*, with the number of seeds "
      "at which an interval of the same spread would decide it. A supporting or contradicting "
      "interval that also lies inside the margin keeps its verdict, marked *inside ±" +
      fixed(kPracticalMargin, 1) + " pp*: a certain effect too small for a laboratory to see.\n";
  for (const auto& regime : regimes) {
    std::vector<std::vector<std::string>> rows;
    for (const auto& c : regime.conclusions) {
      const bool run = c.decision.verdict != StudyVerdict::not_run;
      rows.push_back({std::to_string(c.number), c.claim, run ? with_interval(c.effect) : "-",
                      "**" + c.decision.text() + "**", std::to_string(c.effect.n),
                      run ? pp(c.reference) : "-", run ? with_interval(c.scatter) : "-",
                      c.number == 3 ? with_interval(regime.above_100, 1) : "-"});
    }
    s += "\n**" + regime.label + "** (" + regime.note + ")\n\n" +
         markdown_table({"#", "the paper", "effect (pp) mean [95 % CI]", "verdict", "seeds",
                         "of which the test's own bias (reference)", "simulation scatter mean [CI]",
                         "readings above 100 % mean [CI]"},
                        rows);
  }
  return s;
}

void write_study_files(const std::vector<StudyRegime>& regimes, const fs::path& out_dir) {
  fs::create_directories(out_dir);
  auto study = open_for_writing(out_dir / "study.csv");
  study << "regime,conclusion,claim,seeds,effect_mean,effect_sd,effect_low,effect_high,"
           "verdict,seeds_to_decide,reference,scatter_mean,scatter_sd,scatter_low,scatter_high,"
           "above_100_mean,above_100_low,above_100_high,margin_pp\n";
  for (const auto& r : regimes)
    for (const auto& c : r.conclusions) {
      const Interval& e = c.effect;
      const Interval& sc = c.scatter;
      study << quoted(r.label) << ',' << c.number << ',' << quoted(c.claim) << ',' << e.n << ','
            << cell(e.mean) << ',' << cell(e.sd) << ',' << cell(e.low) << ',' << cell(e.high) << ','
            << to_string(c.decision.verdict) << ',' << c.decision.seeds_to_decide << ','
            << cell(c.reference) << ',' << cell(sc.mean) << ',' << cell(sc.sd) << ','
            << cell(sc.low) << ',' << cell(sc.high) << ',' << cell(r.above_100.mean) << ','
            << cell(r.above_100.low) << ',' << cell(r.above_100.high) << ','
            << cell(kPracticalMargin) << '\n';
    }
  auto seeds = open_for_writing(out_dir / "study_seeds.csv");
  seeds << "regime,seed,conclusion,effect,reference,scatter,above_100\n";
  for (const auto& r : regimes)
    for (const auto& s : r.seeds)
      for (std::size_t k = 0; k < kConclusions; ++k)
        seeds << quoted(r.label) << ',' << cell(s.seed) << ',' << k + 1 << ',' << cell(s.dem[k])
              << ',' << cell(s.reference[k]) << ',' << cell(s.dem[k] - s.reference[k]) << ','
              << cell(s.above_100) << '\n';
  if (!study || !seeds) throw std::runtime_error(out_dir.string() + ": cannot write the study");
}

std::string study_line(const StudyRegime& regime, const StudyConclusion& c) {
  return regime.label + " " + std::to_string(c.number) + ": " + c.decision.text() + " (effect " +
         with_interval(c.effect) + " pp, " + std::to_string(c.effect.n) + " seeds)";
}

}  // namespace sedem::validation
