#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "core/run/stage_setups.h"
#include "core/sample/placement.h"
#include "core/sample/sample_builder.h"
#include "core/scene/scene_loader.h"
#include "tests/sample/placement_checks.h"

namespace sedem {
namespace {

Particles sized(std::size_t n, double diameter) {
  Particles p;
  p.resize(n);
  std::fill(p.diameter.begin(), p.diameter.end(), diameter);
  return p;
}

// Particles per cell of the n_mt x n_mt matrix (cells of the section's aspect ratio).
std::vector<int> per_cell(const Particles& p, const Cylinder& c, std::int64_t side) {
  std::vector<int> count(std::size_t(side * side), 0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto cx = std::int64_t(std::floor((p.x[i] + c.half_width()) / c.diameter * side));
    const auto cy = std::int64_t(std::floor(p.y[i] / c.height * side));
    count[std::size_t(cy * side + cx)] += 1;
  }
  return count;
}

TEST(Placement, PaperRuleGivesACellPerParticle) {
  EXPECT_EQ(cells_per_side(PlacementConfig{}, 1000), 32);  // 31^2 = 961 < 1000 <= 1024
  EXPECT_EQ(cells_per_side(PlacementConfig{}, 1024), 32);
  EXPECT_EQ(cells_per_side(PlacementConfig{}, 1025), 33);
  EXPECT_EQ(cells_per_side(PlacementConfig{}, 1), 1);
  EXPECT_EQ(cells_per_side(PlacementConfig{7, 0.4}, 1000), 7);
}

TEST(Placement, EveryCellHoldsItsShare) {
  const Cylinder c;
  {  // the paper's rule: 1000 particles in 32 x 32 cells, none holds two
    Particles p = sized(1000, 20e-6);
    place_stratified(p, c, PlacementConfig{}, 1);
    const auto count = per_cell(p, c, 32);
    EXPECT_EQ(std::count(count.begin(), count.end(), 1), 1000);
    EXPECT_EQ(std::count(count.begin(), count.end(), 0), 24);
  }
  {  // 1050 particles in 10 x 10 cells: 10 each, and 50 cells one more
    Particles p = sized(1050, 20e-6);
    place_stratified(p, c, PlacementConfig{10, 0.4}, 2);
    const auto count = per_cell(p, c, 10);
    EXPECT_EQ(std::count(count.begin(), count.end(), 10), 50);
    EXPECT_EQ(std::count(count.begin(), count.end(), 11), 50);
  }
}

// Each size is stratified over the height, not only the whole sample: with L particles of a
// size and n_mt rows, every row holds floor(L / n_mt) of them, give or take one or two (a
// random deal would leave rows with none and rows with many).
TEST(Placement, EverySizeIsSpreadEvenlyOverTheRows) {
  const Scene scene = parse_scene(
      "[sample]\nsimulated_count = 20000\nsize_count = 3\n"
      "[sample.placement]\nmethod = \"stratified\"\n[sample.grading]\n"
      "diameters_um = [5, 20, 60]\npercent_finer = [0, 50, 100]\n",
      "rows.toml");
  const Sample s = build_sample(sample_setup(scene));
  const std::int64_t side = cells_per_side(PlacementConfig{}, s.particles.size());
  ASSERT_EQ(side, 142);
  for (std::size_t k = 0; k < s.classes.size(); ++k) {
    std::vector<long> per_row(std::size_t(side), 0);
    for (std::size_t i = 0; i < s.particles.size(); ++i)
      if (s.particles.size_class[i] == std::int32_t(k))
        per_row[std::size_t(s.particles.y[i] / scene.cylinder.height * double(side))] += 1;
    const long base = s.classes[k].simulated_count / side;
    EXPECT_GE(*std::min_element(per_row.begin(), per_row.end()), base - 1) << "size " << k;
    EXPECT_LE(*std::max_element(per_row.begin(), per_row.end()), base + 2) << "size " << k;
  }
}

// Brute force over every pair, in a small dense section (a third of the plane covered).
TEST(Placement, NoOverlapAndInsideTheWallsBottomAndSurface) {
  const Cylinder c = test::small_dense_section();
  Particles p;
  p.resize(3000);
  for (std::size_t i = 0; i < p.size(); ++i) p.diameter[i] = (i % 2 == 0 ? 40e-6 : 12e-6);
  place_stratified(p, c, PlacementConfig{}, 3);
  EXPECT_GT(area_fraction(p, c), 0.3);
  test::expect_inside_and_apart(p, c);
}

TEST(Placement, SameSeedSameSampleOtherSeedOtherSample) {
  const std::string toml =
      "[sample]\nsimulated_count = 5000\n[sample.placement]\nmethod = \"stratified\"\n";
  const Sample a = build_sample(sample_setup(parse_scene(toml, "a.toml", {"sample.seed=42"})));
  const Sample b = build_sample(sample_setup(parse_scene(toml, "b.toml", {"sample.seed=42"})));
  const Sample c = build_sample(sample_setup(parse_scene(toml, "c.toml", {"sample.seed=43"})));
  EXPECT_EQ(a.particles.x, b.particles.x);
  EXPECT_EQ(a.particles.y, b.particles.y);
  EXPECT_EQ(a.particles.diameter, b.particles.diameter);
  EXPECT_EQ(a.particles.diameter, c.particles.diameter);  // the seed moves, not resizes
  std::size_t moved = 0;
  for (std::size_t i = 0; i < a.particles.size(); ++i)
    moved += a.particles.x[i] != c.particles.x[i] ? 1 : 0;
  EXPECT_GT(moved, a.particles.size() * 99 / 100);
}

TEST(Placement, BuiltSampleIsOrderedAndReportsItsAreaFraction) {
  const Sample s = build_sample(sample_setup(
      parse_scene("[sample]\nsimulated_count = 2000\nsize_count = 2\n[sample.grading]\n"
                  "diameters_um = [10, 35, 60]\npercent_finer = [0, 50, 100]\n",
                  "two.toml")));
  ASSERT_EQ(s.classes.size(), 2u);
  EXPECT_EQ(s.classes[0].simulated_count, 1000);
  const auto& p = s.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(p.id[i], i);
    EXPECT_EQ(p.size_class[i], i < 1000 ? 0 : 1);
  }
  const double covered = 1000 * M_PI / 4 * (10e-6 * 10e-6 + 60e-6 * 60e-6);
  EXPECT_NEAR(s.area_fraction, covered / (0.0635 * 0.457), 1e-15);
}

// Large grains cover many cells when the cells are small: the small grains dealt to those
// cells find room nearby. 10^6 particles, two sizes 1:28, placed in about a second.
TEST(Placement, AMillionParticlesOfRatio28AreQuick) {
  Cylinder c;
  c.height = 0.01;
  c.diameter = 0.004;
  Particles p;
  p.resize(1000000);
  for (std::size_t i = 0; i < p.size(); ++i) p.diameter[i] = (i % 20000 == 0 ? 70e-6 : 2.5e-6);
  const auto start = std::chrono::steady_clock::now();
  place_stratified(p, c, PlacementConfig{}, 9);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("placed 1e6 particles (area fraction %.3f) in %.2f s\n", area_fraction(p, c),
              seconds);
  EXPECT_LT(seconds, 10.0);
  for (std::size_t i = 0; i < p.size(); i += 20000) {  // the large ones overlap nothing
    for (std::size_t j = 0; j < p.size(); ++j) {
      if (j == i) continue;
      const double dx = p.x[i] - p.x[j], dy = p.y[i] - p.y[j];
      const double touch = 0.5 * (p.diameter[i] + p.diameter[j]);
      ASSERT_GE(dx * dx + dy * dy, touch * touch);
    }
  }
}

// The paper's cylinder, a log-uniform curve in 220 sizes, 10^6 particles: the whole sample
// (discretisation, weights, placement) is built in about half a second.
TEST(Placement, AMillionParticleSampleIsQuick) {
  const Scene scene = parse_scene(
      "[sample]\nsimulated_count = 1000000\n[sample.placement]\nmethod = \"stratified\"\n",
      "million.toml");
  const auto start = std::chrono::steady_clock::now();
  const Sample s = build_sample(sample_setup(scene));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("built a 1e6-particle sample (area fraction %.4f) in %.2f s\n", s.area_fraction,
              seconds);
  EXPECT_EQ(s.particles.size(), 1000000u);
  EXPECT_LT(seconds, 10.0);
}

}  // namespace
}  // namespace sedem
