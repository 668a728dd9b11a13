#include "core/design/schedule_design.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "core/reference/reference_readings.h"
#include "core/sample/grading_curve.h"
#include "core/sample/sample_builder.h"

namespace sedem {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Diameters equal to this relative precision cover a range's end (the standard's own readings
// span its range exactly).
constexpr double kCoverTolerance = 1e-9;
// Log-spaced points of the truth grid: between a family's points the curve moves less than
// 0.3 pp for any curve of this project's samples; tables are exact (their points are added).
constexpr std::size_t kGridPoints = 1200;

bool is_test(const std::string& test) {
  return test == "hydrometer" || test == "buoyancy" || test == "pipette";
}

bool enabled(const InstrumentsConfig& instruments, const std::string& test) {
  if (test == "hydrometer") return instruments.hydrometer;
  if (test == "buoyancy") return instruments.buoyancy;
  return instruments.pipette;
}

const std::vector<double>& standard_times(const InstrumentsConfig& instruments,
                                          const std::string& test) {
  if (test == "hydrometer") return instruments.hydrometer_times;
  if (test == "buoyancy") return instruments.buoyancy_times;
  return instruments.pipette_times;
}

double standard_depth(const InstrumentsConfig& instruments, const std::string& test) {
  if (test == "buoyancy") return instruments.buoyancy_depth_fraction;
  if (test == "pipette") return instruments.pipette_depth_fraction;
  return std::numeric_limits<double>::quiet_NaN();
}

struct Gap {
  double error = -1, diameter = 0, curve = 0, truth = 0;
  double area = 0;  // pp x ln(d): |curve - truth| integrated over the segment
  void take(double d, double curve_value, double truth_value) {
    const double e = std::abs(curve_value - truth_value);
    if (e > error) {
      error = e;
      diameter = d;
      curve = curve_value;
      truth = truth_value;
    }
  }
};

// The largest gap on the segment between two readings, over the grid points inside it and the
// two readings' own diameters, within the grid's range.
Gap segment_gap(const Reading& a, const Reading& b, const TruthGrid& truth) {
  const auto& log_grid = truth.log_diameters;
  Gap gap;
  const double lo = std::max(std::min(a.diameter, b.diameter), truth.low);
  const double hi = std::min(std::max(a.diameter, b.diameter), truth.high);
  if (lo > hi) return gap;
  for (const Reading* r : {&a, &b})
    if (r->diameter >= truth.low && r->diameter <= truth.high)
      gap.take(r->diameter, r->percent_finer, truth.percent_at(r->diameter));
  // The curve through a and b, linear in log d.
  const double xa = std::log(a.diameter), xb = std::log(b.diameter);
  const double slope = xa == xb ? 0 : (b.percent_finer - a.percent_finer) / (xb - xa);
  const double base = xa == xb ? 0.5 * (a.percent_finer + b.percent_finer) : a.percent_finer;
  auto first = std::lower_bound(truth.diameters.begin(), truth.diameters.end(), lo);
  auto last = std::upper_bound(truth.diameters.begin(), truth.diameters.end(), hi);
  for (auto it = first; it != last; ++it) {
    const auto k = std::size_t(it - truth.diameters.begin());
    const double curve = base + slope * (log_grid[k] - xa);
    gap.take(*it, curve, truth.percent[k]);
    // Each grid point stands for half the log distance to each neighbour (the ends, half one).
    const double left = k > 0 ? log_grid[k] - log_grid[k - 1] : 0;
    const double right = k + 1 < log_grid.size() ? log_grid[k + 1] - log_grid[k] : 0;
    gap.area += std::abs(curve - truth.percent[k]) * 0.5 * (left + right);
  }
  return gap;
}

// The readings of `count` chosen from `candidates` (ascending in time), the first at or after
// `earliest` and reaching the range's top, the last reaching its bottom, with the least worst
// error; among those (the worst is often one reading's own error, which every schedule
// shares), the least mean error. Both exact on the candidates, by dynamic programming over
// pairs of readings: first best[k][j] = min over i < j of max(best[k-1][i], gap(i, j)), then
// the least summed area over the paths whose every gap is within that worst.
struct Path {
  double worst = kInfinity;
  std::vector<std::size_t> picks;
};
Path minimax_path(const std::vector<Reading>& candidates, std::size_t count, double earliest,
                  const TruthGrid& truth) {
  const std::size_t n = candidates.size();
  std::vector<double> gap(n * n, kInfinity), area(n * n, kInfinity);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const Gap g = segment_gap(candidates[i], candidates[j], truth);
      gap[i * n + j] = std::max(0.0, g.error);
      area[i * n + j] = g.area;
    }
  const double top = truth.high * (1 - kCoverTolerance);
  const double bottom = truth.low * (1 + kCoverTolerance);
  auto starts = [&](std::size_t i) {
    return candidates[i].time >= earliest * (1 - kCoverTolerance) && candidates[i].diameter >= top;
  };
  auto ends = [&](std::size_t j) { return candidates[j].diameter <= bottom; };
  // One pass of the dynamic programme: `join` combines a path's cost with a gap's.
  std::vector<std::vector<std::size_t>> parent(count, std::vector<std::size_t>(n, n));
  auto solve = [&](auto join, const std::vector<double>& edge, double limit) {
    std::vector<double> best(n, kInfinity), next(n);
    for (std::size_t i = 0; i < n; ++i)
      if (starts(i)) best[i] = 0;
    for (std::size_t k = 1; k < count; ++k) {
      std::fill(next.begin(), next.end(), kInfinity);
      for (std::size_t j = 0; j < n; ++j)
        for (std::size_t i = 0; i < j; ++i) {
          if (best[i] == kInfinity || gap[i * n + j] > limit) continue;
          const double w = join(best[i], edge[i * n + j]);
          if (w < next[j]) {
            next[j] = w;
            parent[k][j] = i;
          }
        }
      best.swap(next);
    }
    std::size_t end = n;
    for (std::size_t j = 0; j < n; ++j)
      if (ends(j) && best[j] < kInfinity && (end == n || best[j] < best[end])) end = j;
    return std::pair{end, end == n ? kInfinity : best[end]};
  };
  Path path;
  const auto [worst_end, worst] =
      solve([](double a, double b) { return std::max(a, b); }, gap, kInfinity);
  if (worst_end == n) return path;
  path.worst = worst;
  // The minimax path itself qualifies, so this pass always ends somewhere.
  std::size_t end =
      solve([](double a, double b) { return a + b; }, area, worst * (1 + 1e-9) + 1e-12).first;
  path.picks.assign(count, n);
  for (std::size_t k = count; k-- > 0;) {
    path.picks[k] = end;
    end = parent[k][end];
  }
  return path;
}

