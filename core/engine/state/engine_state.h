#pragma once

// The engine's own particle state: structure of arrays in double precision (contact overlaps
// are ~1e-12 m on positions ~0.1 m), kept in a spatially sorted order (re-sorted every few
// steps) so that neighbours sit close in memory. `origin` maps back to the sample's order.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace sedem {

struct EngineState {
  std::vector<double> x, y, vx, vy, omega;
  std::vector<double> diameter, weight;
  std::vector<std::uint32_t> origin;  // index in the sample's Particles
  std::vector<std::uint8_t> frozen;   // 1: resting in the bed, no longer integrated

  std::size_t size() const { return x.size(); }
  void resize(std::size_t n) {
    for (auto* v : {&x, &y, &vx, &vy, &omega, &diameter, &weight}) v->resize(n);
    origin.resize(n);
    frozen.resize(n);
  }
};

// What the force pass leaves for the integrator, per particle (same order as the state).
// `stiffness` bounds how stiffly contacts and lubrication hold the particle (non-zero: it
// touches); `lubrication_stiffness` is the lubrication's share, which the exponential
// integrator folds into an implicit damping (see integrate/integrator.h).
struct ForceAccumulators {
  std::vector<double> fx, fy, torque;
  std::vector<double> stiffness, spin_stiffness, lubrication_stiffness;
  void resize(std::size_t n) {
    for (auto* v : {&fx, &fy, &torque, &stiffness, &spin_stiffness, &lubrication_stiffness})
      v->resize(n);
  }
};

}  // namespace sedem
