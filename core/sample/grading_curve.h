#pragma once

#include "core/sample/sample_config.h"

namespace sedem {

// Percent finer by mass against diameter (SI), from a table of points interpolated linearly
// in log d, or from a named family truncated to [min, max] and renormalised so that it runs
// from 0 at the smallest diameter to 100 at the largest. The config must be valid
// (check_scene); the curve only evaluates it.
class GradingCurve {
 public:
  explicit GradingCurve(const GradingConfig& config);

  double percent_finer(double diameter) const;
  double min_diameter() const { return min_; }
  double max_diameter() const { return max_; }
  // Share of the untruncated family's mass that lies in [min, max] (1 for a table, a
  // log-uniform curve or a single size). Near 0 the family says nothing about this range.
  double captured_share() const { return hi_ - lo_; }

 private:
  double family_cdf(double diameter) const;  // the untruncated family, 0..1

  GradingConfig config_;
  double min_ = 0, max_ = 0;
  double lo_ = 0, hi_ = 1;  // family_cdf at min_ and max_
};

}  // namespace sedem
