#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "core/run/stage_setups.h"
#include "core/sample/placement.h"
#include "core/sample/quasi_random.h"
#include "core/sample/sample_builder.h"
#include "core/scene/scene_loader.h"
#include "tests/sample/placement_checks.h"

namespace sedem {
namespace {

// The first points of R2 from the origin, by hand: i (1/g, 1/g^2) mod 1 with
// 1/g = 0.754877666..., 1/g^2 = 0.569840291...
TEST(QuasiRandom, R2PointsAreTheKroneckerSequenceOfThePlasticNumber) {
  const UnitPoint p1 = r2_point(1, {});
  EXPECT_NEAR(p1.u, 0.7548776662, 1e-10);
  EXPECT_NEAR(p1.v, 0.5698402910, 1e-10);
  const UnitPoint p2 = r2_point(2, {});
  EXPECT_NEAR(p2.u, 0.5097553325, 1e-10);  // 1.5097553325 mod 1
  EXPECT_NEAR(p2.v, 0.1396805820, 1e-10);  // 1.1396805820 mod 1
  const UnitPoint shifted = r2_point(1, {0.5, 0.5});
  EXPECT_NEAR(shifted.u, 0.2548776662, 1e-10);
  EXPECT_NEAR(shifted.v, 0.0698402910, 1e-10);
  const UnitPoint far = r2_point(10'000'000, {});  // 7548776.66246692... mod 1
  EXPECT_NEAR(far.u, 0.6624669276, 1e-7);
}

// A sample of `sizes` log-uniform sizes from 2.5 to 70 um, `count` particles, equal mass.
Sample many_sizes(const std::string& method, std::int64_t count, int sizes, int seed) {
  return build_sample(sample_setup(
      parse_scene("[sample]\nsimulated_count = " + std::to_string(count) +
                      "\nsize_count = " + std::to_string(sizes) +
                      "\nseed = " + std::to_string(seed) + "\n[sample.placement]\nmethod = \"" +
                      method + "\"\n[sample.grading]\nfamily = \"log_uniform\"\n",
                  "ld.toml")));
}

// Deviation of each size's count in circles of the pipette's size (radius 1.495 cm, all
// inside the section) from its expectation, the size's count times the circle's share of
// the plane; root mean square over sizes, 12 heights and 3 seeds, divided by the binomial
// standard deviation sqrt(L p (1 - p)) that independent random points would give.
double circle_count_deviation(const std::string& method) {
  const Cylinder c;
  const double radius = 0.01495;
  const double share = std::numbers::pi * radius * radius / (c.diameter * c.height);
  double squares = 0, binomial = 0;
  for (int seed = 1; seed <= 3; ++seed) {
    const Sample s = many_sizes(method, 8000, 20, seed);
    for (int h = 0; h < 12; ++h) {
      const double yc = radius + (c.height - 2 * radius) * (h + 0.5) / 12.0;
      std::vector<long> in(s.classes.size(), 0);
      for (std::size_t i = 0; i < s.particles.size(); ++i) {
        const double dx = s.particles.x[i], dy = s.particles.y[i] - yc;
        if (dx * dx + dy * dy <= radius * radius) in[std::size_t(s.particles.size_class[i])] += 1;
      }
      for (std::size_t k = 0; k < s.classes.size(); ++k) {
        const double expected = double(s.classes[k].simulated_count) * share;
        squares += (double(in[k]) - expected) * (double(in[k]) - expected);
        binomial += expected * (1 - share);
      }
    }
  }
  return std::sqrt(squares / binomial);
}

// 8000 particles in 20 sizes (about 400 each, 10 in a circle): the low-discrepancy counts
// are off by about a third of what random points would give (measured 0.37), while the
// stratified placement, random within its cells, is off by nearly as much as random points
// (measured 0.82): the test tells the two apart.
TEST(LowDiscrepancyPlacement, EachSizeCountsTrueInThePipettesCircle) {
  const double low = circle_count_deviation("low_discrepancy");
  const double stratified = circle_count_deviation("stratified");
  std::printf("circle counts, rms deviation / binomial sd: low_discrepancy %.3f, stratified %.3f\n",
              low, stratified);
  EXPECT_LT(low, 0.45);
  EXPECT_GT(stratified, 0.7);
}

// Largest deviation, over horizontal bands a tenth of the height, of each size's count and
// of the count of all sizes finer than it (what a test reads once the coarser ones have
// settled) from its share, in units of the binomial sd of random points: {sizes, runs}.
std::pair<double, double> band_count_deviation(const std::string& method) {
  const Cylinder c;
  constexpr int kBands = 10;
  const double share = 1.0 / kBands;
  double by_size = 0, by_run = 0;
  for (int seed = 1; seed <= 3; ++seed) {
    const Sample s = many_sizes(method, 8000, 20, seed);
    const std::size_t sizes = s.classes.size();
    std::vector<std::vector<long>> in(sizes, std::vector<long>(kBands, 0));
    for (std::size_t i = 0; i < s.particles.size(); ++i) {
      const auto band = std::min(kBands - 1, int(s.particles.y[i] / c.height * kBands));
      in[std::size_t(s.particles.size_class[i])][std::size_t(band)] += 1;
    }
    long run_total = 0;
    std::vector<long> run(kBands, 0);
    for (std::size_t k = 0; k < sizes; ++k) {
      const auto count = double(s.classes[k].simulated_count);
      run_total += s.classes[k].simulated_count;
      for (std::size_t b = 0; b < kBands; ++b) {
        run[b] += in[k][b];
        const double sd = std::sqrt(count * share * (1 - share));
        const double run_sd = std::sqrt(double(run_total) * share * (1 - share));
        by_size = std::max(by_size, std::abs(double(in[k][b]) - count * share) / sd);
        by_run = std::max(by_run, std::abs(double(run[b]) - double(run_total) * share) / run_sd);
      }
    }
  }
  return {by_size, by_run};
}

// 8000 particles in 20 sizes, bands a tenth of the height (about 40 particles of a size in
// each): the worst low-discrepancy count is off by about half a binomial sd (measured 0.52
// by size, 0.45 by run), where the largest of these 600 counts from random points would be
// off by about three sd and the stratified placement's, already stratified over its rows,
// by about one (measured 0.99 and 0.90).
TEST(LowDiscrepancyPlacement, EachSizeAndEachFinerRunCountsTrueInEveryBand) {
  const auto [size_low, run_low] = band_count_deviation("low_discrepancy");
  const auto [size_stratified, run_stratified] = band_count_deviation("stratified");
  std::printf(
      "band counts, largest deviation / binomial sd: low_discrepancy %.3f (sizes) "
      "%.3f (runs), stratified %.3f %.3f\n",
      size_low, run_low, size_stratified, run_stratified);
  EXPECT_LT(size_low, 0.8);
  EXPECT_LT(run_low, 0.8);
}

// Brute force over every pair, in a small dense section (a third of the plane covered): the
// points that would overlap move to free places nearby.
TEST(LowDiscrepancyPlacement, NoOverlapAndInsideTheWallsBottomAndSurface) {
  const Cylinder c = test::small_dense_section();
  Particles p;
  p.resize(3000);
  for (std::size_t i = 0; i < p.size(); ++i) p.diameter[i] = (i < 1500 ? 12e-6 : 40e-6);
  place_low_discrepancy(p, c, 3);
  EXPECT_GT(area_fraction(p, c), 0.3);
  test::expect_inside_and_apart(p, c);
}

// A dilute sample: every particle sits exactly on its point (none had to move), which is
// the band's R2 point mapped into the span its centre may take.
TEST(LowDiscrepancyPlacement, DiluteParticlesSitOnTheirPoints) {
  const Cylinder c;
  Particles p;
  p.resize(5000);
  std::fill(p.diameter.begin(), p.diameter.end(), 20e-6);
  place_low_discrepancy(p, c, 11);
  Particles q = p;
  place_low_discrepancy(q, c, 11);
  EXPECT_EQ(p.x, q.x);
  EXPECT_EQ(p.y, q.y);
  // Seven bands (H / B = 7.2): particles 0 and 7 share band 0, at points 0 and 1 of its
  // sequence, one R2 step apart: their offsets differ by (1/g, 1/g^2) mod 1 of the band.
  const double r = 10e-6;
  const double width = c.diameter - 2 * r, band = (c.height - 2 * r) / 7;
  auto frac = [](double v) { return v - std::floor(v); };
  EXPECT_NEAR(frac((p.x[7] - p.x[0]) / width), 0.7548776662, 1e-9);
  EXPECT_NEAR(frac((p.y[7] - p.y[0]) / band), 0.5698402910, 1e-9);
}

TEST(LowDiscrepancyPlacement, SameSeedSameSampleOtherSeedOtherSample) {
  const std::string toml =
      "[sample]\nsimulated_count = 5000\n[sample.placement]\n"
      "method = \"low_discrepancy\"\n";
  const Sample a = build_sample(sample_setup(parse_scene(toml, "a.toml", {"sample.seed=42"})));
  const Sample b = build_sample(sample_setup(parse_scene(toml, "b.toml", {"sample.seed=42"})));
  const Sample c = build_sample(sample_setup(parse_scene(toml, "c.toml", {"sample.seed=43"})));
  EXPECT_EQ(a.particles.x, b.particles.x);
  EXPECT_EQ(a.particles.y, b.particles.y);
  std::size_t moved = 0;
  for (std::size_t i = 0; i < a.particles.size(); ++i)
    moved += a.particles.x[i] != c.particles.x[i] ? 1 : 0;
  EXPECT_GT(moved, a.particles.size() * 99 / 100);
  // And the key chooses the method: the stratified sample of the same seed differs.
  const Sample s = build_sample(sample_setup(
      parse_scene(toml, "s.toml", {"sample.seed=42", "sample.placement.method=stratified"})));
  EXPECT_NE(a.particles.x, s.particles.x);
}

// The paper's cylinder, 10^6 particles in 220 sizes: placed as quickly as the stratified way.
TEST(LowDiscrepancyPlacement, AMillionParticleSampleIsQuick) {
  const Scene scene = parse_scene(
      "[sample]\nsimulated_count = 1000000\n[sample.placement]\nmethod = \"low_discrepancy\"\n",
      "million.toml");
  const auto start = std::chrono::steady_clock::now();
  const Sample s = build_sample(sample_setup(scene));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("built a 1e6-particle low-discrepancy sample in %.2f s\n", seconds);
  EXPECT_EQ(s.particles.size(), 1000000u);
  EXPECT_LT(seconds, 10.0);
}

}  // namespace
}  // namespace sedem
