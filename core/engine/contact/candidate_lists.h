#pragma once

// Candidate lists (Verlet): for each particle, in the neighbour grid's order, the partners the
// grid finds within search[i] + search[j] of the positions (x0, y0) the lists were built at.
// The search radii carry a margin of `margin` radii beyond the interaction range, so the lists
// stay complete until the particles have moved far enough to use it (moved_beyond_margin).
// The force pass and the contact projection both read them.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/engine/contact/appended_cells.h"
#include "core/engine/contact/neighbour_grid.h"
#include "core/engine/state/engine_state.h"

namespace sedem {

class CandidateLists {
 public:
  void configure(int threads);
  // Builds the lists at the current positions (they become the build positions x0, y0).
  // With `frozen_aware` (no force pass: the projection alone reads the lists), a frozen
  // particle lists its coarser partners only: a same-level pair of a frozen and a moving
  // particle is found from the moving side, and a bed of frozen grains costs little.
  void rebuild(const EngineState& s, NeighbourGrid& grid, bool frozen_aware);
  // The same from the build positions already held (a checkpoint's), for the first `rows`
  // particles (all when rows exceeds the state).
  void rebuild_at_build_positions(const EngineState& s, NeighbourGrid& grid, bool frozen_aware,
                                  std::size_t rows = SIZE_MAX);
  // Rows for the particles appended to the state since the last build or extension, without
  // touching the others (a grain joining the local stepper's members re-indexes nobody, and
  // a full build costs a thousand times its share): particle k's row lists every particle m
  // with a row before it within search[k] + search[m] of the build positions, its own x0, y0
  // those it had when appended (found in `grid`, the one the lists were built with, and among
  // the other appended ones). So a pair with an appended particle is held once, in the later
  // one's row. Not for the force pass (it reads the grid's rows only; the global stepper never
  // appends).
  void extend(const EngineState& s, const NeighbourGrid& grid) { extend_to(s, grid, s.size()); }
  // Widens particle k's search radius to `radius` without a build (carried steps: a grain
  // picked up by a coarse one travels at its carrier's pace, and needs the pairs that pace can
  // close): a row of its own lists the particles m that the wider radius brings within
  // search[k] + search[m] and the old one did not, so every pair is still held once. Lists
  // built with the final radii hold the same pairs. Nothing for a particle without a row yet,
  // a radius no wider, or stale lists.
  void widen(const NeighbourGrid& grid, std::size_t k, double radius);
  // A widening since the build, in order: a checkpoint keeps them, and a resumed run's
  // rebuild_at_build_positions takes the radii back to the build's and replays them (with
  // the appends between them) to the same rows.
  struct Widening {
    std::uint32_t particle;     // state index
    std::uint32_t appended_to;  // the particles that had rows then
    double from, to;            // its search radius before and after
  };
  std::vector<Widening> widenings;
  // Whether the widenings read from a checkpoint name particles and radii a state of n
  // particles can hold (replaying them indexes the state with them).
  bool widenings_fit(std::size_t n) const;
  // Valid while no particle has moved more than half the margin the radii carry beyond the
  // interaction range: see the comment at its definition.
  bool moved_beyond_margin(const EngineState& s);
  // Margins per grain (margin_per_grain), sized before a build from how much of its margin each
  // grain used since the last one: doubled (up to kWidestMargin times `margin`) past
  // kWidenAbove of it, halved (down to `margin`) below kNarrowBelow. Grains falling at their
  // step's full pace use their margin in a few steps while most barely touch theirs, and
  // wider margins for all cost more in the lists than the builds they save. Needs the build
  // positions of every particle of the state.
  void size_margins(const EngineState& s);
  static constexpr double kWidenAbove = 0.35, kNarrowBelow = 0.15, kWidestMargin = 8;
  // The lists: row k lists the partners of particle_of(k). The first grid_rows rows follow
  // the grid's order (a same-level pair in both rows, a cross-level pair in the finer side's);
  // the rest are extend()'s and widen()'s, each pair of them held there alone.
  const std::vector<std::uint32_t>& list_start() const { return list_start_; }
  const std::vector<std::uint32_t>& list() const { return list_; }
  std::size_t rows() const { return list_start_.empty() ? 0 : list_start_.size() - 1; }
  std::uint32_t particle_of(std::size_t row, const NeighbourGrid& grid) const {
    return row < grid_rows ? grid.order()[row] : row_particle_[row - grid_rows];
  }
  // The particles 0 .. appended_to() - 1 have rows (the grid's, then the appended ones).
  std::size_t appended_to() const { return appended_to_; }
  // The first row holding a pair of a particle appended from `particle` on: the later rows
  // hold every such pair (and maybe others).
  std::size_t first_row_from(std::size_t particle) const {
    if (particle < grid_rows) return 0;
    return particle < appended_to_ ? append_row_[particle - grid_rows] : rows();
  }
  // Working memory of the lists themselves (the radii and build positions not included).
  std::size_t bytes() const;

