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

// Expects every close pair held once and no other pair (nor two frozen grains: a bed costs
// nothing). Returns how many close pairs there are, and how many with a particle from `later` on.
std::pair<std::size_t, std::size_t> expect_close_pairs_held_once(const Crowd& c,
                                                                 std::size_t later) {
  const auto held = c.taken();
  std::size_t pairs = 0, with_later = 0;
  for (std::size_t j = 0; j < c.state.size(); ++j)
    for (std::size_t i = 0; i < j; ++i) {
      const bool both_frozen = c.state.frozen[i] && c.state.frozen[j];
      const auto it = held.find({i, j});
      const int times = it == held.end() ? 0 : it->second;
      if (!close(c, i, j) || both_frozen) {
        EXPECT_EQ(times, 0) << i << " " << j;
        continue;
      }
      ++pairs;
      with_later += j >= later;
      EXPECT_EQ(times, 1) << i << " " << j;
    }
  return {pairs, with_later};
}

TEST(CandidateLists, AppendedParticlesHoldEachClosePairOnce) {
  Crowd c;
  for (int i = 0; i < 1500; ++i) c.append(i % 7 == 0);
  c.lists.rebuild_at_build_positions(c.state, c.grid, true);
  for (int i = 0; i < 300; ++i) c.append(i % 5 == 0);
  c.lists.extend(c.state, c.grid);
  ASSERT_EQ(c.lists.rows(), c.state.size());
  EXPECT_EQ(c.lists.grid_rows, 1500u);

  const auto [pairs, with_appended] = expect_close_pairs_held_once(c, 1500);
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

// Widened rows (carried steps: a grain picked up by a coarse one needs a wider search): after
// widenings of grains of the grid's rows and of appended ones, some twice, between appends, the
// lists hold every pair within the radii now exactly once, as lists built with them would.
// A resumed run (the grid's rows from the build's radii, then the appends and widenings again in
// their order) gets the same rows to the entry.
TEST(CandidateLists, WidenedRowsHoldEachClosePairOnceAndReplayFromACheckpoint) {
  Crowd c;
  for (int i = 0; i < 1200; ++i) c.append(i % 7 == 0);
  c.lists.rebuild_at_build_positions(c.state, c.grid, true);
  std::uniform_int_distribution<int> pick(0, 1 << 30);
  std::size_t widened = 0;
  for (int batch = 0; batch < 6; ++batch) {
    for (int i = 0; i < 40; ++i) c.append(i % 5 == 0);
    c.lists.extend(c.state, c.grid);
    for (int w = 0; w < 25; ++w) {
      const std::size_t k = std::size_t(pick(c.rng)) % c.state.size();
      // To about a coarse grain's reach: many partners the old radius did not hold.
      c.lists.widen(c.grid, k, c.lists.search[k] + 20e-6 + 50e-6 * (w % 3));
      ++widened;
    }
    const std::size_t again = std::size_t(pick(c.rng)) % c.state.size();  // twice, some
    c.lists.widen(c.grid, again, c.lists.search[again] * 1.5);
    c.lists.widen(c.grid, again, c.lists.search[again]);  // no wider: nothing
    ++widened;
  }
  ASSERT_EQ(c.lists.widenings.size(), widened);
  ASSERT_EQ(c.lists.rows(), c.state.size() + widened);
  ASSERT_EQ(c.lists.appended_to(), c.state.size());

  const std::size_t pairs = expect_close_pairs_held_once(c, c.state.size()).first;
  std::size_t added_by_widening = 0;
  for (std::size_t k = c.lists.grid_rows; k < c.lists.rows(); ++k)
    if (c.lists.first_row_from(c.lists.particle_of(k, c.grid)) != k)  // not an appended row
      added_by_widening += c.lists.list_start()[k + 1] - c.lists.list_start()[k];
  EXPECT_GT(pairs, 1000u);
  EXPECT_GT(added_by_widening, 200u);

  // What a checkpoint keeps: the radii now, the build positions, the grid's row count and the
  // widenings.
  CandidateLists resumed;
  resumed.configure(1);
  resumed.search = c.lists.search;
  resumed.x0 = c.lists.x0;
  resumed.y0 = c.lists.y0;
  resumed.widenings = c.lists.widenings;
  ASSERT_TRUE(resumed.widenings_fit(c.state.size()));
  NeighbourGrid grid = c.grid;
  resumed.rebuild_at_build_positions(c.state, grid, true, c.lists.grid_rows);
  EXPECT_EQ(resumed.list_start(), c.lists.list_start());
  EXPECT_EQ(resumed.list(), c.lists.list());
  EXPECT_EQ(resumed.search, c.lists.search);
  EXPECT_EQ(resumed.widenings.size(), c.lists.widenings.size());
  for (std::size_t k = 0; k < resumed.rows(); ++k)
    EXPECT_EQ(resumed.particle_of(k, grid), c.lists.particle_of(k, c.grid)) << k;

  // A full build forgets them: the radii now are its own.
  c.lists.rebuild(c.state, c.grid, true);
  EXPECT_TRUE(c.lists.widenings.empty());
  EXPECT_EQ(c.lists.rows(), c.state.size());
}

// Stale by pairs (check_pairs): when the two largest excesses sum past zero, the lists are
// stale only if a pair whose excesses sum to zero or more is within its search radii now,
// however many grains moved (a first version rebuilt without looking past 4 096 of them). A
// lattice of 4 970 grains 100 um apart, each 10 um across with a search radius of 21 um (a
// margin of 3.2 radii): all move half their margin up, grain 0 three margins to the right, which
// leaves it 52.6 um from its nearest neighbour (beyond the 42 um of their two radii).
TEST(CandidateLists, StaleByPairsLooksAtEveryGrainThatMoved) {
  const double half_width = 3.5e-3, height = 7.2e-3, spacing = 100e-6, d = 10e-6;
  EngineState state;
  NeighbourGrid grid;
  CandidateLists lists;
  grid.configure(42e-6, 42e-6, half_width, height);
  lists.configure(1);
  lists.margin = 3.2;
  lists.range = 1;
  for (int row = 0; row < 71; ++row)
    for (int column = 0; column < 70; ++column) {
      const std::size_t k = state.size();
      state.resize(k + 1);
      state.x[k] = -half_width + 0.5 * spacing + column * spacing;
      state.y[k] = 0.5 * spacing + row * spacing;
      state.diameter[k] = d;
      state.origin[k] = std::uint32_t(k);
      lists.search.push_back(0.5 * d * (lists.range + lists.margin));
    }
  ASSERT_GT(state.size(), 4096u);
  lists.margin_per_grain = true;
  lists.check_pairs = true;
  lists.rebuild(state, grid, false);
  const double margin = lists.margin_of(0, d);
  ASSERT_NEAR(margin, 16e-6, 1e-12);
  for (std::size_t k = 1; k < state.size(); ++k) state.y[k] += 0.5 * margin;
  state.x[0] += 3 * margin;
  EXPECT_FALSE(lists.moved_beyond_margin(state));
  // Its right-hand neighbour 0.9 of its margin towards it instead: 37.6 um apart, and the two
  // excesses (2.01 and -0.09 margins) sum past zero.
  state.y[1] -= 0.5 * margin;
  state.x[1] -= 0.9 * margin;
  EXPECT_TRUE(lists.moved_beyond_margin(state));
  // Without the pair check any two such excesses make the lists stale.
  state.x[1] += 0.9 * margin;
  state.y[1] += 0.5 * margin;
  lists.check_pairs = false;
  EXPECT_TRUE(lists.moved_beyond_margin(state));
}

TEST(CandidateLists, WideningsThatNameNoParticleOrNoWiderRadiusDoNotFit) {
  CandidateLists lists;
  const std::size_t n = 10;
  lists.widenings = {{2, 5, 1e-6, 2e-6}, {7, 8, 1e-6, 3e-6}};
  EXPECT_TRUE(lists.widenings_fit(n));
  const CandidateLists::Widening bad[] = {{10, 10, 1e-6, 2e-6},  // no such particle
                                          {6, 5, 1e-6, 2e-6},    // no row yet
                                          {2, 11, 1e-6, 2e-6},   // more rows than particles
                                          {2, 5, 2e-6, 2e-6},    // no wider
                                          {2, 5, 0, 2e-6},       // no radius
                                          {2, 5, 1e-6, HUGE_VAL}, {2, 5, std::nan(""), 2e-6}};
  for (const auto& w : bad) {
    lists.widenings = {w};
    EXPECT_FALSE(lists.widenings_fit(n)) << w.particle << " " << w.appended_to << " " << w.from;
  }
  lists.widenings = {{2, 8, 1e-6, 2e-6}, {3, 5, 1e-6, 2e-6}};  // fewer rows than before
  EXPECT_FALSE(lists.widenings_fit(n));
}

}  // namespace
}  // namespace sedem
