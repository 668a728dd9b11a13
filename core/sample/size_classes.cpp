#include "core/sample/size_classes.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

namespace sedem {

std::vector<double> discrete_diameters(const GradingCurve& curve, std::int64_t size_count) {
  const double d0 = curve.min_diameter(), d1 = curve.max_diameter();
  if (d0 == d1) return {d0};
  if (size_count <= 1) return {std::sqrt(d0 * d1)};
  std::vector<double> phi(static_cast<std::size_t>(size_count));
  const double steps = double(size_count - 1);
  for (std::size_t n = 0; n < phi.size(); ++n) phi[n] = d0 * std::pow(d1 / d0, double(n) / steps);
  phi.back() = d1;  // exact, whatever pow rounds to
  return phi;
}

std::vector<SizeClass> discretise(const GradingCurve& curve, std::int64_t size_count,
                                  double section_mass, double particle_density) {
  const std::vector<double> phi = discrete_diameters(curve, size_count);
  std::vector<SizeClass> classes;
  double w_prev = 0;
  for (std::size_t n = 0; n < phi.size(); ++n) {
    const double w = n + 1 < phi.size() ? curve.percent_finer(0.5 * (phi[n] + phi[n + 1])) : 100.0;
    SizeClass c;
    c.diameter = phi[n];
    c.mass_fraction = (w - w_prev) / 100.0;
    w_prev = w;
    if (!(c.mass_fraction > 0)) continue;
    c.real_count = section_mass * c.mass_fraction / grain_mass(c.diameter, particle_density);
    classes.push_back(c);
  }
  return classes;
}

std::vector<double> simulated_shares(const std::vector<SizeClass>& classes,
                                     const std::string& weighting) {
  std::vector<double> share(classes.size());
  for (std::size_t k = 0; k < classes.size(); ++k) {
    if (weighting == "uniform_count")
      share[k] = classes[k].real_count;
    else if (weighting == "equal_per_size")
      share[k] = 1;
    else
      share[k] = classes[k].mass_fraction;
  }
  const double sum = std::accumulate(share.begin(), share.end(), 0.0);
  for (auto& s : share) s /= sum;
  return share;
}

std::int64_t count_for_mass_fraction(const std::vector<SizeClass>& classes,
                                     const std::vector<double>& shares, double mass_fraction,
                                     double particle_density) {
  double real_mass = 0, mass_per_particle = 0;
  for (std::size_t k = 0; k < classes.size(); ++k) {
    const double m = grain_mass(classes[k].diameter, particle_density);
    real_mass += classes[k].real_count * m;
    mass_per_particle += shares[k] * m;
  }
  const double n = std::round(mass_fraction * real_mass / mass_per_particle);
  return n > 9e18 ? INT64_MAX : std::int64_t(n);
}

void assign_counts(std::vector<SizeClass>& classes, const std::vector<double>& shares,
                   std::int64_t total) {
  const std::size_t k_count = classes.size();
  const std::int64_t n_total = std::max<std::int64_t>(total, std::int64_t(k_count));
  // Sizes whose quota is below one particle get exactly one; the rest share what is left in
  // proportion to their shares. Repeat until no new size falls below one.
  std::vector<bool> pinned(k_count, false);
  double free_share = 0;        // share of the sizes not pinned at one particle
  std::int64_t free_count = 0;  // particles left for them
  const auto count_free = [&] {
    free_share = 0;
    free_count = n_total;
    for (std::size_t k = 0; k < k_count; ++k) {
      if (pinned[k])
        free_count -= 1;
      else
        free_share += shares[k];
    }
  };
  for (bool changed = true; changed;) {
    changed = false;
    count_free();
    for (std::size_t k = 0; k < k_count; ++k) {
      if (pinned[k]) continue;
      if (shares[k] / free_share * double(free_count) < 1) pinned[k] = changed = true;
    }
  }
  count_free();
  std::vector<double> remainder(k_count, -1.0);
  std::int64_t given = 0;
  for (std::size_t k = 0; k < k_count; ++k) {
    if (pinned[k]) {
      classes[k].simulated_count = 1;
    } else {
      const double quota = shares[k] / free_share * double(free_count);
      classes[k].simulated_count = long(std::floor(quota));
      remainder[k] = quota - std::floor(quota);
    }
    given += classes[k].simulated_count;
  }
  std::vector<std::size_t> order(k_count);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return remainder[a] > remainder[b]; });
  for (std::size_t i = 0; given < n_total && i < k_count; ++i, ++given)
    classes[order[i]].simulated_count += 1;
  for (auto& c : classes) c.weight = c.real_count / double(c.simulated_count);
}

}  // namespace sedem
