#pragma once

// Candidate lists (Verlet): for each particle, in the neighbour grid's order, the partners the
// grid finds within search[i] + search[j] of the positions (x0, y0) the lists were built at.
// The search radii carry a margin of `margin` radii beyond the interaction range, so the lists
// stay complete until the particles have moved far enough to use it (moved_beyond_margin).
// The force pass and the contact projection both read them.

#include <cstddef>
#include <cstdint>
#include <vector>

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
  // The same from the build positions already held (a checkpoint's), for the first n particles.
  void rebuild_at_build_positions(const EngineState& s, NeighbourGrid& grid, bool frozen_aware);
  // Valid while no particle has moved more than half the margin the radii carry beyond the
  // interaction range: see the comment at its definition.
  bool moved_beyond_margin(const EngineState& s);
  // The lists: partners of grid.order()[k] are list()[list_start()[k] .. [k + 1]).
  const std::vector<std::uint32_t>& list_start() const { return list_start_; }
  const std::vector<std::uint32_t>& list() const { return list_; }
  // Working memory of the lists themselves (the radii and build positions not included).
  std::size_t bytes() const;

  std::vector<double> search;  // search radius: radius + lubrication reach + skins + margin
  std::vector<double> x0, y0;  // positions when the lists were built
  double margin = 2;           // of the search radii, in radii
  // Carried steps (integrator.carried_fraction): a grain's margin is its search radius beyond the
  // interaction range (`range` radii), margin times its carrier's radius, not its own.
  bool margin_per_grain = false;
  double range = 1;
  // The margin grain i's search radius holds (the interaction range left out).
  double margin_of(std::size_t i, double diameter) const {
    return margin_per_grain ? search[i] - 0.5 * range * diameter : 0.5 * margin * diameter;
  }
  bool stale = true;  // to be rebuilt before the next pass reads them
  // Stale only by particles appended to the state since the build: the lists still hold every
  // pair among the others (carried steps choose a step from them meanwhile).
  bool appended_only = false;
  std::size_t built_count() const { return list_start_.empty() ? 0 : list_start_.size() - 1; }

 private:
  void build(const NeighbourGrid& grid, std::size_t n, const double* bx, const double* by,
             const double* radius, const std::uint8_t* frozen);

  int threads_ = 1;
  std::vector<double> top_excess_;  // per thread: the two largest moves beyond the margin
  std::vector<std::vector<std::uint32_t>> local_lists_;
  std::vector<std::uint32_t> list_start_, list_;
};

}  // namespace sedem
