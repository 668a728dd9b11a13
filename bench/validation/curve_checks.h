#pragma once

#include <string>
#include <vector>

#include "core/instruments/granulometry.h"
#include "core/model/sample.h"

namespace sedem::validation {

// Measures of one grading curve (a test's readings, in reading order) used to weigh the
// paper's conclusions. All in percentage points (pp) of percent finer.

// The readings with phi_o >= min_diameter (the "large sizes", read early in the test).
TestReadings large_sizes(const TestReadings& curve, double min_diameter);
// The readings taken at or before `time` (s).
TestReadings up_to(const TestReadings& curve, double time);

// Root mean square of the second differences of w_o, the points ordered by diameter: 0 for a
// straight line (or fewer than three points), large for a curve that bends back and forth.
double roughness(const TestReadings& curve);

// Total variation of w_o along the diameter beyond what a monotone curve between the same
// ends needs: 0 for any monotone curve, twice the height of each spurious wiggle otherwise.
double excess_variation(const TestReadings& curve);

// The true curve sampled at the test's diameters, as readings at the test's times.
TestReadings truth_at(const TestReadings& curve, const std::vector<SizeClass>& classes);

// w_o(test) - w_o(true) at each reading's phi_o. Negative: the test finds less mass finer
// than phi_o than there is, i.e. more coarse mass than the sample holds.
std::vector<double> deviations_from_truth(const TestReadings& curve,
                                          const std::vector<SizeClass>& classes);
// w_o(a) - w_o(b) reading by reading (same times).
std::vector<double> differences(const TestReadings& a, const TestReadings& b);

double mean(const std::vector<double>& v);
double mean_abs(const std::vector<double>& v);
double max_abs(const std::vector<double>& v);
double root_mean_square(const std::vector<double>& v);

// Spearman's rank correlation of two equally long lists (ties share their mean rank); 0 when
// either list is constant or shorter than two.
double rank_correlation(const std::vector<double>& x, const std::vector<double>& y);

// Size classes rebuilt from a true curve given as (diameter, cumulative percent finer)
// points, such as granulometry.csv holds.
std::vector<SizeClass> classes_from_true_curve(const std::vector<GradingPoint>& curve);

}  // namespace sedem::validation
