// Candidate lists extended with particles appended since their build (a grain joining the local
// stepper's members) hold every close pair once, as a full build at the same build positions
// would, and give the same rows whether appended at once or in batches (a resumed run rebuilds
// the grid's rows and extends the rest at once).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <utility>

#include "core/engine/contact/candidate_lists.h"
#include "core/engine/contact/neighbour_grid.h"
#include "core/engine/state/engine_state.h"

namespace sedem {
namespace {

constexpr double kHalfWidth = 0.5e-3, kHeight = 2e-3;

struct Crowd {
  EngineState state;
  NeighbourGrid grid;
  CandidateLists lists;
  std::mt19937 rng{23};

  Crowd() {
    grid.configure(5e-6, 4 * 70e-6, kHalfWidth, kHeight);
    lists.configure(1);
  }
  // Appends a particle at a random place (its build position where it is now), with a search
  // radius of twice its radius; sizes from 2.5 to 70 um.
  void append(bool frozen) {
    std::uniform_real_distribution<double> ux(-kHalfWidth, kHalfWidth), uy(0, kHeight), ud(0, 1);
    const std::size_t k = state.size();
    state.resize(k + 1);
    state.x[k] = ux(rng);
    state.y[k] = uy(rng);
    state.diameter[k] = ud(rng) < 0.1 ? 70e-6 : 2.5e-6 + 20e-6 * ud(rng) * ud(rng);
    state.origin[k] = std::uint32_t(k);
    state.frozen[k] = frozen ? 1 : 0;
    lists.search.push_back(state.diameter[k]);
    lists.x0.push_back(state.x[k]);
    lists.y0.push_back(state.y[k]);
  }
  // How many times each pair (i < j) is held, counting a grid row's same-level pair once, as
  // the contact projection takes it (from the lower index, or from the moving side).
  std::map<std::pair<std::size_t, std::size_t>, int> taken() const {
    std::map<std::pair<std::size_t, std::size_t>, int> held;
    const auto& start = lists.list_start();
    const auto& list = lists.list();
    for (std::size_t k = 0; k < lists.rows(); ++k) {
      const std::uint32_t i = lists.particle_of(k, grid);
      for (std::uint32_t c = start[k]; c < start[k + 1]; ++c) {
        const std::uint32_t j = list[c];
        const bool fi = state.frozen[i] != 0, fj = state.frozen[j] != 0;
        if (fi && fj) continue;
        if (k < lists.grid_rows && grid.level(i) == grid.level(j) && (fi != fj ? fi : j < i))
          continue;
        ++held[{std::min<std::size_t>(i, j), std::max<std::size_t>(i, j)}];
      }
    }
    return held;
  }
};

bool close(const Crowd& c, std::size_t i, std::size_t j) {
  const double reach = c.lists.search[i] + c.lists.search[j];
  return std::hypot(c.lists.x0[i] - c.lists.x0[j], c.lists.y0[i] - c.lists.y0[j]) < reach;
}

TEST(CandidateLists, AppendedParticlesHoldEachClosePairOnce) {
  Crowd c;
  for (int i = 0; i < 1500; ++i) c.append(i % 7 == 0);
  c.lists.rebuild_at_build_positions(c.state, c.grid, true);
  for (int i = 0; i < 300; ++i) c.append(i % 5 == 0);
  c.lists.extend(c.state, c.grid);
  ASSERT_EQ(c.lists.rows(), c.state.size());
  EXPECT_EQ(c.lists.grid_rows, 1500u);

  const auto held = c.taken();
  std::size_t pairs = 0, with_appended = 0;
  for (std::size_t j = 0; j < c.state.size(); ++j)
    for (std::size_t i = 0; i < j; ++i) {
      const bool both_frozen = c.state.frozen[i] && c.state.frozen[j];
      const auto it = held.find({i, j});
      const int times = it == held.end() ? 0 : it->second;
      if (!close(c, i, j) || both_frozen) {
        EXPECT_EQ(times, 0) << i << " " << j;  // only close pairs, and a bed costs nothing
        continue;
      }
      ++pairs;
      with_appended += j >= 1500;
      EXPECT_EQ(times, 1) << i << " " << j;
    }
  EXPECT_GT(pairs, 300u);
  EXPECT_GT(with_appended, 50u);
}

TEST(CandidateLists, RowsAppendedInBatchesAreThoseAppendedAtOnce) {
  Crowd batches, at_once;  // the same draws: both start from the same seed
  for (int i = 0; i < 800; ++i) batches.append(false);
  for (int i = 0; i < 800; ++i) at_once.append(false);
  batches.lists.rebuild_at_build_positions(batches.state, batches.grid, true);
  at_once.lists.rebuild_at_build_positions(at_once.state, at_once.grid, true);
  for (int batch = 0; batch < 5; ++batch) {
    for (int i = 0; i < 20; ++i) batches.append(i % 3 == 0);
    batches.lists.extend(batches.state, batches.grid);
  }
  for (int i = 0; i < 100; ++i) at_once.append(i % 20 % 3 == 0);
  at_once.lists.extend(at_once.state, at_once.grid);
  EXPECT_EQ(batches.lists.list_start(), at_once.lists.list_start());
  EXPECT_EQ(batches.lists.list(), at_once.lists.list());

  // What a resumed run does: the grid's rows from the saved build positions, then the rest.
  CandidateLists resumed;
  resumed.configure(1);
  resumed.search = batches.lists.search;
  resumed.x0 = batches.lists.x0;
  resumed.y0 = batches.lists.y0;
  NeighbourGrid grid = batches.grid;
  resumed.rebuild_at_build_positions(batches.state, grid, true, batches.lists.grid_rows);
  EXPECT_EQ(resumed.list_start(), batches.lists.list_start());
  EXPECT_EQ(resumed.list(), batches.lists.list());
}

TEST(CandidateLists, StaleListsAreNotExtended) {
  Crowd c;
  for (int i = 0; i < 100; ++i) c.append(false);
  c.lists.rebuild_at_build_positions(c.state, c.grid, true);
  c.lists.stale = true;
  c.append(false);
  c.lists.extend(c.state, c.grid);
  EXPECT_EQ(c.lists.rows(), 100u);
}

// Margins per grain follow each grain's pace: one that used more than kWidenAbove of its margin
// since the build gets twice as much (up to kWidestMargin times the base), one that used less
// than kNarrowBelow half as much (down to the base), the others keep theirs; the lists built
// with them hold every pair within the new search radii, and the staleness check reads each
// grain's own margin.
TEST(CandidateLists, MarginsFollowEachGrainsPace) {
  Crowd c;
  for (int i = 0; i < 400; ++i) c.append(false);
  c.state.diameter[1] = c.state.diameter[0];
  c.lists.margin = 3.2;
  c.lists.range = 1;
  c.lists.margin_per_grain = true;
  auto margin = [&](std::size_t k) { return c.lists.margin_of(k, c.state.diameter[k]); };
  const double base = 3.2;
  // Margins in radii: 0 and 1 the base, 2 four times it, 3 at the widest, 4 twice the base.
  const double start[] = {base, base, 4 * base, CandidateLists::kWidestMargin * base, 2 * base};
  for (std::size_t k = 0; k < c.state.size(); ++k) {
    const double r = 0.5 * c.state.diameter[k];
    c.lists.search[k] = r * (c.lists.range + (k < 5 ? start[k] : base));
  }
  c.lists.rebuild_at_build_positions(c.state, c.grid, true);
  // 0 uses half its margin, 1 and 2 nothing, 3 all of it, 4 a quarter.
  const double used[] = {0.5, 0, 0, 1, 0.25};
  for (std::size_t k = 0; k < 5; ++k) c.state.y[k] += used[k] * margin(k);
  c.lists.size_margins(c.state);
  const double expected[] = {2 * base, base, 2 * base, CandidateLists::kWidestMargin * base,
                             2 * base};
  for (std::size_t k = 0; k < 5; ++k)
    EXPECT_NEAR(margin(k) / (0.5 * c.state.diameter[k]), expected[k], 1e-9) << k;
  for (std::size_t k = 5; k < c.state.size(); ++k)
    EXPECT_NEAR(margin(k) / (0.5 * c.state.diameter[k]), base, 1e-9) << k;

  c.lists.rebuild(c.state, c.grid, false);
  const auto held = c.taken();
  for (std::size_t j = 0; j < c.state.size(); ++j)
    for (std::size_t i = 0; i < j; ++i)
      if (close(c, i, j)) {
        EXPECT_EQ(held.count({i, j}), 1u) << i << " " << j;
      }

  // Grain 0 (twice the base now) may travel 1.5 times the base margin, grain 1 may not.
  c.lists.x0 = c.state.x;
  c.lists.y0 = c.state.y;
  const double r = 0.5 * c.state.diameter[0];  // grain 1's too
  c.state.x[0] += 1.5 * base * r;
  EXPECT_FALSE(c.lists.moved_beyond_margin(c.state));
  c.state.x[1] += 1.5 * base * r;
  EXPECT_TRUE(c.lists.moved_beyond_margin(c.state));
}

}  // namespace
}  // namespace sedem
