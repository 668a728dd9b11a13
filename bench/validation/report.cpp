#include "bench/validation/report.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "bench/validation/curve_checks.h"
#include "bench/validation/markdown.h"

namespace sedem::validation {

namespace {

using Rows = std::vector<std::vector<std::string>>;
const std::vector<std::string> kTests = {"hydrometer", "buoyancy", "pipette"};

std::string pp(double v) {
  return fixed(v, 2);
}
std::string um(double metres) {
  return fixed(1e6 * metres, 1);
}
std::string count_of(std::size_t k, std::size_t n) {
  return std::to_string(k) + " of " + std::to_string(n);
}

// The full test: 24 h, the scene files' particle count.
constexpr double kFullEndTime = 86400;
constexpr double kFullParticles = 30000;

// A list of numbers from the scene, as the scene file writes it: [0.5, 1, 2].
std::string times_of(const RunFolder& run, const std::string& key) {
  const auto it = run.scene.find(key);
  if (it == run.scene.end() || !it->is_array()) return "-";
  std::string s;
  for (const auto& v : *it) s += (s.empty() ? "" : ", ") + significant(v.get<double>(), 6);
  return "[" + s + "]";
}

Section setup_section(const ReportInputs& in) {
  std::string s;
  double end = 0;
  std::size_t particles = 0;
  for (const auto& r : in.runs) {
    end = std::max(end, r.simulated_time_s);
    particles = std::max(particles, r.particle_count);
  }
  const bool full = end >= kFullEndTime;
  if (!full)
    s += "> **Short pipeline run** (" + std::to_string(particles) + " particles, " + fixed(end, 0) +
         " s simulated): it checks the machinery, not the paper. The full validation "
         "simulates the whole test (86 400 s) with the scene files' 30 000 particles, 220 sizes "
         "and standard reading times; "
         "rerun `scripts/validate.sh` to regenerate every table and figure here.\n\n";
  Rows rows;
  for (const auto& r : in.runs)
    rows.push_back({r.name, r.status, std::to_string(r.particle_count),
                    fixed(r.number("sample.size_count"), 0), fixed(r.simulated_time_s, 0),
                    r.text("sample.weighting"), r.text("integrator.method")});
  s += markdown_table(
      {"sample", "status", "particles", "sizes", "simulated (s)", "weighting", "integrator"}, rows);
  if (!in.runs.empty()) {
    s += "\nReading times (min):";
    for (const auto& test : kTests)
      s += " " + test + " " + times_of(in.runs.front(), "instruments." + test + ".times_min") +
           (test == kTests.back() ? "." : ";");
    s += "\n";
  }
  std::set<double> fractions;
  for (const auto& r : in.depth) fractions.insert(r.number("instruments.pipette.depth_fraction"));
  s += "\nAlso: " + std::to_string(in.reduced.size()) + " runs with fewer particles (" +
       (in.reduced.empty() ? std::string("none")
                           : std::to_string(in.reduced.front().particle_count) + " particles") +
       "), " + std::to_string(in.weighting.size()) + " runs with as few particles and `" +
       (in.weighting.empty() ? std::string("-") : in.weighting.front().text("sample.weighting")) +
       "` weighting, and the particles of the five runs read again with the sphere and the "
       "pipette at " +
       std::to_string(fractions.size()) + " depths (";
  std::string list;
  for (double f : fractions) list += (list.empty() ? "" : ", ") + fixed(f, 2);
  s += list + " H). The early part of the test: readings up to " + fixed(in.early_s, 0) +
       " s. Machine: " + (in.machine.empty() ? "not recorded" : in.machine) + ".\n";
  return {"setup", s};
}

Section runs_section(const ReportInputs& in) {
  Rows rows;
  for (const auto& r : in.runs) {
    std::vector<std::string> row{r.name, std::to_string(r.particle_count), fixed(r.wall_time_s, 1),
                                 significant(r.particle_steps_per_s, 3)};
    for (const auto& name : kTests) {
      const RunTest* t = r.test(name);
      row.push_back(t ? pp(t->error_pp) + " / " + pp(t->bias_pp) : "-");
    }
    rows.push_back(row);
  }
  return {"runs", markdown_table({"sample", "particles", "wall (s)", "particle-steps/s",
                                  "hydrometer error / bias (pp)", "buoyancy error / bias (pp)",
                                  "pipette error / bias (pp)"},
                                 rows)};
}

Section cost_section(const ReportInputs& in) {
  Rows rows;
  for (const auto& r : in.runs) {
    const double per_hour =
        r.simulated_time_s > 0 ? r.wall_time_s / (r.simulated_time_s / 3600) : 0;
    const double paper = paper_hours(r.name);
    const double paper_per_hour = paper * 3600 / (kPaperSimulatedSeconds / 3600);
    rows.push_back(
        {r.name, std::to_string(r.particle_count), fixed(r.simulated_time_s / 3600, 2),
         fixed(r.wall_time_s, 1), fixed(per_hour, 1),
         paper > 0 ? fixed(paper, 0) + " h (" + fixed(paper_per_hour, 0) + " s)" : "-",
         paper > 0 && per_hour > 0 ? significant(paper_per_hour / per_hour, 3) + "x" : "-"});
  }
  const bool short_runs = std::any_of(in.runs.begin(), in.runs.end(), [](const RunFolder& r) {
    return r.simulated_time_s < kFullEndTime;
  });
  std::string s =
      short_runs ? "A short run: its ratio sets a few particles over minutes against the paper's "
                   "full runs and means nothing yet.\n\n"
                 : "";
  if (short_runs) {
    // What the full runs would take if the step and the throughput stayed as measured here.
    std::vector<double> days;
    for (const auto& r : in.runs)
      if (r.simulated_time_s > 0 && r.particle_steps_per_s > 0)
        days.push_back(r.steps / r.simulated_time_s * kFullEndTime * kFullParticles /
                       r.particle_steps_per_s / 86400);
    if (!days.empty())
      s += "At the step (" +
           significant(in.runs.front().simulated_time_s / in.runs.front().steps, 2) +
           " s) and the particle-steps per second of these runs, one full run (" +
           fixed(kFullParticles, 0) + " particles, " + fixed(kFullEndTime, 0) +
           " s) would take about " + fixed(*std::min_element(days.begin(), days.end()), 0) +
           " to " + fixed(*std::max_element(days.begin(), days.end()), 0) +
           " days of wall time per sample; a rough figure, since neither stays the same.\n\n";
  }
  s += markdown_table(
      {"sample", "particles", "simulated (h)", "wall (s)", "wall per simulated hour (s)",
       "paper: total (per simulated hour)", "sedem faster by"},
      rows);
  s += "\nThe paper: " + fixed(paper_hours("sample2"), 0) + " h (sample 2) and " +
       fixed(paper_hours("sample3"), 0) + " h (sample 3) for " + fixed(kPaperSimulatedSeconds, 0) +
       " s of sedimentation on a 12-core Core i7-4930K at 3.4 GHz. sedem: " +
       (in.machine.empty() ? std::string("this machine") : in.machine) +
       ". The ratio compares wall time per simulated hour; the particle counts differ "
       "(the paper's is not stated consistently), so read it as an order of magnitude.\n";
  return {"cost", s};
}

Check size_range_check(const ReportInputs& in, std::string& table) {
  const auto rows = size_range_rows(in.runs);
  Rows t;
  std::vector<double> small, large;
  std::size_t both = 0, better = 0;
  for (const auto& r : rows) {
    t.push_back({r.sample, r.test, std::to_string(r.small_readings), pp(r.small_deviation),
                 std::to_string(r.large_readings), pp(r.large_deviation)});
    if (r.small_readings && r.large_readings) {
      ++both;
      better += r.small_deviation < r.large_deviation ? 1 : 0;
      small.push_back(r.small_deviation), large.push_back(r.large_deviation);
    }
  }
  const std::string limit = um(kLargeDiameter) + " um";
  table =
      markdown_table({"sample", "test", "readings below " + limit, "their mean abs(w - true) (pp)",
                      "readings at or above " + limit, "their mean abs(w - true) (pp)"},
                     t);
  Check c{"size_range",
          "Inside the range allowed by the standards, small particles are easier to measure than "
          "large ones",
          size_range_verdict(rows), "", "Fig. 18; table \"Small and large sizes\""};
  c.evidence = "mean abs(w - true) below " + limit + " smaller than above it in " +
               count_of(better, both) + " (sample, test) rows with readings on both sides; mean " +
               pp(mean(small)) + " pp below, " + pp(mean(large)) + " pp above";
  return c;
}

Check smoothing_check(const ReportInputs& in, std::string& table) {
  const auto rows = smoothing_rows(in.runs);
  Rows t;
  std::map<std::string, std::vector<double>> index;
  for (const auto& r : rows) {
    t.push_back({r.sample, r.test, pp(r.roughness), pp(r.truth_roughness), pp(r.index()),
                 pp(r.mean_abs_deviation)});
    index[r.test].push_back(r.index());
  }
  table =
      markdown_table({"sample", "test", "roughness (pp)", "truth's roughness at its diameters (pp)",
                      "difference (pp)", "mean abs(w - true) (pp)"},
                     t);
  Check c{"smoothing", "The hydrometer test smooths the real granulometry", smoothing_verdict(rows),
          "", "Fig. 18; table \"Smoothing\""};
  c.evidence = "roughness minus the truth's, mean over the samples: hydrometer " +
               pp(mean(index["hydrometer"])) + " pp, buoyancy " + pp(mean(index["buoyancy"])) +
               " pp, pipette " + pp(mean(index["pipette"])) + " pp";
  return c;
}

Check oscillation_check(const ReportInputs& in, std::string& table) {
  const auto rows = oscillation_rows(in.runs);
  Rows t;
  std::size_t above = 0;
  for (const auto& r : rows) {
    t.push_back({r.sample, r.test, std::to_string(r.readings), pp(r.scatter), pp(r.excess),
                 std::to_string(r.above_100)});
    if (r.test != "hydrometer") above += r.above_100;
  }
  table = markdown_table({"sample", "test", "readings at phi >= " + um(kLargeDiameter) + " um",
                          "RMS(DEM - reference) (pp)", "excess variation (pp)", "readings > 100 %"},
                         t);
  Check c{"oscillation", "The buoyancy and pipette tests oscillate for large sizes",
          oscillation_verdict(rows), "", "Figs. 16-18; table \"Oscillation\""};
  c.evidence = "RMS scatter around the reference at phi >= " + um(kLargeDiameter) +
               " um, mean over the samples: hydrometer " + pp(mean_scatter(rows, "hydrometer")) +
               " pp, buoyancy " + pp(mean_scatter(rows, "buoyancy")) + " pp, pipette " +
               pp(mean_scatter(rows, "pipette")) + " pp (floor " + pp(kOscillationFloor) +
               " pp); buoyancy and pipette readings above 100 %: " + std::to_string(above);
  return c;
}

Check large_size_check(const ReportInputs& in, std::string& table) {
  std::vector<RunFolder> all = in.runs;
  all.insert(all.end(), in.reduced.begin(), in.reduced.end());
  all.insert(all.end(), in.weighting.begin(), in.weighting.end());
  auto rows = large_size_rows(all);
  Rows t;
  std::map<std::string, std::pair<std::size_t, std::size_t>> by_weighting;  // negative, rows
  std::vector<double> dem, ref;
  for (const auto& r : rows) {
    const std::string kind = r.weighting + ", " + std::to_string(r.particles) + " particles";
    t.push_back({r.sample, r.test, kind, std::to_string(r.readings), pp(r.dem_deviation),
                 pp(r.reference_deviation)});
    if (r.readings == 0) continue;
    auto& w = by_weighting[kind];
    w.second += 1;
    w.first += r.dem_deviation < 0 ? 1 : 0;
    dem.push_back(r.dem_deviation);
    ref.push_back(r.reference_deviation);
  }
  table =
      markdown_table({"sample", "test", "run", "readings at phi >= " + um(kLargeDiameter) + " um",
                      "mean w(DEM) - w(true) (pp)", "mean w(reference) - w(true) (pp)"},
                     t);
  Check c{"large_sizes",
          "All tests predict larger particles than in reality, with a small accumulated weight",
          large_size_verdict(rows), "", "Fig. 18; table \"Large sizes\""};
  std::size_t negative = 0, n = 0;
  std::string per;
  for (const auto& [w, k] : by_weighting) {
    negative += k.first;
    n += k.second;
    per += (per.empty() ? "" : "; ") + w + ": " + count_of(k.first, k.second);
  }
  c.evidence = "w(test) - w(true) at phi >= " + um(kLargeDiameter) + " um negative in " +
               count_of(negative, n) + " rows (" + per + "); mean " + pp(mean(dem)) +
               " pp (DEM), " + pp(mean(ref)) + " pp (reference)";
  return c;
}

Check depth_check(const ReportInputs& in, std::string& table) {
  const auto rows = depth_rows(in.depth.empty() ? in.runs : in.depth);
  Rows t;
  for (const auto& r : rows)
    t.push_back({r.sample, r.test, fixed(r.depth_fraction, 2), fixed(100 * r.depth_m, 1),
                 pp(r.mean_abs_deviation), pp(r.max_abs_deviation),
                 pp(r.reference_mean_abs_deviation), pp(r.reference_bias)});
  table = markdown_table(
      {"sample", "test", "depth / H", "depth (cm)", "mean abs(w - true) (pp)",
       "max abs(w - true) (pp)", "reference: mean abs(w - true) (pp)", "reference bias (pp)"},
      t);
  const auto gaps = profile_gap_rows(in.runs);
  Rows g;
  std::vector<double> upper, middle, lower;
  const auto percent = [](double v) {
    return std::isnan(v) ? std::string("-") : fixed(100 * v, 1);
  };
  const auto add = [](std::vector<double>& to, double v) {
    if (!std::isnan(v)) to.push_back(v);
  };
  for (const auto& r : gaps) {
    g.push_back(
        {r.sample, fixed(r.time_s, 0), percent(r.upper), percent(r.middle), percent(r.lower)});
    add(upper, r.upper), add(middle, r.middle), add(lower, r.lower);
  }
  table +=
      "\nFig. 12 against Eq. 16: mean relative gap of the largest diameter above a depth, "
      "per third of the column, where Eq. 16 is below the sample's largest grain (-: nowhere "
      "in that third).\n\n" +
      markdown_table(
          {"sample", "time (s)", "upper third (%)", "middle third (%)", "lower third (%)"}, g);
  Check c{"depth",
          "In the buoyancy and pipette tests, the higher the measurement point, the more accurate",
          depth_verdict(rows), "", "Fig. 12; table \"Measurement depth\""};
  std::set<double> fractions;
  for (const auto& r : rows) fractions.insert(r.depth_fraction);
  c.evidence = "rank correlation of depth and mean abs(w - true) over " +
               std::to_string(fractions.size()) + " depths: " + fixed(depth_trend(rows), 2) +
               " (positive: deeper is worse); the same for the reference (the test without the "
               "simulation's scatter): " +
               fixed(depth_trend(rows, true), 2) + "; Fig. 12 gap to Eq. 16: upper third " +
               fixed(100 * mean(upper), 1) + " %, middle " + fixed(100 * mean(middle), 1) +
               " %, lower " + fixed(100 * mean(lower), 1) + " %";
  return c;
}

Check early_check(const ReportInputs& in, std::string& table) {
  const auto early = early_rows(in.runs, in.early_s);
  const auto reduced = reduced_rows(in.runs, in.reduced);
  Rows t;
  std::vector<double> early_errors, reduced_errors;
  for (const auto& r : early) {
    t.push_back(
        {r.sample, r.test, std::to_string(r.early_readings) + " of " + std::to_string(r.readings),
         pp(r.early_error), pp(r.error), um(r.early_smallest_diameter), um(r.smallest_diameter)});
    if (r.early_readings) early_errors.push_back(r.early_error);
  }
  table = markdown_table({"sample", "test", "readings up to " + fixed(in.early_s, 0) + " s",
                          "their error (pp)", "error of all readings (pp)",
                          "smallest phi_o so far (um)", "smallest phi_o of the run (um)"},
                         t);
  Rows rr;
  double wall = 0, reduced_wall = 0;
  std::set<std::string> samples;
  for (const auto& r : reduced) {
    rr.push_back({r.sample, r.test, std::to_string(r.reduced_particles), pp(r.reduced_error),
                  std::to_string(r.particles), pp(r.error)});
    reduced_errors.push_back(r.reduced_error);
    if (samples.insert(r.sample).second) wall += r.wall_s, reduced_wall += r.reduced_wall_s;
  }
  if (!rr.empty())
    table += "\nRuns with fewer particles (a smaller simulated mass) against the full runs.\n\n" +
             markdown_table({"sample", "test", "particles", "error (pp)", "full run's particles",
                             "full run's error (pp)"},
                            rr);
  Check c{"early_reduced",
          "A reduced mass and the early part of the test already give reasonable results",
          early_reduced_verdict(early, reduced), "", "table \"Early part and reduced mass\""};
  const auto largest = [](const std::vector<double>& v) { return pp(max_abs(v)); };
  const auto ok = [](const std::vector<double>& v) {
    return count_of(std::size_t(std::count_if(v.begin(), v.end(),
                                              [](double e) { return e <= kReasonableError; })),
                    v.size());
  };
  c.evidence = "readings up to " + fixed(in.early_s, 0) + " s within " + pp(kReasonableError) +
               " pp of the reference in " + ok(early_errors) + " rows (largest " +
               largest(early_errors) + " pp)";
  if (!reduced.empty())
    c.evidence += "; runs with " + std::to_string(reduced.front().reduced_particles) +
                  " particles in " + ok(reduced_errors) + " rows (largest " +
                  largest(reduced_errors) + " pp) at " +
                  significant(reduced_wall > 0 ? wall / reduced_wall : 0, 3) + "x less wall time";
  return c;
}

}  // namespace

double paper_hours(const std::string& sample) {
  if (sample == "sample2") return 60;
  if (sample == "sample3") return 420;
  return 0;
}

std::string verdict_line(const Check& check) {
  return check.id + ": " + to_string(check.verdict) + " -- " + check.evidence;
}

Report build_report(const ReportInputs& in) {
  Report report;
  report.sections = {setup_section(in), runs_section(in), cost_section(in)};
  std::vector<std::pair<std::string, std::string>> details;
  for (auto* check : {size_range_check, smoothing_check, oscillation_check, large_size_check,
                      depth_check, early_check}) {
    std::string table;
    report.checks.push_back(check(in, table));
    details.emplace_back(report.checks.back().id, table);
  }
  Rows rows;
  for (std::size_t k = 0; k < report.checks.size(); ++k) {
    const Check& c = report.checks[k];
    rows.push_back({std::to_string(k + 1), c.claim, std::string("**") + to_string(c.verdict) + "**",
                    c.evidence, c.where});
  }
  report.sections.push_back(
      {"conclusions", markdown_table({"#", "the paper", "sedem", "the numbers", "see"}, rows)});
  for (auto& [id, table] : details) report.sections.push_back({"check-" + id, table});
  return report;
}

}  // namespace sedem::validation
