#pragma once

#include <cstddef>
#include <vector>

namespace sedem {

// The spread of a result over runs that differ only in their seed: how far one run's number
// can be trusted, and how many seeds a tighter interval would take.

// Two-sided Student-t quantile: the t with P(|T| <= t) = level for `dof` degrees of freedom
// (dof >= 1, 0 < level < 1; otherwise std::invalid_argument).
double student_t_quantile(double level, int dof);

// Mean, sample standard deviation and the two-sided `level` confidence interval of the mean
// (mean +- t * sd / sqrt(n)) of values; NaN values are skipped (n counts the rest). n == 0: all
// NaN; n == 1: sd, low, high NaN.
struct Interval {
  std::size_t n = 0;
  double mean = 0, sd = 0, low = 0, high = 0;
  double half_width() const;
};
Interval mean_interval(const std::vector<double>& values, double level = 0.95);

// The number of values at which an interval of this spread would have half-width `target`
// (n with t_{n-1} sd / sqrt(n) <= target, smallest such n >= 2, searched up to 1e6; 0 if sd is
// NaN, infinite or negative, target <= 0, or no n up to 1e6 is enough).
std::size_t count_for_half_width(double sd, double target, double level = 0.95);

}  // namespace sedem
