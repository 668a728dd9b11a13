#pragma once

// The chores both steppers run between steps, each with its period named.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/engine/contact/neighbour_grid.h"
#include "core/engine/forces/force_model.h"
#include "core/engine/state/engine_state.h"
#include "core/model/fluid.h"

namespace sedem {

// Puts the state in the neighbour grid's bucket order, so that a particle's neighbours are
// near it in memory for the next steps. Taken when the candidate lists are rebuilt, at most
// once every kPeriod steps.
class ResortTask {
 public:
  static constexpr std::int64_t kPeriod = 16;
  bool due(std::int64_t step) const { return step - done_at >= kPeriod; }
  // Reorders the state and the search radii and pace radii (which follow the state's order;
  // the pace radii only where there are as many).
  void run(EngineState& s, std::vector<double>& search, std::vector<double>& pace,
           const NeighbourGrid& grid, std::int64_t step);
  std::size_t bytes() const;

  std::int64_t done_at = 0;  // the step of the last resort (saved in checkpoints)

 private:
  std::vector<double> scratch_;
  std::vector<std::uint32_t> scratch_index_;
  std::vector<std::uint8_t> scratch_flag_;
};

// Freezes the particles resting below `height` (0: none), every kPeriod steps: below every
// instrument nothing they could still do is measured.
class FreezeTask {
 public:
  static constexpr std::int64_t kPeriod = 64;
  bool enabled() const { return height > 0; }
  bool due(std::int64_t step) const { return height > 0 && step % kPeriod == 0; }
  // `touching[i] > 0`: particle i touches something. Returns how many are frozen now.
  std::size_t run(EngineState& s, const std::vector<double>& touching, const ForceModel& model,
                  const Fluid& fluid) const;

  double height = 0;
};

}  // namespace sedem
