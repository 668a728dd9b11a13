#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include "core/run/stage_setups.h"
#include "core/sample/memory_order.h"
#include "core/sample/placement.h"
#include "core/sample/sample_builder.h"
#include "core/scene/scene_loader.h"

namespace sedem {
namespace {

Sample built(std::int64_t count, int seed) {
  return build_sample(sample_setup(parse_scene(
      "[sample]\nsimulated_count = " + std::to_string(count) + "\nsize_count = 8\nseed = " +
          std::to_string(seed) + "\n[sample.grading]\nfamily = \"log_uniform\"\n",
      "order.toml")));
}

using Grain = std::tuple<std::int32_t, double, double, double, double>;

std::vector<Grain> grains(const Particles& p) {
  std::vector<Grain> g;
  for (std::size_t k = 0; k < p.size(); ++k)
    g.emplace_back(p.size_class[k], p.x[k], p.y[k], p.diameter[k], p.weight[k]);
  return g;
}

// Mean distance between grains of one class that are next to each other in the order.
double mean_step(const Particles& p) {
  double sum = 0;
  std::size_t pairs = 0;
  for (std::size_t k = 1; k < p.size(); ++k) {
    if (p.size_class[k] != p.size_class[k - 1]) continue;
    sum += std::hypot(p.x[k] - p.x[k - 1], p.y[k] - p.y[k - 1]);
    ++pairs;
  }
  return sum / double(pairs);
}

// Three classes, placed as build_sample places them (classes in a row, largest first).
Particles placed(std::size_t per_class, const Cylinder& c) {
  Particles p;
  p.resize(3 * per_class);
  const double diameters[] = {60e-6, 20e-6, 5e-6};
  for (std::size_t k = 0; k < p.size(); ++k) {
    p.size_class[k] = std::int32_t(k / per_class);
    p.diameter[k] = diameters[k / per_class];
    p.weight[k] = 1.0 + double(k / per_class);
    p.id[k] = std::uint32_t(k);
  }
  place_particles(p, c, PlacementConfig{}, 7);
  return p;
}

TEST(MemoryOrder, KeepsEveryGrainAndEachClassTogether) {
  const Cylinder c;
  const Particles before = placed(2000, c);
  Particles p = before;
  order_for_memory(p, c);
  std::vector<Grain> was = grains(before), is = grains(p);
  EXPECT_NE(was, is);  // renumbered
  std::sort(was.begin(), was.end());
  std::sort(is.begin(), is.end());
  EXPECT_EQ(was, is);  // the same grains
  for (std::size_t k = 1; k < p.size(); ++k) ASSERT_LE(p.size_class[k - 1], p.size_class[k]);
  for (std::size_t k = 0; k < p.size(); ++k) ASSERT_EQ(p.id[k], k);
}

TEST(MemoryOrder, NeighboursInTheOrderAreNeighboursInTheSection) {
  const Cylinder c;
  const Particles before = placed(10000, c);
  Particles p = before;
  order_for_memory(p, c);
  const double spacing = std::sqrt(c.diameter * c.height / double(p.size()));
  // In placement order consecutive grains of a class lie a good part of the section apart;
  // along the curve a few spacings (its jumps included).
  EXPECT_GT(mean_step(before), 0.1 * c.height);
  EXPECT_LT(mean_step(p), 8 * spacing);
  // Ordered twice, the same order: the key depends on the positions only.
  Particles again = p;
  order_for_memory(again, c);
  EXPECT_EQ(again.x, p.x);
  EXPECT_EQ(again.y, p.y);
}

TEST(MemoryOrder, BuildSampleNumbersEachClassAlongTheCurve) {
  const Sample s = built(20000, 5);
  const Cylinder c;
  const double spacing = std::sqrt(c.diameter * c.height / double(s.particles.size()));
  EXPECT_LT(mean_step(s.particles), 8 * spacing);
}

}  // namespace
}  // namespace sedem
