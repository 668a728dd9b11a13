#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/instruments/granulometry.h"
#include "core/instruments/test_setup.h"
#include "core/sample/sample_setup.h"

namespace sedem {

// Designing a test's reading schedule (docs/design.md): the times (and, for the sphere and
// the pipette, the one depth) at which a laboratory should read so that the grading curve
// it draws through its readings, linear in log diameter between them as a laboratory draws
// it, stays closest to the true curve everywhere on the diameters the standard schedule
// covers, not only at the readings.

// A schedule: the times of a test's readings and the depth of the sphere's centre or the
// pipette's tip as a fraction of the suspension's height (the hydrometer floats: NaN).
struct ReadingSchedule {
  std::vector<double> times;  // s, ascending
  double depth_fraction = 0;
};

// How far a schedule's curve is from the truth over a range of diameters.
struct ScheduleScore {
  double worst_error = 0;     // pp, the largest |curve - truth| over the range
  double worst_diameter = 0;  // m, where it is
  double worst_curve = 0;     // %, the curve there
  double worst_truth = 0;     // %, the truth there
  double mean_error = 0;      // pp, |curve - truth| averaged over the range in log d
  std::vector<Reading> readings;
};

// The diameters on which a schedule is judged, and the truth on them.
struct TruthGrid {
  double low = 0, high = 0;                  // m, the range
  std::vector<double> diameters;             // m, ascending, the range's ends included
  std::vector<double> percent;               // the true percent finer at each
  std::vector<double> log_diameters;         // ln of each, where the curves are linear
  std::function<double(double)> percent_at;  // the true percent finer at any diameter
};

// The worst |interpolated curve - truth| over the grid and at the readings' own diameters in
// the range, the curve drawn through the readings linear in log diameter (readings outside the
// range still anchor it). Where the truth is piecewise linear in log d too (a table), the
// largest gap lies on one of those points, so the score is exact. A range the readings do not
// span is scored over the part they span only: callers check coverage.
ScheduleScore score_readings(const std::vector<Reading>& readings, const TruthGrid& truth);

// Times a person reads off a clock or a stopwatch: every 15 s up to 2 min, every half minute
// up to 10 min, every minute up to 4 h, every 5 min up to `last`; from `first` on (which is
// included, as is `last`).
std::vector<double> clock_times(double first, double last);

struct DesignOptions {
  std::string test;                // hydrometer | buoyancy | pipette
  std::size_t readings = 0;        // 0: as many as the standard schedule
  std::int64_t size_count = 1000;  // sizes of the reference's sample: near the continuous curve
  double last_time = 86400;        // s: no reading after 24 h
  // Depths tried for the sphere and the pipette, fractions of the height (the standard's is
  // always among them).
  std::vector<double> depth_fractions{0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4, 0.5, 0.6, 0.7};
};

// Throws std::invalid_argument (one line naming the option, the value and what is allowed)
// for an unknown test, a test the setup disables, or a reading count below 2.
void check_design_options(const TestSetup& setup, const DesignOptions& options);

// The three schedules of a design and their scores against the truth, from the reference
// solution (the near-exact continuum of the setup's physics).
struct ScheduleDesign {
  std::string test;
  TruthGrid truth;
  ReadingSchedule standard, designed, floor;
  ScheduleScore standard_score, designed_score, floor_score;
  // The floor at the designed depth (a reading every minute over the designed schedule's
  // times), when the sphere or the pipette is designed to read at another depth: the fair
  // floor to set a designed schedule against. Empty times otherwise.
  ReadingSchedule depth_floor;
  ScheduleScore depth_floor_score;
  std::size_t schedules_searched = 0;  // candidate schedules' worth of work: pairs x depths
};

// The standard schedule is the setup's; the floor reads every minute over the standard's
// times at its depth (what the instrument's own averaging leaves, whatever the schedule);
// the designed schedule has the same number of readings (or options.readings), starts no
// earlier than the standard, ends within options.last_time, reads at clock_times, spans the
// standard's diameters, and has the least worst error: a minimax path through the candidate
// times (dynamic programming over pairs of readings, exact on the candidates).
ScheduleDesign design_schedule(const TestSetup& setup, const SampleSetup& sample,
                               const DesignOptions& options);

// The instruments with only `test` enabled, reading at `schedule`'s times and depth (the
// profiles of Fig. 12 kept within them).
InstrumentsConfig instruments_for_schedule(InstrumentsConfig in, const std::string& test,
                                           const ReadingSchedule& schedule);

// The reference solution of the sample's grading curve cut into `size_count` sizes, solved once
// (its fronts cost O(sizes^2)) and read by any schedule of any test of the setup.
class ScheduleReader {
 public:
  ScheduleReader(const TestSetup& setup, const SampleSetup& sample, std::int64_t size_count);
  ~ScheduleReader();
  std::vector<Reading> readings(const std::string& test, const ReadingSchedule& schedule) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// The truth grid over [low, high]: log-spaced points, the table's own points within the range
// (where a piecewise-linear curve's largest gap to a straight segment lies) and both ends.
TruthGrid truth_grid(const GradingConfig& grading, double low, double high);

}  // namespace sedem