// A reading every minute over a schedule's times, at its depth: its first time, each whole
// minute after it, its last.
ReadingSchedule every_minute(const ReadingSchedule& schedule) {
  ReadingSchedule s;
  s.depth_fraction = schedule.depth_fraction;
  const double first = schedule.times.front(), last = schedule.times.back();
  s.times = {first};
  for (double t = (std::floor(first / 60) + 1) * 60; t < last; t += 60) s.times.push_back(t);
  s.times.push_back(last);
  return s;
}

}  // namespace

ScheduleScore score_readings(const std::vector<Reading>& readings, const TruthGrid& truth) {
  std::vector<Reading> sorted = readings;
  std::sort(sorted.begin(), sorted.end(),
            [](const Reading& a, const Reading& b) { return a.diameter < b.diameter; });
  Gap worst;
  double area = 0;
  for (std::size_t i = 0; i + 1 < sorted.size(); ++i) {
    const Gap g = segment_gap(sorted[i], sorted[i + 1], truth);
    area += g.area;
    if (g.error > worst.error) worst = g;
  }
  if (sorted.size() == 1) worst = segment_gap(sorted[0], sorted[0], truth);
  ScheduleScore score;
  score.worst_error = std::max(0.0, worst.error);
  score.worst_diameter = worst.diameter;
  score.worst_curve = worst.curve;
  score.worst_truth = worst.truth;
  score.mean_error = truth.high > truth.low ? area / std::log(truth.high / truth.low) : 0;
  score.readings = readings;
  return score;
}

