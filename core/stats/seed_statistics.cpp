#include "core/stats/seed_statistics.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace sedem {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The continued fraction of the incomplete beta function (modified Lentz), which converges
// fast for x < (a + 1) / (a + b + 2).
double beta_continued_fraction(double a, double b, double x) {
  constexpr double tiny = 1e-300;
  double c = 1, d = 1 - (a + b) * x / (a + 1);
  if (std::abs(d) < tiny) d = tiny;
  d = 1 / d;
  double h = d;
  for (int m = 1; m <= 1000; ++m) {
    const double m2 = 2.0 * m;
    for (const double coefficient : {m * (b - m) * x / ((a + m2 - 1) * (a + m2)),
                                     -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1))}) {
      d = 1 + coefficient * d;
      if (std::abs(d) < tiny) d = tiny;
      c = 1 + coefficient / c;
      if (std::abs(c) < tiny) c = tiny;
      d = 1 / d;
      h *= d * c;
    }
    if (std::abs(d * c - 1) < 1e-16) break;
  }
  return h;
}

// The regularised incomplete beta function I_x(a, b).
double incomplete_beta(double a, double b, double x) {
  if (x <= 0) return 0;
  if (x >= 1) return 1;
  const double log_front =
      std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x);
  if (x < (a + 1) / (a + b + 2)) return std::exp(log_front) * beta_continued_fraction(a, b, x) / a;
  return 1 - std::exp(log_front) * beta_continued_fraction(b, a, 1 - x) / b;
}

}  // namespace

double student_t_quantile(double level, int dof) {
  if (!(level > 0 && level < 1))
    throw std::invalid_argument("student_t_quantile: level must lie in (0, 1)");
  if (dof < 1) throw std::invalid_argument("student_t_quantile: dof must be at least 1");
  // P(|T| > t) = I_x(dof/2, 1/2) with x = dof / (dof + t^2), increasing in x: bisecting on x
  // in [0, 1] stays bounded however large t is (dof = 1 at a high level).
  const double nu = dof, tail = 1 - level;
  double lo = 0, hi = 1;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid == lo || mid == hi) break;
    (incomplete_beta(0.5 * nu, 0.5, mid) < tail ? lo : hi) = mid;
  }
  const double x = 0.5 * (lo + hi);
  return std::sqrt(nu * (1 - x) / x);
}

double Interval::half_width() const {
  return 0.5 * (high - low);
}

Interval mean_interval(const std::vector<double>& values, double level) {
  Interval r;
  double sum = 0;
  for (const double v : values)
    if (!std::isnan(v)) sum += v, ++r.n;
  if (r.n == 0) {
    r.mean = r.sd = r.low = r.high = kNaN;
    return r;
  }
  r.mean = sum / double(r.n);
  if (r.n == 1) {
    r.sd = r.low = r.high = kNaN;
    return r;
  }
  double squares = 0;
  for (const double v : values)
    if (!std::isnan(v)) squares += (v - r.mean) * (v - r.mean);
  r.sd = std::sqrt(squares / double(r.n - 1));
  const double half = student_t_quantile(level, int(r.n - 1)) * r.sd / std::sqrt(double(r.n));
  r.low = r.mean - half;
  r.high = r.mean + half;
  return r;
}

std::size_t count_for_half_width(double sd, double target, double level) {
  constexpr std::size_t largest = 1000000;
  if (!std::isfinite(sd) || sd < 0 || !(target > 0)) return 0;
  auto fits = [&](std::size_t n) {
    return student_t_quantile(level, int(n - 1)) * sd / std::sqrt(double(n)) <= target;
  };
  if (!fits(largest)) return 0;
  // t_{n-1} / sqrt(n) falls as n grows: the smallest n that fits, by bisection.
  std::size_t lo = 1, hi = largest;  // lo does not fit (no interval from one value), hi fits
  while (hi - lo > 1) {
    const std::size_t mid = lo + (hi - lo) / 2;
    (fits(mid) ? hi : lo) = mid;
  }
  return hi;
}

}  // namespace sedem
