#pragma once

#include <cstddef>
#include <cstdint>

namespace sedem {

// What the engine did so far: counts that benchmarks, progress and run.json report.
struct EngineStats {
  std::int64_t steps = 0;
  double particle_steps = 0;      // sum over steps of the particles integrated (not frozen)
  double last_step = 0;           // s
  std::size_t contacts = 0;       // particles touching something at the last step
  std::size_t frozen = 0;         // particles frozen in the bed
  double max_overlap_ratio = 0;   // largest overlap / smaller radius seen so far
  std::int64_t list_builds = 0;   // candidate lists built (Verlet rebuilds), the first included
  std::int64_t widened_rows = 0;  // rows added for grains whose search widened (carried steps)
  // Local time stepping: coasting windows taken, and grains that left or joined the common step.
  std::int64_t windows = 0, engaged = 0, released = 0;
  std::int64_t box_moves = 0;  // moving members' boxes moved on, having used their allowance
  std::size_t members = 0;     // grains on the common step at the last step (frozen included)
  std::size_t retired = 0;     // grains that fell below every instrument onto the coarse bed
  // What set the last step (local steps; docs/engine.md): the members a coarser grain pushed
  // faster than 3 times their settling speed, and the step the others alone would have allowed
  // (s; 0 where not known).
  std::size_t pushed = 0;
  double unpushed_step = 0;
  // Carried sub-steps (integrator.carried_substeps): the members of the last step's fast set and
  // the sub-steps they took (0 and 0: the step was not split).
  std::size_t fast_set = 0, substeps = 0;
  // Local steps, every 64th step (0 at the others, or where no member moved): the members'
  // particle-steps if each cluster of them (joined by overlapping boxes) took the step its own
  // fastest member allows, over the common step's (1: nothing to save). A report (of what
  // integrator.own_steps would take, from the clusters of the one-step scheme). And the largest
  // cluster's share of the moving members (1: one cluster).
  double own_step_share = 0, largest_cluster = 0;
  // Own steps (integrator.own_steps): members lagging the common step at the step's end.
  std::size_t lagging = 0;
};

}  // namespace sedem
