#include "bench/validation/study.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include "bench/validation/checks.h"
#include "bench/validation/curve_checks.h"

namespace sedem::validation {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// An effect with nothing to average is unknown, not zero: mean_interval skips it.
double mean_or_nan(const std::vector<double>& v) {
  return v.empty() ? kNaN : mean(v);
}

std::vector<RunFolder> reference_only(std::vector<RunFolder> runs) {
  for (auto& run : runs)
    for (auto& t : run.tests) t.dem = t.reference;
  return runs;
}

std::string fixed_margin() {
  char b[16];
  std::snprintf(b, sizeof b, "%.1f", kPracticalMargin);
  return b;
}

}  // namespace

const char* to_string(StudyVerdict v) {
  switch (v) {
    case StudyVerdict::supports:
      return "supports";
    case StudyVerdict::contradicts:
      return "contradicts";
    case StudyVerdict::no_effect:
      return "no effect";
    case StudyVerdict::inconclusive:
      return "inconclusive";
    case StudyVerdict::not_run:
      return "not run";
  }
  return "inconclusive";
}

std::string Decision::text() const {
  std::string s = to_string(verdict);
  if (inside_margin) return s + ", inside ±" + fixed_margin() + " pp";
  if (verdict != StudyVerdict::inconclusive) return s;
  if (seeds == 0) return s + ": no seed has readings for it";
  if (seeds < 2) return s + ": needs at least 2 seeds";
  if (seeds_to_decide == 0) return s + ": no count of seeds up to a million would decide it";
  return s + ": ~" + std::to_string(seeds_to_decide) + " seeds would decide it";
}

Decision decide(const Interval& effect, double margin) {
  Decision d;
  d.seeds = effect.n;
  if (effect.n < 2 || std::isnan(effect.sd)) return d;
  const bool inside = effect.low >= -margin && effect.high <= margin;
  if (effect.low > 0) {
    d.verdict = StudyVerdict::supports;
    d.inside_margin = inside;
  } else if (effect.high < 0) {
    d.verdict = StudyVerdict::contradicts;
    d.inside_margin = inside;
  } else if (inside) {
    d.verdict = StudyVerdict::no_effect;
  } else {
    // Either way out: a half-width below |mean| excludes zero, one below margin - |mean| fits
    // the interval inside the margin; the nearer of the two is the honest estimate.
    const double size = std::abs(effect.mean);
    const std::size_t to_sign = size > 0 ? count_for_half_width(effect.sd, size, kStudyLevel) : 0;
    const std::size_t to_margin =
        margin > size ? count_for_half_width(effect.sd, margin - size, kStudyLevel) : 0;
    d.seeds_to_decide = to_sign == 0     ? to_margin
                        : to_margin == 0 ? to_sign
                                         : std::min(to_sign, to_margin);
  }
  return d;
}

SeedRuns reference_only(const SeedRuns& runs) {
  return {runs.seed, reference_only(runs.runs), reference_only(runs.shallow),
          reference_only(runs.deep)};
}

double size_range_effect(const std::vector<RunFolder>& runs) {
  std::vector<double> v;
  for (const auto& r : size_range_rows(runs))
    if (r.small_readings > 0 && r.large_readings > 0)
      v.push_back(r.large_deviation - r.small_deviation);
  return mean_or_nan(v);
}

double smoothing_effect(const std::vector<RunFolder>& runs) {
  std::vector<double> v;
  for (const auto& r : smoothing_rows(runs))
    if (r.test == "hydrometer") v.push_back(-r.index());
  return mean_or_nan(v);
}

double oscillation_effect(const std::vector<RunFolder>& runs) {
  std::map<std::string, std::map<std::string, double>> scatter;  // sample -> test -> scatter
  for (const auto& r : oscillation_rows(runs))
    if (r.readings > 0) scatter[r.sample][r.test] = r.scatter;
  std::vector<double> v;
  for (const auto& [sample, tests] : scatter) {
    if (!tests.count("hydrometer") || !tests.count("buoyancy") || !tests.count("pipette")) continue;
    v.push_back(std::min(tests.at("buoyancy"), tests.at("pipette")) - tests.at("hydrometer"));
  }
  return mean_or_nan(v);
}

