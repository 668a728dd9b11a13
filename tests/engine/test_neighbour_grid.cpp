// The hierarchical neighbour grid finds every close pair exactly once per side it should,
// against a brute-force search, for sizes spanning 1:28.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <utility>

#include "core/engine/contact/neighbour_grid.h"

namespace sedem {
namespace {

TEST(NeighbourGrid, FindsEveryClosePairLikeBruteForce) {
  std::mt19937 rng(11);
  const double hw = 0.5e-3, h = 2e-3;
  std::uniform_real_distribution<double> ux(-hw, hw), uy(0, h), ud(0, 1);
  const std::size_t n = 3000;
  std::vector<double> x(n), y(n), r(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = ux(rng);
    y[i] = uy(rng);
    r[i] = 0.5 * (ud(rng) < 0.1 ? 70e-6 : 2.5e-6 + 20e-6 * ud(rng) * ud(rng));
  }
  NeighbourGrid grid;
  grid.configure(5e-6, 70e-6, hw, h);
  grid.build(n, x.data(), y.data(), r.data());
  EXPECT_GE(grid.level_count(), 5);

  std::multiset<std::pair<std::size_t, std::size_t>> found;
  for (std::size_t i = 0; i < n; ++i)
    grid.for_each_candidate(i, x.data(), y.data(), r.data(), [&](std::uint32_t j) {
      if (std::hypot(x[j] - x[i], y[j] - y[i]) < r[i] + r[j]) found.insert({i, j});
    });
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      if (std::hypot(x[j] - x[i], y[j] - y[i]) >= r[i] + r[j]) continue;
      ++pairs;
      const std::size_t ij = found.count({i, j}), ji = found.count({j, i});
      if (grid.level(i) == grid.level(j)) {
        EXPECT_EQ(ij, 1u) << i << " " << j;
        EXPECT_EQ(ji, 1u) << i << " " << j;
      } else {
        // Found once, from the finer particle.
        EXPECT_EQ(grid.level(i) < grid.level(j) ? ij : ji, 1u) << i << " " << j;
        EXPECT_EQ(ij + ji, 1u) << i << " " << j;
      }
    }
  }
  EXPECT_GT(pairs, 100u);
}

}  // namespace
}  // namespace sedem
