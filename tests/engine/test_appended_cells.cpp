// The appended particles' cells answer what the pairwise scan they replace found: every particle
// added within reach of a point, in increasing index, whatever the cell's side and however wide
// a particle's reach (the rows of the candidate lists, and with them a run, stay the same to
// the bit).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/engine/contact/appended_cells.h"

namespace sedem {
namespace {

struct Added {
  std::vector<double> x, y, reach;
};

// The particles within reach[m] + reach of (x, y), as the pairwise scan takes them.
std::vector<std::size_t> scanned(const Added& a, std::size_t first, double x, double y,
                                 double reach) {
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k < a.x.size(); ++k)
    if (std::hypot(a.x[k] - x, a.y[k] - y) < a.reach[k] + reach) out.push_back(first + k);
  return out;
}

std::vector<std::size_t> found(AppendedCells& cells, const Added& a, std::size_t first, double x,
                               double y, double reach) {
  std::vector<std::size_t> out;
  cells.for_each_near(x, y, reach, [&](std::size_t m) {
    const std::size_t k = m - first;
    if (std::hypot(a.x[k] - x, a.y[k] - y) < a.reach[k] + reach) out.push_back(m);
  });
  return out;
}

TEST(AppendedCells, FindWhatThePairwiseScanFindsInItsOrder) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> ux(-1e-3, 1e-3), uy(0, 0.2), ur(1e-6, 40e-6), u(0, 1);
  for (const double cell : {1e-6, 80e-6, 1e-2}) {  // far smaller, about, far larger than a reach
    AppendedCells cells;
    const std::size_t first = 1000;
    cells.reset(cell);
    Added a;
    std::size_t queries = 0, with_partners = 0;
    for (std::size_t k = 0; k < 3000; ++k) {
      // Half of them crowd one spot, so that cells hold many; one in 500 reaches far.
      const bool crowd = u(rng) < 0.5;
      const double x = crowd ? 1e-4 * u(rng) : ux(rng), y = crowd ? 0.1 + 1e-4 * u(rng) : uy(rng);
      const double reach = u(rng) < 0.002 ? 5e-3 : ur(rng);
      const auto want = scanned(a, first, x, y, reach);
      EXPECT_EQ(found(cells, a, first, x, y, reach), want) << "cell " << cell << ", k " << k;
      ++queries;
      with_partners += !want.empty();
      cells.add(first + k, x, y, reach);
      a.x.push_back(x);
      a.y.push_back(y);
      a.reach.push_back(reach);
    }
    EXPECT_GT(with_partners, queries / 4) << cell;  // the crowd has partners to find
  }
}

TEST(AppendedCells, ResetForgetsWhatWasAdded) {
  AppendedCells cells;
  cells.reset(1e-4);
  cells.add(10, 0, 0, 1e-5);
  cells.add(11, 1e-6, 0, 1e-5);
  std::vector<std::size_t> seen;
  cells.for_each_near(0, 0, 1e-5, [&](std::size_t m) { seen.push_back(m); });
  EXPECT_EQ(seen, (std::vector<std::size_t>{10, 11}));
  cells.reset(1e-4);
  seen.clear();
  cells.for_each_near(0, 0, 1e-5, [&](std::size_t m) { seen.push_back(m); });
  EXPECT_TRUE(seen.empty());
  cells.add(20, 0, 0, 1e-5);
  cells.for_each_near(0, 0, 1e-5, [&](std::size_t m) { seen.push_back(m); });
  EXPECT_EQ(seen, (std::vector<std::size_t>{20}));
}

// A grain of the grid's rows whose search widened is added after the appended ones, and may be
// added again: it comes back once, in index order, from the hashed cells and from the look at
// every entry alike.
TEST(AppendedCells, ParticlesAddedOutOfOrderOrTwiceComeBackOnceInOrder) {
  for (const double cell : {1e-5, 1.0}) {  // a block of many cells (every entry), or one cell
    AppendedCells cells;
    cells.reset(cell);
    cells.add(30, 0, 0, 1e-5);
    cells.add(31, 2e-6, 0, 1e-5);
    cells.add(7, 1e-6, 1e-6, 1e-5);
    cells.add(7, 1e-6, 1e-6, 3e-5);
    cells.add(2, -1e-6, 0, 1e-5);
    std::vector<std::size_t> seen;
    cells.for_each_near(0, 0, 1e-5, [&](std::size_t m) { seen.push_back(m); });
    EXPECT_EQ(seen, (std::vector<std::size_t>{2, 7, 30, 31})) << cell;
  }
}

}  // namespace
}  // namespace sedem