std::vector<double> clock_times(double first, double last) {
  std::vector<double> t{first};
  auto add_steps = [&](double step, double until) {
    double x = std::floor(t.back() / step + kCoverTolerance) * step + step;
    for (; x <= std::min(until, last) * (1 + kCoverTolerance); x += step)
      if (x > t.back()) t.push_back(x);
  };
  add_steps(15, 120);
  add_steps(30, 600);
  add_steps(60, 4 * 3600);
  add_steps(300, last);
  if (t.back() < last * (1 - kCoverTolerance)) t.push_back(last);
  return t;
}

void check_design_options(const TestSetup& setup, const DesignOptions& options) {
  if (!is_test(options.test))
    throw std::invalid_argument("--test " + options.test +
                                ": allowed hydrometer, buoyancy or pipette");
  if (!enabled(setup.instruments, options.test))
    throw std::invalid_argument("--test " + options.test + ": the scene disables it (instruments." +
                                options.test + ".enabled = false)");
  if (options.readings == 1 || options.readings > 200)
    throw std::invalid_argument("--readings " + std::to_string(options.readings) +
                                ": allowed 2 to 200 (0: the standard's count)");
  if (standard_times(setup.instruments, options.test).size() < 2)
    throw std::invalid_argument("instruments." + options.test +
                                ".times_min: a design needs a standard of 2 readings or more");
  if (options.size_count < 1 || options.size_count > 100000)
    throw std::invalid_argument("--sizes " + std::to_string(options.size_count) +
                                ": allowed 1 to 100000");
}

InstrumentsConfig instruments_for_schedule(InstrumentsConfig in, const std::string& test,
                                           const ReadingSchedule& schedule) {
  in.hydrometer = test == "hydrometer";
  in.buoyancy = test == "buoyancy";
  in.pipette = test == "pipette";
  if (in.hydrometer) in.hydrometer_times = schedule.times;
  if (in.buoyancy) {
    in.buoyancy_times = schedule.times;
    in.buoyancy_depth_fraction = schedule.depth_fraction;
  }
  if (in.pipette) {
    in.pipette_times = schedule.times;
    in.pipette_depth_fraction = schedule.depth_fraction;
  }
  // Fig. 12's profiles are not a reading: keep them within the run.
  in.profile_times.erase(std::remove_if(in.profile_times.begin(), in.profile_times.end(),
                                        [&](double t) { return t > schedule.times.back(); }),
                         in.profile_times.end());
  return in;
}

struct ScheduleReader::State {
  TestSetup setup;
  Sample sample;
  ReferenceSolution reference;
};

namespace {

Sample planned_sample(const SampleSetup& setup) {
  const SamplePlan plan = plan_sample(setup);
  Sample sample;
  sample.classes = plan.classes;
  sample.particle_density = setup.sample.particle_density;
  sample.section_mass = plan.section_mass;
  return sample;
}

SampleSetup with_sizes(SampleSetup setup, std::int64_t size_count) {
  setup.sample.size_count = size_count;
  return setup;
}

}  // namespace

ScheduleReader::ScheduleReader(const TestSetup& setup, const SampleSetup& sample,
                               std::int64_t size_count) {
  Sample planned = planned_sample(with_sizes(sample, size_count));
  ReferenceSolution reference = make_reference(setup, planned, reference_options(setup));
  state_.reset(new State{setup, std::move(planned), std::move(reference)});
}

ScheduleReader::~ScheduleReader() = default;

std::vector<Reading> ScheduleReader::readings(const std::string& test,
                                              const ReadingSchedule& schedule) const {
  TestSetup only = state_->setup;
  only.instruments = instruments_for_schedule(only.instruments, test, schedule);
  auto tests = reference_readings(only, state_->sample, state_->reference);
  if (tests.size() != 1) throw std::logic_error("ScheduleReader: no " + test);
  return std::move(tests.front().rows);
}

