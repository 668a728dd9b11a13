#pragma once

#include <string>
#include <vector>

#include "bench/validation/run_folder.h"

namespace sedem::validation {

// The paper's conclusions (Sects. 5.4, 5.5 and 6), each as numbers taken from run folders and
// a rule that turns them into a verdict. Rows are per sample and test; every threshold is a
// named constant below, printed with the verdict.

enum class Verdict { supports, contradicts, inconclusive };
const char* to_string(Verdict v);

// "Large sizes": readings with phi_o at or above this (the first minutes of each test).
inline constexpr double kLargeDiameter = 20e-6;  // m
// Oscillation smaller than this is not told apart from a smooth curve.
inline constexpr double kOscillationFloor = 1.0;  // pp
// A "reasonable" result: within this of the reference solution.
inline constexpr double kReasonableError = 5.0;  // pp
// A rank correlation beyond +-this between depth and deviation is a trend.
inline constexpr double kTrendCorrelation = 0.3;

// 0. "Inside the range allowed by the standards, small particles are easier to measure than
// large ones": the mean |w_o(test) - w_o(true)| of the readings below and at or above
// kLargeDiameter.
struct SizeRangeRow {
  std::string sample, test;
  std::size_t small_readings = 0, large_readings = 0;
  double small_deviation = 0, large_deviation = 0;
};
std::vector<SizeRangeRow> size_range_rows(const std::vector<RunFolder>& runs);
// Over the rows with readings on both sides: supports when at least two thirds measure the
// small sizes better, contradicts when two thirds measure them worse.
Verdict size_range_verdict(const std::vector<SizeRangeRow>& rows);

// 1. "The hydrometer test smoothes the real granulometry": a test's roughness (RMS second
// difference of w_o along the diameter) minus that of the true curve at the same diameters.
// Negative: smoother than the truth.
struct SmoothingRow {
  std::string sample, test;
  double roughness = 0, truth_roughness = 0, mean_abs_deviation = 0;
  double index() const { return roughness - truth_roughness; }
};
std::vector<SmoothingRow> smoothing_rows(const std::vector<RunFolder>& runs);
// Supports when, in most samples, the hydrometer is smoother than the truth and smoother
// (relative to the truth) than both other tests; contradicts when in most samples it is
// neither.
Verdict smoothing_verdict(const std::vector<SmoothingRow>& rows);

// 2. "The buoyancy and pipette tests oscillate for large sizes": over the large-size
// readings, the RMS of DEM minus reference (the simulation's scatter around the test's own
// continuum curve) and the excess variation (non-monotone wiggles) of the DEM curve.
struct OscillationRow {
  std::string sample, test;
  std::size_t readings = 0, above_100 = 0;
  double scatter = 0, excess = 0;
};
std::vector<OscillationRow> oscillation_rows(const std::vector<RunFolder>& runs);
// Mean scatter of a test over the samples.
double mean_scatter(const std::vector<OscillationRow>& rows, const std::string& test);
// Supports when buoyancy and pipette both scatter more than the hydrometer and more than
// kOscillationFloor; contradicts when neither scatters more than the hydrometer.
Verdict oscillation_verdict(const std::vector<OscillationRow>& rows);

// 3. "All tests predict larger particles than in reality, with a small accumulated weight":
// the mean signed w_o(test) - w_o(true) over the large-size readings. Negative: the test
// finds coarse mass the sample does not hold.
struct LargeSizeRow {
  std::string sample, test, weighting;
  std::size_t particles = 0, readings = 0;
  double dem_deviation = 0, reference_deviation = 0;
};
std::vector<LargeSizeRow> large_size_rows(const std::vector<RunFolder>& runs);
// Supports when at least two thirds of the rows (with readings) are negative, contradicts
// when at least two thirds are positive.
Verdict large_size_verdict(const std::vector<LargeSizeRow>& rows);

// 4. "In the buoyancy and pipette tests, the higher the measurement point, the more accurate":
// the same particles read at several depths; accuracy is the mean |w_o(test) - w_o(true)|.
struct DepthRow {
  std::string sample, test;
  double depth_fraction = 0, depth_m = 0;
  double mean_abs_deviation = 0, max_abs_deviation = 0;  // DEM against the truth
  // The reference (the same instrument on the continuum solution) against the truth: the
  // test's own accuracy at that depth, free of the simulation's scatter.
  double reference_mean_abs_deviation = 0, reference_bias = 0;
};
// Rows of the buoyancy and pipette tests of every run given (the same samples read at
// several depths), sorted by sample, test, depth.
std::vector<DepthRow> depth_rows(const std::vector<RunFolder>& runs);
// Rank correlation of depth and mean deviation (of the DEM, or of the reference), per
// sample and test, averaged.
double depth_trend(const std::vector<DepthRow>& rows, bool reference = false);
// Supports when deeper is worse (trend >= kTrendCorrelation), contradicts when deeper is
// better (<= -kTrendCorrelation).
Verdict depth_verdict(const std::vector<DepthRow>& rows);

// Fig. 12 beside it: how far the largest diameter above a depth is from Eq. 16, relative,
// in the upper, middle and lower third of the column, over the depths where Eq. 16 is below
// the sample's largest grain (deeper, both curves are that grain). NaN for a third with no
// such depth.
struct ProfileGapRow {
  std::string sample;
  double time_s = 0;
  double upper = 0, middle = 0, lower = 0;  // mean relative gap
};
std::vector<ProfileGapRow> profile_gap_rows(const std::vector<RunFolder>& runs);

// 5. "A reduced mass and the early part of the test already give reasonable results": the
// error (DEM against reference) of the readings up to `early_s`, and of runs with fewer
// particles against the full runs of the same samples.
struct EarlyRow {
  std::string sample, test;
  std::size_t early_readings = 0, readings = 0;
  double early_error = 0, error = 0;
  double early_smallest_diameter = 0, smallest_diameter = 0;  // m, how far down the curve
};
std::vector<EarlyRow> early_rows(const std::vector<RunFolder>& runs, double early_s);
struct ReducedRow {
  std::string sample, test;
  std::size_t particles = 0, reduced_particles = 0;
  double wall_s = 0, reduced_wall_s = 0;
  double error = 0, reduced_error = 0;
};
// Pairs each reduced run with the full run of the same scene name.
std::vector<ReducedRow> reduced_rows(const std::vector<RunFolder>& runs,
                                     const std::vector<RunFolder>& reduced);
// Supports when the early readings and the reduced runs (when given) are within
// kReasonableError of the reference in most rows; contradicts when most of both are not.
Verdict early_reduced_verdict(const std::vector<EarlyRow>& early,
                              const std::vector<ReducedRow>& reduced);
// Share (0..1) of rows within kReasonableError.
double share_reasonable(const std::vector<EarlyRow>& rows);
double share_reasonable(const std::vector<ReducedRow>& rows);

}  // namespace sedem::validation
