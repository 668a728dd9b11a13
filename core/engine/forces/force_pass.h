#pragma once

// One parallel pass over the particles (in the grid's spatial order) that sums, for each
// particle, weight and buoyancy, wall contacts, pair contacts with friction and lubrication.
// Same-level pairs are evaluated from both sides (each particle writes only its own sums);
// pairs across grid levels are evaluated once, from the finer side, which queues the partner's
// share; the queues are applied after the pass in thread order. No atomics: the result is
// deterministic for a given thread count.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/engine/contact/candidate_lists.h"
#include "core/engine/contact/neighbour_grid.h"
#include "core/engine/forces/force_model.h"
#include "core/engine/instability.h"
#include "core/engine/state/engine_state.h"
#include "core/engine/state/pair_history.h"

namespace sedem {

// Whether a step needs the force pass: pair forces (the explicit integrator) or lubrication.
// Otherwise a free particle feels only weight, buoyancy and drag, which the integrator applies
// itself, and the exponential integrator's projection finds the contacts in its own one pass
// over the candidate lists.
inline bool needs_force_pass(const ForceModel& m) {
  return m.contact_forces || m.lubrication;
}

struct PassFacts {
  std::size_t contacts = 0;      // particles touching a wall or another particle
  double min_contact_mass = 0;   // lightest particle touching or within the skin (0 if none)
  double max_overlap_ratio = 0;  // overlap / smaller radius, worst pair or wall
  Blowup blowup;
};

class ForcePass {
 public:
  void configure(const ForceModel& model, int threads);
  // Over the candidate lists (contact/candidate_lists.h), built on the same grid.
  void run(const EngineState& s, const NeighbourGrid& grid, const CandidateLists& lists,
           const PairHistory& old_springs, PairHistory& new_springs, double dt,
           ForceAccumulators& out, PassFacts& facts);
  std::size_t bytes() const;

 private:
  struct Reaction {
    std::uint32_t j;
    double fx, fy, torque, stiffness, spin_stiffness, lubrication_stiffness;
  };
  struct ThreadFacts {
    std::size_t contacts = 0;
    double min_contact_mass = 0, max_overlap_ratio = 0;
    Blowup blowup;
  };
  ForceModel model_;
  int threads_ = 1;
  std::vector<std::vector<Reaction>> reactions_;
  std::vector<std::vector<PairHistory::Entry>> springs_;
  std::vector<ThreadFacts> facts_;
};

}  // namespace sedem
