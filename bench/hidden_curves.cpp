#include "bench/hidden_curves.h"

#include <cmath>
#include <random>
#include <sstream>

namespace sedem::bench {

namespace {

std::string toml_list(const std::vector<double>& v) {
  std::ostringstream s;
  s.precision(10);
  s << '[';
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i) s << ',';
    s << v[i];
  }
  return s.str() + ']';
}

// A mixture of log-normal modes (median, log-spread, mass share) as a table of points spaced
// evenly in log d over +-3.5 spreads of the outer modes.
HiddenCurve lognormal_mixture(const std::string& name, const std::vector<double>& median,
                              const std::vector<double>& spread, const std::vector<double>& share) {
  double lo = 1e300, hi = 0;
  for (std::size_t m = 0; m < median.size(); ++m) {
    lo = std::min(lo, std::log(median[m]) - 3.5 * spread[m]);
    hi = std::max(hi, std::log(median[m]) + 3.5 * spread[m]);
  }
  HiddenCurve c{name, {}, {}};
  const int points = 48;
  for (int i = 0; i <= points; ++i) {
    const double ln_d = lo + (hi - lo) * i / points;
    double finer = 0, total = 0;
    for (std::size_t m = 0; m < median.size(); ++m) {
      finer += share[m] * 0.5 * std::erfc(-(ln_d - std::log(median[m])) / (spread[m] * M_SQRT2));
      total += share[m];
    }
    double p = 100 * finer / total;
    if (i == 0) p = 0;
    if (i == points) p = 100;
    c.diameter_um.push_back(std::exp(ln_d));
    c.percent_finer.push_back(p);
  }
  return c;
}

}  // namespace

std::vector<std::string> HiddenCurve::overrides() const {
  return {"sample.grading.family=\"table\"",
          "sample.grading.diameters_um=" + toml_list(diameter_um),
          "sample.grading.percent_finer=" + toml_list(percent_finer)};
}

std::vector<HiddenCurve> hidden_curves(int variants, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto uniform = [&](double a, double b) {
    return std::uniform_real_distribution<double>(a, b)(rng);
  };
  std::vector<HiddenCurve> curves;
  for (int v = 1; v <= variants; ++v) {
    std::string tag = "-";
    tag += std::to_string(v);
    {  // most of the mass within a factor of 1.2-1.5, the rest spread thinly on both sides
      const double knee = uniform(12, 45), width = uniform(1.2, 1.5), inside = uniform(75, 92);
      const double below = uniform(0.3, 0.7) * (100 - inside);
      curves.push_back({"narrow" + tag,
                        {knee / uniform(4, 8), knee, knee * width, knee * width * uniform(1.5, 3)},
                        {0, below, below + inside, 100}});
    }
    {  // no mass between gap and gap * ratio
      const double gap = uniform(6, 20), ratio = uniform(2, 4), finer = uniform(30, 60);
      curves.push_back({"gap-graded" + tag,
                        {gap / uniform(3, 6), gap, gap * ratio, gap * ratio * uniform(2, 4)},
                        {0, finer, finer, 100}});
    }
    curves.push_back(lognormal_mixture("bimodal" + tag, {uniform(3, 8), uniform(25, 60)},
                                       {uniform(0.2, 0.5), uniform(0.2, 0.5)},
                                       {uniform(0.3, 0.7), 1.0}));
    curves.push_back({"log-uniform" + tag, {uniform(1, 4), uniform(40, 120)}, {0, 100}});
    {  // 40-70 % clay (finer than 2 um), the rest silt to fine sand
      const double clay = uniform(40, 70), silt = clay + uniform(0.6, 0.9) * (100 - clay);
      curves.push_back({"clay-heavy" + tag,
                        {uniform(0.3, 0.8), 2.0, uniform(15, 30), uniform(60, 100)},
                        {0, clay, silt, 100}});
    }
  }
  return curves;
}

}  // namespace sedem::bench
