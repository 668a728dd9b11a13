#include "core/sample/sample_builder.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "core/scene/scene.h"

namespace sedem {
namespace {

// Percent finer at diameter d: the table interpolated linearly in log d.
double percent_finer(const GradingConfig& g, double d) {
  const auto& ds = g.diameters;
  const auto& ps = g.percent_finer;
  if (d <= ds.front()) return ps.front();
  if (d >= ds.back()) return ps.back();
  auto it = std::upper_bound(ds.begin(), ds.end(), d);
  std::size_t i = std::size_t(it - ds.begin());
  double t = std::log(d / ds[i - 1]) / std::log(ds[i] / ds[i - 1]);
  return ps[i - 1] + t * (ps[i] - ps[i - 1]);
}

}  // namespace

Sample build_sample(const Scene& scene) {
  const auto& cfg = scene.sample;
  const auto& g = cfg.grading;
  Sample sample;
  sample.particle_density = cfg.particle_density;
  sample.section_mass = cfg.total_mass * scene.cylinder.section_fraction;

  // n_phi diameters spaced evenly in log d; class n holds the mass between the midpoints.
  const std::size_t n = std::size_t(cfg.size_count);
  const double d0 = g.diameters.front(), d1 = g.diameters.back();
  std::vector<double> edges(n + 1);
  for (std::size_t k = 0; k <= n; ++k)
    edges[k] = d0 * std::pow(d1 / d0, n == 0 ? 0.0 : double(k) / double(n));
  double total_real = 0;
  for (std::size_t k = 0; k < n; ++k) {
    SizeClass c;
    c.diameter = std::sqrt(edges[k] * edges[k + 1]);
    c.mass_fraction = (percent_finer(g, edges[k + 1]) - percent_finer(g, edges[k])) / 100.0;
    if (c.mass_fraction <= 0) continue;
    const double grain_mass =
        cfg.particle_density * std::numbers::pi / 6.0 * std::pow(c.diameter, 3);
    c.real_count = sample.section_mass * c.mass_fraction / grain_mass;  // Eq. 15
    total_real += c.real_count;
    sample.classes.push_back(c);
  }

  // Equal mass per simulated particle: each class gets particles in proportion to its mass.
  const double target = double(cfg.simulated_count);
  for (auto& c : sample.classes) {
    double share = cfg.weighting == "uniform_count" ? c.real_count / total_real : c.mass_fraction;
    c.simulated_count = std::max(1L, std::lround(share * target));
    c.weight = c.real_count / double(c.simulated_count);
  }

  std::size_t total = 0;
  for (const auto& c : sample.classes) total += std::size_t(c.simulated_count);
  auto& p = sample.particles;
  p.resize(total);
  std::mt19937_64 rng(std::uint64_t(cfg.seed));
  const double half = scene.cylinder.half_width();
  std::size_t i = 0;
  double covered = 0;
  for (std::size_t k = 0; k < sample.classes.size(); ++k) {
    const auto& c = sample.classes[k];
    const double r = 0.5 * c.diameter;
    std::uniform_real_distribution<double> ux(-half + r, half - r),
        uy(r, scene.cylinder.height - r);
    for (long j = 0; j < c.simulated_count; ++j, ++i) {
      p.x[i] = ux(rng);
      p.y[i] = uy(rng);
      p.diameter[i] = c.diameter;
      p.weight[i] = c.weight;
      p.size_class[i] = std::int32_t(k);
      p.id[i] = std::uint32_t(i);
      covered += std::numbers::pi * r * r;
    }
  }
  sample.area_fraction = covered / (scene.cylinder.diameter * scene.cylinder.height);
  return sample;
}

}  // namespace sedem
