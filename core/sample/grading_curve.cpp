#include "core/sample/grading_curve.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sedem {

GradingCurve::GradingCurve(const GradingConfig& config) : config_(config) {
  if (config_.family == "table") {
    min_ = config_.diameters.front();
    max_ = config_.diameters.back();
  } else if (config_.family == "single") {
    min_ = max_ = config_.diameter;
  } else {
    min_ = config_.min_diameter;
    max_ = config_.max_diameter;
    lo_ = family_cdf(min_);
    hi_ = family_cdf(max_);
  }
}

double GradingCurve::family_cdf(double d) const {
  const auto& f = config_.family;
  if (f == "log_normal") {
    const double z = std::log(d / config_.median_diameter) / config_.spread;
    return 0.5 * std::erfc(-z / std::numbers::sqrt2);
  }
  if (f == "rosin_rammler")
    return -std::expm1(-std::pow(d / config_.median_diameter, config_.spread));
  // log_uniform: already 0 at min and 1 at max.
  return std::log(d / config_.min_diameter) / std::log(config_.max_diameter / config_.min_diameter);
}

double GradingCurve::percent_finer(double d) const {
  if (d < min_) return 0;
  if (d >= max_) return 100;
  if (config_.family == "table") {
    const auto& ds = config_.diameters;
    const auto& ps = config_.percent_finer;
    const std::size_t i = std::size_t(std::upper_bound(ds.begin(), ds.end(), d) - ds.begin());
    const double t = std::log(d / ds[i - 1]) / std::log(ds[i] / ds[i - 1]);
    return ps[i - 1] + t * (ps[i] - ps[i - 1]);
  }
  return std::clamp(100.0 * (family_cdf(d) - lo_) / (hi_ - lo_), 0.0, 100.0);
}

}  // namespace sedem
