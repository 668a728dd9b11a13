#include "bench/validation/checks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

#include "bench/validation/curve_checks.h"
#include "core/physics/stokes.h"

namespace sedem::validation {

namespace {

bool most(std::size_t count, std::size_t of) {
  return of > 0 && 2 * count > of;
}
bool two_thirds(std::size_t count, std::size_t of) {
  return of > 0 && 3 * count >= 2 * of;
}

const SmoothingRow* find_row(const std::vector<SmoothingRow>& rows, const std::string& sample,
                             const std::string& test) {
  for (const auto& r : rows)
    if (r.sample == sample && r.test == test) return &r;
  return nullptr;
}

double smallest_diameter(const TestReadings& t) {
  double d = 0;
  for (const auto& r : t.rows) d = d == 0 ? r.diameter : std::min(d, r.diameter);
  return d;
}

Fluid fluid_of(const RunFolder& run) {
  Fluid f;
  f.density = run.number("fluid.density", f.density);
  f.viscosity = run.number("fluid.viscosity", f.viscosity);
  f.gravity = run.number("fluid.gravity", f.gravity);
  return f;
}

}  // namespace

const char* to_string(Verdict v) {
  switch (v) {
    case Verdict::supports:
      return "supports";
    case Verdict::contradicts:
      return "contradicts";
    case Verdict::inconclusive:
      return "inconclusive";
  }
  return "inconclusive";
}

std::vector<SizeRangeRow> size_range_rows(const std::vector<RunFolder>& runs) {
  std::vector<SizeRangeRow> rows;
  for (const auto& run : runs)
    for (const auto& t : run.tests) {
      SizeRangeRow row{run.name, t.test, 0, 0, 0, 0};
      std::vector<double> small, large;
      const auto dev = deviations_from_truth(t.dem, run.classes);
      for (std::size_t k = 0; k < dev.size(); ++k)
        (t.dem.rows[k].diameter >= kLargeDiameter ? large : small).push_back(dev[k]);
      row.small_readings = small.size();
      row.large_readings = large.size();
      row.small_deviation = mean_abs(small);
      row.large_deviation = mean_abs(large);
      rows.push_back(row);
    }
  return rows;
}

Verdict size_range_verdict(const std::vector<SizeRangeRow>& rows) {
  std::size_t n = 0, better = 0, worse = 0;
  for (const auto& r : rows) {
    if (r.small_readings == 0 || r.large_readings == 0) continue;
    ++n;
    if (r.small_deviation < r.large_deviation) ++better;
    if (r.small_deviation > r.large_deviation) ++worse;
  }
  if (two_thirds(better, n)) return Verdict::supports;
  if (two_thirds(worse, n)) return Verdict::contradicts;
  return Verdict::inconclusive;
}

std::vector<SmoothingRow> smoothing_rows(const std::vector<RunFolder>& runs) {
  std::vector<SmoothingRow> rows;
  for (const auto& run : runs)
    for (const auto& t : run.tests)
      rows.push_back({run.name, t.test, roughness(t.dem), roughness(truth_at(t.dem, run.classes)),
                      mean_abs(deviations_from_truth(t.dem, run.classes))});
  return rows;
}

Verdict smoothing_verdict(const std::vector<SmoothingRow>& rows) {
  std::size_t samples = 0, smoother = 0, rougher = 0;
  std::vector<std::string> seen;
  for (const auto& r : rows) {
    if (r.test != "hydrometer" || std::count(seen.begin(), seen.end(), r.sample)) continue;
    seen.push_back(r.sample);
    const auto* b = find_row(rows, r.sample, "buoyancy");
    const auto* p = find_row(rows, r.sample, "pipette");
    if (!b || !p) continue;
    ++samples;
    const bool below_truth = r.index() < 0;
    const bool below_others = r.index() < b->index() && r.index() < p->index();
    if (below_truth && below_others) ++smoother;
    if (!below_truth && !below_others) ++rougher;
  }
  if (most(smoother, samples)) return Verdict::supports;
  if (most(rougher, samples)) return Verdict::contradicts;
  return Verdict::inconclusive;
}

std::vector<OscillationRow> oscillation_rows(const std::vector<RunFolder>& runs) {
  std::vector<OscillationRow> rows;
  for (const auto& run : runs)
    for (const auto& t : run.tests) {
      const TestReadings dem = large_sizes(t.dem, kLargeDiameter);
      // The reference at the same times: the DEM's large-size readings are its first ones.
      TestReadings ref = t.reference;
      ref.rows.resize(std::min(ref.rows.size(), t.dem.rows.size()));
      TestReadings ref_large = ref;
      ref_large.rows.clear();
      for (std::size_t k = 0; k < ref.rows.size(); ++k)
        if (t.dem.rows[k].diameter >= kLargeDiameter) ref_large.rows.push_back(ref.rows[k]);
      OscillationRow row{run.name, t.test, dem.rows.size(), 0, 0, 0};
      for (const auto& r : dem.rows) row.above_100 += r.percent_finer > 100.0 ? 1 : 0;
      row.scatter = root_mean_square(differences(dem, ref_large));
      row.excess = excess_variation(dem);
      rows.push_back(row);
    }
  return rows;
}

double mean_scatter(const std::vector<OscillationRow>& rows, const std::string& test) {
  std::vector<double> v;
  for (const auto& r : rows)
    if (r.test == test && r.readings > 0) v.push_back(r.scatter);
  return mean(v);
}

Verdict oscillation_verdict(const std::vector<OscillationRow>& rows) {
  const double h = mean_scatter(rows, "hydrometer"), b = mean_scatter(rows, "buoyancy"),
               p = mean_scatter(rows, "pipette");
  if (b > h && p > h && b > kOscillationFloor && p > kOscillationFloor) return Verdict::supports;
  if (b <= h && p <= h) return Verdict::contradicts;
  return Verdict::inconclusive;
}

std::vector<LargeSizeRow> large_size_rows(const std::vector<RunFolder>& runs) {
  std::vector<LargeSizeRow> rows;
  for (const auto& run : runs)
    for (const auto& t : run.tests) {
      const TestReadings dem = large_sizes(t.dem, kLargeDiameter);
      const TestReadings ref = large_sizes(t.reference, kLargeDiameter);
      rows.push_back({run.name, t.test, run.text("sample.weighting", "?"), run.particle_count,
                      dem.rows.size(), mean(deviations_from_truth(dem, run.classes)),
                      mean(deviations_from_truth(ref, run.classes))});
    }
  return rows;
}

Verdict large_size_verdict(const std::vector<LargeSizeRow>& rows) {
  std::size_t n = 0, negative = 0, positive = 0;
  for (const auto& r : rows) {
    if (r.readings == 0) continue;
    ++n;
    if (r.dem_deviation < 0) ++negative;
    if (r.dem_deviation > 0) ++positive;
  }
  if (two_thirds(negative, n)) return Verdict::supports;
  if (two_thirds(positive, n)) return Verdict::contradicts;
  return Verdict::inconclusive;
}

std::vector<DepthRow> depth_rows(const std::vector<RunFolder>& runs) {
  std::vector<DepthRow> rows;
  for (const auto& run : runs)
    for (const auto& t : run.tests) {
      if (t.test != "buoyancy" && t.test != "pipette") continue;
      const auto dev = deviations_from_truth(t.dem, run.classes);
      const auto ref = deviations_from_truth(t.reference, run.classes);
      rows.push_back({run.name, t.test, run.number("instruments." + t.test + ".depth_fraction"),
                      t.depth_m, mean_abs(dev), max_abs(dev), mean_abs(ref), t.bias_pp});
    }
  std::sort(rows.begin(), rows.end(), [](const DepthRow& a, const DepthRow& b) {
    return std::tie(a.sample, a.test, a.depth_fraction) <
           std::tie(b.sample, b.test, b.depth_fraction);
  });
  return rows;
}

double depth_trend(const std::vector<DepthRow>& rows, bool reference) {
  std::map<std::pair<std::string, std::string>, std::pair<std::vector<double>, std::vector<double>>>
      groups;
  for (const auto& r : rows) {
    auto& [depth, deviation] = groups[{r.sample, r.test}];
    depth.push_back(r.depth_fraction);
    deviation.push_back(reference ? r.reference_mean_abs_deviation : r.mean_abs_deviation);
  }
  std::vector<double> trends;
  for (const auto& [key, g] : groups)
    if (g.first.size() >= 3) trends.push_back(rank_correlation(g.first, g.second));
  return mean(trends);
}

Verdict depth_verdict(const std::vector<DepthRow>& rows) {
  const double trend = depth_trend(rows);
  if (trend >= kTrendCorrelation) return Verdict::supports;
  if (trend <= -kTrendCorrelation) return Verdict::contradicts;
  return Verdict::inconclusive;
}

std::vector<ProfileGapRow> profile_gap_rows(const std::vector<RunFolder>& runs) {
  const auto gap = [](const std::vector<double>& v) {
    return v.empty() ? std::numeric_limits<double>::quiet_NaN() : mean_abs(v);
  };
  std::vector<ProfileGapRow> rows;
  for (const auto& run : runs) {
    if (run.classes.empty()) continue;
    const double height = run.number("cylinder.height_m", 0.457);
    const double largest = run.classes.back().diameter;
    const double density = run.number("sample.particle_density", 2500);
    for (const auto& p : run.profiles) {
      std::vector<double> thirds[3];
      for (std::size_t k = 0; k < p.depth_m.size(); ++k) {
        // Where Eq. 16 exceeds the largest grain both curves sit at that grain: no test.
        const double bound =
            stokes::limiting_diameter(p.depth_m[k], p.time_s, density, fluid_of(run));
        if (bound <= 0 || bound >= largest) continue;
        const int third = std::clamp(int(3 * p.depth_m[k] / height), 0, 2);
        thirds[third].push_back((p.largest_diameter_m[k] - bound) / bound);
      }
      rows.push_back({run.name, p.time_s, gap(thirds[0]), gap(thirds[1]), gap(thirds[2])});
    }
  }
  return rows;
}

std::vector<EarlyRow> early_rows(const std::vector<RunFolder>& runs, double early_s) {
  std::vector<EarlyRow> rows;
  for (const auto& run : runs)
    for (const auto& t : run.tests) {
      const TestReadings dem = up_to(t.dem, early_s);
      TestReadings ref = t.reference;
      ref.rows.resize(std::min(ref.rows.size(), dem.rows.size()));
      rows.push_back({run.name, t.test, dem.rows.size(), t.dem.rows.size(),
                      max_abs(differences(dem, ref)), t.error_pp, smallest_diameter(dem),
                      smallest_diameter(t.dem)});
    }
  return rows;
}

std::vector<ReducedRow> reduced_rows(const std::vector<RunFolder>& runs,
                                     const std::vector<RunFolder>& reduced) {
  std::vector<ReducedRow> rows;
  for (const auto& small : reduced) {
    const auto full = std::find_if(runs.begin(), runs.end(),
                                   [&](const RunFolder& r) { return r.name == small.name; });
    if (full == runs.end()) continue;
    for (const auto& t : small.tests) {
      const RunTest* f = full->test(t.test);
      if (!f) continue;
      rows.push_back({small.name, t.test, full->particle_count, small.particle_count,
                      full->wall_time_s, small.wall_time_s, f->error_pp, t.error_pp});
    }
  }
  return rows;
}

double share_reasonable(const std::vector<EarlyRow>& rows) {
  std::size_t n = 0, ok = 0;
  for (const auto& r : rows)
    if (r.early_readings > 0) ++n, ok += r.early_error <= kReasonableError ? 1 : 0;
  return n ? double(ok) / double(n) : 0.0;
}

double share_reasonable(const std::vector<ReducedRow>& rows) {
  std::size_t ok = 0;
  for (const auto& r : rows) ok += r.reduced_error <= kReasonableError ? 1 : 0;
  return rows.empty() ? 0.0 : double(ok) / double(rows.size());
}

Verdict early_reduced_verdict(const std::vector<EarlyRow>& early,
                              const std::vector<ReducedRow>& reduced) {
  if (std::none_of(early.begin(), early.end(), [](const EarlyRow& r) { return r.early_readings; }))
    return Verdict::inconclusive;
  const double e = share_reasonable(early);
  const bool have_reduced = !reduced.empty();
  const double r = share_reasonable(reduced);
  if (e > 0.5 && (!have_reduced || r > 0.5)) return Verdict::supports;
  if (e < 0.5 && (!have_reduced || r < 0.5)) return Verdict::contradicts;
  return Verdict::inconclusive;
}

}  // namespace sedem::validation