TruthGrid truth_grid(const GradingConfig& grading, double low, double high) {
  TruthGrid grid;
  grid.low = low;
  grid.high = high;
  const auto curve = std::make_shared<GradingCurve>(grading);
  grid.percent_at = [curve](double d) { return curve->percent_finer(d); };
  for (std::size_t k = 0; k < kGridPoints; ++k)
    grid.diameters.push_back(low * std::pow(high / low, double(k) / double(kGridPoints - 1)));
  if (grading.family == "table")
    for (double d : grading.diameters)
      if (d > low && d < high) grid.diameters.push_back(d);
  std::sort(grid.diameters.begin(), grid.diameters.end());
  grid.diameters.erase(std::unique(grid.diameters.begin(), grid.diameters.end()),
                       grid.diameters.end());
  for (double d : grid.diameters) {
    grid.percent.push_back(grid.percent_at(d));
    grid.log_diameters.push_back(std::log(d));
  }
  return grid;
}

ScheduleDesign design_schedule(const TestSetup& setup, const SampleSetup& sample,
                               const DesignOptions& options) {
  check_design_options(setup, options);
  ScheduleDesign design;
  design.test = options.test;
  design.standard.times = standard_times(setup.instruments, options.test);
  std::sort(design.standard.times.begin(), design.standard.times.end());
  design.standard.depth_fraction = standard_depth(setup.instruments, options.test);
  const std::size_t count = options.readings == 0 ? design.standard.times.size() : options.readings;

  const ScheduleReader reader(setup, sample, options.size_count);
  const auto standard_rows = reader.readings(options.test, design.standard);
  double low = kInfinity, high = 0;
  for (const auto& r : standard_rows) {
    low = std::min(low, r.diameter);
    high = std::max(high, r.diameter);
  }
  design.truth = truth_grid(sample.sample.grading, low, high);
  design.standard_score = score_readings(standard_rows, design.truth);

  const double first = design.standard.times.front();
  design.floor = every_minute(design.standard);
  design.floor_score = score_readings(reader.readings(options.test, design.floor), design.truth);

  // The designed schedule: every depth tried (the hydrometer has one), the best kept.
  std::vector<double> depths{design.standard.depth_fraction};
  if (options.test != "hydrometer") {
    depths.insert(depths.end(), options.depth_fractions.begin(), options.depth_fractions.end());
    std::sort(depths.begin(), depths.end());
    depths.erase(std::unique(depths.begin(), depths.end()), depths.end());
  }
  ReadingSchedule candidates;
  candidates.times = clock_times(first, options.last_time);
  for (double t : design.standard.times) candidates.times.push_back(t);
  std::sort(candidates.times.begin(), candidates.times.end());
  candidates.times.erase(std::unique(candidates.times.begin(), candidates.times.end()),
                         candidates.times.end());
  double best = kInfinity;
  for (double depth : depths) {
    candidates.depth_fraction = depth;
    const auto rows = reader.readings(options.test, candidates);
    const Path path = minimax_path(rows, count, first, design.truth);
    design.schedules_searched += rows.size() * rows.size() / 2;
    if (path.picks.empty() || !(path.worst < best)) continue;
    best = path.worst;
    design.designed.depth_fraction = depth;
    design.designed.times.clear();
    std::vector<Reading> picked;
    for (std::size_t i : path.picks) {
      design.designed.times.push_back(rows[i].time);
      picked.push_back(rows[i]);
    }
    design.designed_score = score_readings(picked, design.truth);
  }
  if (design.designed.times.empty())
    throw std::runtime_error("no schedule of " + std::to_string(count) +
                             " readings spans the standard's diameters");
  if (design.designed.depth_fraction != design.standard.depth_fraction &&
      !std::isnan(design.designed.depth_fraction)) {
    design.depth_floor = every_minute(design.designed);
    design.depth_floor_score =
        score_readings(reader.readings(options.test, design.depth_floor), design.truth);
  }
  return design;
}

}  // namespace sedem