  std::vector<double> search;  // search radius: radius + lubrication reach + skins + margin
  std::vector<double> x0, y0;  // positions when the lists were built
  double margin = 2;           // of the search radii, in radii
  // A grain's margin is its search radius beyond the interaction range (`range` radii): with
  // local steps, sized by size_margins, or with carried steps (integrator.carried_fraction)
  // margin times its carrier's radius, not its own. Otherwise `margin` radii for every grain.
  bool margin_per_grain = false;
  // With margins per grain: the lists are stale only when a pair whose moves sum past its
  // margins is within its search radii (not when any two grains' moves do). Local steps
  // without carried steps, whose sub-steps' fine grains fell 0.9 % less in a crowd with it.
  bool check_pairs = false;
  double range = 1;
  // The margin grain i's search radius holds (the interaction range left out).
  double margin_of(std::size_t i, double diameter) const {
    return margin_per_grain ? search[i] - 0.5 * range * diameter : 0.5 * margin * diameter;
  }
  bool stale = true;            // to be rebuilt before the next pass reads them
  std::uint64_t grid_rows = 0;  // the rows the last build put in the grid's order

 private:
  struct Near {
    std::uint32_t particle;
    double excess, x;
  };
  // moved_beyond_margin's grains that could be in a pair past its margins, and those of them
  // past their own.
  std::vector<Near> near_, past_;
  void build(const NeighbourGrid& grid, std::size_t n, const double* bx, const double* by,
             const double* radius, const std::uint8_t* frozen);
  // extend() for the particles up to n only.
  void extend_to(const EngineState& s, const NeighbourGrid& grid, std::size_t n);
  // Calls visit(m) for every particle m with a row that may lie within reach + search[m] of
  // particle k's build position (and maybe farther: the caller tests the distance). The grid
  // finds its rows' particles by the radii it was built with; those appended since, and those
  // widened, are in appended_ instead.
  template <class Visit>
  void for_each_held_near(const NeighbourGrid& grid, std::size_t k, double reach, Visit&& visit) {
    grid.for_each_near(x0[k], y0[k], reach, x0.data(), y0.data(), [&](std::size_t m) {
      if (!widened_[m]) visit(m);
    });
    appended_.for_each_near(x0[k], y0[k], reach, visit);
  }

  int threads_ = 1;
  std::vector<double> top_excess_;  // per thread: the two largest moves beyond the margin
  std::vector<std::vector<std::uint32_t>> local_lists_;
  std::vector<std::uint32_t> list_start_, list_;
  AppendedCells appended_;  // the particles appended, and those widened, since the last build
  std::size_t appended_to_ = 0;
  std::vector<std::uint32_t> row_particle_;  // per row after the grid's: its particle
  std::vector<std::uint32_t> append_row_;    // per appended particle: its row
  std::vector<std::uint8_t> widened_;        // per particle of the grid's rows: in appended_
};

}  // namespace sedem
