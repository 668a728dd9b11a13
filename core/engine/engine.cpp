#include "core/engine/engine.h"

#include <algorithm>
#include <cmath>

#include "core/physics/stokes.h"

namespace sedem {

Engine::Engine(const Scene& scene, Sample sample) : scene_(scene), sample_(std::move(sample)) {
  step_ = scene_.output.interval;
}

// First slice: weight, buoyancy and Stokes drag integrated exactly over each step
// (u relaxes to u_tr with time constant tau), the bottom as a rigid floor.
void Engine::advance_to(double t) {
  auto& p = sample_.particles;
  const std::size_t n = p.size();
  const double rho_p = sample_.particle_density;
  while (time_ < t) {
    const double dt = std::min(step_, t - time_);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      const double d = p.diameter[i];
      const double tau = stokes::relaxation_time(d, rho_p, scene_.fluid);
      const double ut = -stokes::terminal_velocity(d, rho_p, scene_.fluid);
      const double decay = std::exp(-dt / tau);
      // Exact solution of du/dt = (ut - u)/tau over dt, for velocity and displacement.
      const double v0 = p.vy[i];
      p.y[i] += ut * dt + (v0 - ut) * tau * (1.0 - decay);
      p.vy[i] = ut + (v0 - ut) * decay;
      p.vx[i] *= decay;
      const double r = 0.5 * d;
      if (p.y[i] < r) {
        p.y[i] = r;
        p.vy[i] = 0;
      }
    }
    time_ += dt;
    stats_.steps += 1;
    stats_.particle_steps += double(n);
  }
}

}  // namespace sedem
