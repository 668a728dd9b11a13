#include "core/engine/schedule/periodic_tasks.h"

#include <cmath>
#include <utility>

#include "core/physics/stokes.h"

namespace sedem {

void ResortTask::run(EngineState& s, std::vector<double>& search, std::vector<double>& pace,
                     const NeighbourGrid& grid, std::int64_t step) {
  done_at = step;
  const auto& order = grid.order();
  const std::size_t n = s.size();
  if (order.size() != n) return;
  scratch_.resize(n);
  auto permute = [&](auto& v, auto& tmp) {
    tmp.resize(n);
    for (std::size_t k = 0; k < n; ++k) tmp[k] = v[order[k]];
    std::swap(v, tmp);
  };
  for (auto* v : {&s.x, &s.y, &s.vx, &s.vy, &s.omega, &s.diameter, &s.weight, &search})
    permute(*v, scratch_);
  if (pace.size() == n) permute(pace, scratch_);
  permute(s.origin, scratch_index_);
  permute(s.frozen, scratch_flag_);
}

std::size_t ResortTask::bytes() const {
  return scratch_.capacity() * sizeof(double) + scratch_index_.capacity() * sizeof(std::uint32_t) +
         scratch_flag_.capacity();
}

// A particle is at rest when it touches something and moves at less than 1e-3 of its
// terminal speed.
std::size_t FreezeTask::run(EngineState& s, const std::vector<double>& touching,
                            const ForceModel& model, const Fluid& fluid) const {
  std::size_t frozen = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!s.frozen[i] && s.y[i] < height && touching[i] > 0) {
      const double ut = stokes::terminal_velocity(s.diameter[i], model.particle_density, fluid);
      if (std::hypot(s.vx[i], s.vy[i]) < 1e-3 * ut) {
        s.frozen[i] = 1;
        s.vx[i] = s.vy[i] = s.omega[i] = 0;
      }
    }
    frozen += s.frozen[i];
  }
  return frozen;
}

}  // namespace sedem
