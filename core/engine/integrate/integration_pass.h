#pragma once

// What both integrators share: the per-thread sums of one pass over the particles, reduced in
// thread order, and the blow-up check of every particle they move.

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "core/engine/instability.h"
#include "core/engine/state/engine_state.h"
#include "core/engine/threads_for.h"

namespace sedem::integration {

// Per-thread partial results of an integration pass, reduced in thread order.
struct ThreadSums {
  double max_change = 0;  // velocity change / own terminal speed, free particles
  double max_rate = 0;    // c/m, free particles
  double max_speed = 0;
  double max_radii_per_s = 0;  // speed / radius, moving particles
  // The same over the particles not pushed (see StepLimit), and how many are.
  double max_unpushed_radii_per_s = 0;
  std::size_t pushed = 0;
  Blowup blowup;
};

[[gnu::noinline]] inline void report(const EngineState& s, std::size_t i, double runaway,
                                     Blowup& b) {
  if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) b.note(s.origin[i], "position", s.x[i]);
  if (!std::isfinite(s.vx[i]) || !std::isfinite(s.vy[i])) b.note(s.origin[i], "velocity", s.vx[i]);
  const double speed = std::sqrt(s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i]);
  if (speed > runaway) b.note(s.origin[i], "speed", speed);
  if (!std::isfinite(s.omega[i])) b.note(s.origin[i], "angular velocity", s.omega[i]);
}

// One comparison on the common path: a NaN fails `<=`, an Inf exceeds the bound, and a
// non-finite position or spin makes their sum non-finite.
inline void check(const EngineState& s, std::size_t i, double runaway, Blowup& b) {
  const double v2 = s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i];
  if (!(v2 <= runaway * runaway) || !std::isfinite(s.x[i] + s.y[i] + s.omega[i]))
    report(s, i, runaway, b);
}

// `sums` is the caller's, reused every step (no allocation per step).
template <class Body>
ThreadSums integrate(int threads, std::size_t n, std::vector<ThreadSums>& sums, Body&& body) {
  threads = threads_for(threads, n);
  // Only the threads this pass runs on: a slot left from a pass with more would join the sums.
  sums.resize(std::size_t(std::max(1, threads)));
  // One thread: no parallel region at all. Entering one, even with if(false), costs local
  // steps (thousands of short steps of a few members a second) about 7 % of their time.
  if (threads <= 1) {
    sums[0] = ThreadSums{};
    for (std::size_t i = 0; i < n; ++i) body(i, sums[0]);
  } else {
#pragma omp parallel num_threads(threads)
    {
      sums[std::size_t(omp_get_thread_num())] = ThreadSums{};
      ThreadSums& mine = sums[std::size_t(omp_get_thread_num())];
#pragma omp for schedule(static)
      for (std::size_t i = 0; i < n; ++i) body(i, mine);
    }
  }
  ThreadSums total;
  for (const ThreadSums& t : sums) {
    total.max_change = std::max(total.max_change, t.max_change);
    total.max_rate = std::max(total.max_rate, t.max_rate);
    total.max_speed = std::max(total.max_speed, t.max_speed);
    total.max_radii_per_s = std::max(total.max_radii_per_s, t.max_radii_per_s);
    total.max_unpushed_radii_per_s =
        std::max(total.max_unpushed_radii_per_s, t.max_unpushed_radii_per_s);
    total.pushed += t.pushed;
    if (t.blowup.found && !total.blowup.found) total.blowup = t.blowup;
  }
  return total;
}

}  // namespace sedem::integration