double large_size_effect(const std::vector<RunFolder>& runs) {
  std::vector<double> v;
  for (const auto& r : large_size_rows(runs))
    if (r.readings > 0) v.push_back(r.dem_deviation);
  return -mean_or_nan(v);
}

double depth_effect(const std::vector<RunFolder>& shallow, const std::vector<RunFolder>& deep) {
  const auto deep_rows = depth_rows(deep);
  std::vector<double> v;
  for (const auto& s : depth_rows(shallow))
    for (const auto& d : deep_rows)
      if (d.sample == s.sample && d.test == s.test)
        v.push_back(d.mean_abs_deviation - s.mean_abs_deviation);
  return mean_or_nan(v);
}

double early_effect(const std::vector<RunFolder>& runs, double early_s) {
  bool any = false;
  double largest = 0;
  for (const auto& r : early_rows(runs, early_s))
    if (r.early_readings > 0) any = true, largest = std::max(largest, r.early_error);
  return any ? kReasonableError - largest : kNaN;
}

std::size_t readings_above_100(const std::vector<RunFolder>& runs) {
  std::size_t n = 0;
  for (const auto& run : runs)
    for (const auto& t : run.tests)
      if (t.test == "buoyancy" || t.test == "pipette")
        for (const auto& r : t.dem.rows) n += r.percent_finer > 100.0 ? 1 : 0;
  return n;
}

std::array<double, kConclusions> effects(const SeedRuns& runs, double early_s) {
  const bool depth = !runs.shallow.empty() && !runs.deep.empty();
  return {size_range_effect(runs.runs),
          smoothing_effect(runs.runs),
          oscillation_effect(runs.runs),
          large_size_effect(runs.runs),
          depth ? depth_effect(runs.shallow, runs.deep) : kNaN,
          early_effect(runs.runs, early_s)};
}

SeedEffects seed_effects(const SeedRuns& runs, double early_s) {
  return {runs.seed, effects(runs, early_s), effects(reference_only(runs), early_s),
          double(readings_above_100(runs.runs))};
}

const std::string& study_claim(std::size_t k) {
  static const std::array<std::string, kConclusions> claims = {
      "Inside the range allowed by the standards, small particles are easier to measure than "
      "large ones",
      "The hydrometer test smooths the real granulometry",
      "The buoyancy and pipette tests oscillate for large sizes",
      "All tests predict larger particles than in reality, with a small accumulated weight",
      "In the buoyancy and pipette tests, the higher the measurement point, the more accurate",
      "The early part of the test already gives reasonable results"};
  return claims.at(k - 1);
}

StudyRegime study_regime(const std::string& label, const std::vector<SeedEffects>& seeds,
                         bool depth_run) {
  StudyRegime regime;
  regime.label = label;
  regime.seeds = seeds;
  std::vector<double> above;
  for (const auto& s : seeds) above.push_back(s.above_100);
  regime.above_100 = mean_interval(above, kStudyLevel);
  for (std::size_t k = 0; k < kConclusions; ++k) {
    std::vector<double> dem, reference, scatter;
    for (const auto& s : seeds) {
      dem.push_back(s.dem[k]);
      reference.push_back(s.reference[k]);
      scatter.push_back(s.dem[k] - s.reference[k]);
    }
    StudyConclusion& c = regime.conclusions[k];
    c.number = k + 1;
    c.claim = study_claim(k + 1);
    c.effect = mean_interval(dem, kStudyLevel);
    c.scatter = mean_interval(scatter, kStudyLevel);
    c.reference = mean_interval(reference, kStudyLevel).mean;
    c.decision = decide(c.effect);
    if (k == 4 && !depth_run) c.decision = {StudyVerdict::not_run, c.effect.n, 0};
  }
  return regime;
}

}  // namespace sedem::validation
