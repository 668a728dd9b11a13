#include "bench/validation/curve_checks.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace sedem::validation {

namespace {

// Percent finer ordered by diameter (ascending).
std::vector<double> by_diameter(const TestReadings& curve) {
  std::vector<Reading> rows = curve.rows;
  std::stable_sort(rows.begin(), rows.end(),
                   [](const Reading& a, const Reading& b) { return a.diameter < b.diameter; });
  std::vector<double> w;
  for (const auto& r : rows) w.push_back(r.percent_finer);
  return w;
}

template <class Keep>
TestReadings filtered(const TestReadings& curve, Keep keep) {
  TestReadings out = curve;
  out.rows.clear();
  for (const auto& r : curve.rows)
    if (keep(r)) out.rows.push_back(r);
  return out;
}

std::vector<double> ranks(const std::vector<double>& v) {
  std::vector<std::size_t> order(v.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return v[a] < v[b]; });
  std::vector<double> rank(v.size());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && v[order[j + 1]] == v[order[i]]) ++j;
    for (std::size_t k = i; k <= j; ++k) rank[order[k]] = 0.5 * double(i + j);
    i = j + 1;
  }
  return rank;
}

}  // namespace

TestReadings large_sizes(const TestReadings& curve, double min_diameter) {
  return filtered(curve, [&](const Reading& r) { return r.diameter >= min_diameter; });
}

TestReadings up_to(const TestReadings& curve, double time) {
  return filtered(curve, [&](const Reading& r) { return r.time <= time * (1 + 1e-12); });
}

double roughness(const TestReadings& curve) {
  const auto w = by_diameter(curve);
  if (w.size() < 3) return 0;
  std::vector<double> second;
  for (std::size_t i = 1; i + 1 < w.size(); ++i) second.push_back(w[i + 1] - 2 * w[i] + w[i - 1]);
  return root_mean_square(second);
}

double excess_variation(const TestReadings& curve) {
  const auto w = by_diameter(curve);
  if (w.size() < 2) return 0;
  double total = 0;
  for (std::size_t i = 1; i < w.size(); ++i) total += std::abs(w[i] - w[i - 1]);
  return total - std::abs(w.back() - w.front());
}

TestReadings truth_at(const TestReadings& curve, const std::vector<SizeClass>& classes) {
  TestReadings out = curve;
  out.extra_columns.clear();
  for (auto& r : out.rows) {
    r.percent_finer = true_percent_finer(classes, r.diameter);
    r.extra.clear();
  }
  return out;
}

std::vector<double> deviations_from_truth(const TestReadings& curve,
                                          const std::vector<SizeClass>& classes) {
  return differences(curve, truth_at(curve, classes));
}

std::vector<double> differences(const TestReadings& a, const TestReadings& b) {
  if (a.rows.size() != b.rows.size())
    throw std::invalid_argument("differences: " + a.test + " has " + std::to_string(a.rows.size()) +
                                " readings, the other " + std::to_string(b.rows.size()));
  std::vector<double> d;
  for (std::size_t k = 0; k < a.rows.size(); ++k)
    d.push_back(a.rows[k].percent_finer - b.rows[k].percent_finer);
  return d;
}

double mean(const std::vector<double>& v) {
  return v.empty() ? 0.0 : std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
}

double mean_abs(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += std::abs(x);
  return v.empty() ? 0.0 : s / double(v.size());
}

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

double root_mean_square(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x * x;
  return v.empty() ? 0.0 : std::sqrt(s / double(v.size()));
}

double rank_correlation(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() != y.size()) throw std::invalid_argument("rank_correlation: lengths differ");
  if (x.size() < 2) return 0;
  const auto rx = ranks(x), ry = ranks(y);
  const double mx = mean(rx), my = mean(ry);
  double sxy = 0, sxx = 0, syy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (rx[i] - mx) * (ry[i] - my);
    sxx += (rx[i] - mx) * (rx[i] - mx);
    syy += (ry[i] - my) * (ry[i] - my);
  }
  return sxx > 0 && syy > 0 ? sxy / std::sqrt(sxx * syy) : 0.0;
}

std::vector<SizeClass> classes_from_true_curve(const std::vector<GradingPoint>& curve) {
  std::vector<GradingPoint> sorted = curve;
  std::sort(sorted.begin(), sorted.end(),
            [](const GradingPoint& a, const GradingPoint& b) { return a.diameter < b.diameter; });
  std::vector<SizeClass> classes;
  double below = 0;
  for (const auto& p : sorted) {
    SizeClass c;
    c.diameter = p.diameter;
    c.mass_fraction = (p.percent_finer - below) / 100.0;
    below = p.percent_finer;
    classes.push_back(c);
  }
  return classes;
}

}  // namespace sedem::validation
