#pragma once

// Contacts of the exponential integrator as overdamped constraints (XPBD-like). After the free
// update (drag, weight, buoyancy, lubrication; no contact force), each touching pair or wall
// gets a force lambda >= 0 that, applied constantly over the step, moves particle i by w_i lambda
// along the normal (w_i: its mobility, the displacement per unit force over the step) and leaves
// the overlap at lambda / K_N (compliance 1/K_N: a backward-Euler normal spring). The forces are
// found by a few Jacobi sweeps over the constraints,
//   dlambda = max(-lambda, (overlap - lambda / K_N) / (n_a w_a + n_b w_b + 1 / K_N)),
// n the number of contacts of each particle: a Gershgorin bound on the constraint system, so
// every sweep is a contraction and the two partners see the same dlambda (exact action and
// reaction). Each sweep reads the previous sweep's positions, gathers per particle over the
// force pass's candidate lists (a same-level pair is solved identically from both sides; a
// cross-level pair from the finer side, which queues its partner's share, applied in thread
// order): deterministic, no atomics. Each step starts from the forces the previous step ended
// with (kept by sample indices, so re-sorting and list rebuilds keep them; saved in
// checkpoints): a resting bed is held from the first sweep. Friction and contact torques are not
// represented.

#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <vector>

#include "core/engine/engine_state.h"
#include "core/engine/force_pass.h"
#include "core/engine/forces.h"
#include "core/engine/neighbour_grid.h"
#include "core/engine/pair_history.h"

namespace sedem {

class ContactProjection {
 public:
  void configure(const ForceModel& model, int threads, int sweeps);
  // `mobility[i]`: displacement per unit force over the step; `response[i]`: velocity change
  // per unit of that displacement. Moves (x, y) from their free values and adds the matching
  // velocity change. Returns the number of particles that touched in the first sweep.
  std::size_t run(EngineState& s, const NeighbourGrid& grid, const ForcePass& pass,
                  const std::vector<double>& mobility, const std::vector<double>& response);
  std::size_t bytes() const;
  void save(std::ostream& out) const;
  void load(std::istream& in);

 private:
  struct Reaction {
    std::uint32_t j;
    double dx, dy;
    std::uint32_t count;
  };
  enum class Mode {
    start,  // count each particle's contacts; take the forces of the last step
    warm,   // displacements of the current forces, unchanged
    solve,  // one Jacobi sweep: change the forces, their displacements
    last,   // solve, and keep the forces for the next step
  };
  // One pass at the current positions: displacements into (dx_, dy_), the contact counts at
  // these positions into count_. Returns the number of touching particles.
  std::size_t sweep(const EngineState& s, const NeighbourGrid& grid, const ForcePass& pass,
                    const std::vector<double>& mobility, Mode mode);

  ForceModel model_;
  int threads_ = 1, sweeps_ = 32;
  std::vector<double> moved_x_, moved_y_, dx_, dy_;
  std::vector<double> pair_force_;                // lambda per candidate-list entry
  std::vector<double> side_force_, floor_force_;  // lambda per particle against walls, bottom
  std::vector<std::uint32_t> count_, next_count_;
  std::vector<std::vector<Reaction>> reactions_;
  std::vector<std::vector<PairHistory::Entry>> kept_;
  PairHistory warm_;  // forces at the end of the last step; walls as partners kWall, kFloor
  std::vector<std::size_t> touching_;
  std::vector<double> worst_;  // per thread: largest overlap beyond its target / radius
  double residual_ = 0;
};

}  // namespace sedem
