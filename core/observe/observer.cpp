#include "core/observe/observer.h"

#include <algorithm>
#include <cmath>

namespace sedem {

std::vector<double> every(double interval, double end) {
  std::vector<double> times;
  const auto n = static_cast<long>(std::floor(end / interval + 1e-9));
  for (long k = 0; k <= n; ++k) times.push_back(double(k) * interval);
  if (times.back() < end - 1e-9 * std::max(1.0, end)) times.push_back(end);
  return times;
}

std::vector<double> merge_times(const std::vector<std::vector<double>>& lists, double tolerance) {
  std::vector<double> all;
  for (const auto& l : lists) all.insert(all.end(), l.begin(), l.end());
  std::sort(all.begin(), all.end());
  std::vector<double> merged;
  for (double t : all)
    if (merged.empty() || t - merged.back() > tolerance * std::max(1.0, std::fabs(t)))
      merged.push_back(t);
  return merged;
}

bool contains_time(const std::vector<double>& times, double t, double tolerance) {
  auto it = std::lower_bound(times.begin(), times.end(), t - tolerance * std::max(1.0, t));
  return it != times.end() && std::fabs(*it - t) <= tolerance * std::max(1.0, std::fabs(t));
}

}  // namespace sedem
