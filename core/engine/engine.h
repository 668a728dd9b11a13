#pragma once

// The DEM engine: Eq. 5 for every particle, forces of Sect. 3 and 4.2 (see
// forces/force_model.h), the integrators of Sect. 4.6 (see integrate/integrator.h), neighbour
// search in contact/neighbour_grid.h. The engine owns the shared state (schedule/engine_parts.h)
// and hands each step to one stepper: every particle on the common step
// (schedule/global_stepper.h), or free grains coasting on windows of their own
// (schedule/local_stepper.h). Candidate lists (Verlet) are rebuilt from the grid when a
// particle has moved beyond the lists' margin since the last build (at least 3 radii:
// list_margin in schedule/engine_parts.cpp); at most every ResortTask::kPeriod steps the rebuild
// first re-sorts the state in grid order. Every FreezeTask::kPeriod steps resting particles below
// the lowest instrument are frozen. A blow-up throws InstabilityError.

#include <cstdint>
#include <iosfwd>
#include <memory>
#include <string>

#include "core/engine/engine_setup.h"
#include "core/engine/instability.h"
#include "core/model/engine_stats.h"
#include "core/model/particles.h"
#include "core/model/sample.h"
#include "core/model/snapshot.h"

namespace sedem {

struct EngineParts;
class GlobalStepper;
class LocalStepper;

class Engine {
 public:
  Engine(const EngineSetup& setup, Sample sample);
  ~Engine();

  double time() const;
  // The particles in the sample's order, brought up to date on demand.
  const Particles& particles() const;
  const Sample& sample() const;
  const EngineStats& stats() const;

  // Advances to exactly `t` (no-op if t <= time()). Throws InstabilityError on a blow-up.
  void advance_to(double t);
  // One step of the integrator's choosing (the last one shortened to land on `limit`).
  void step(double limit);
  Snapshot snapshot() const { return Snapshot{time(), particles()}; }

  // The full state (positions, velocities, spins, frozen flags, tangential springs, time,
  // step rule): resuming with the same scene, sample and thread count continues bit for bit.
  void save_checkpoint(const std::string& path) const;
  void load_checkpoint(const std::string& path);
  // The same into and from a stream that may hold more after it (the observers' state);
  // `name` is the file's, for the errors.
  void save_checkpoint(std::ostream& out) const;
  void load_checkpoint(std::istream& in, const std::string& name);

  const char* integrator_name() const;
  int threads() const;
  // Whether free grains coast on windows of their own (integrator.local_steps).
  bool local_steps() const { return local_ != nullptr; }
  // With local steps, the first broken promise of the scheme (a grain outside its box, a
  // window ended unlooked-at, two boxes overlapping that must not), or "" (for tests).
  std::string local_violation() const;
  double freeze_height() const;
  // With local steps: below this height grains leave the dynamics for the coarse bed (0: none).
  double retire_height() const;
  // Heap bytes held by the engine, its copy of the sample included.
  std::size_t bytes() const;
  // Kinetic energy of translation and rotation, J (a diagnostic for tests and benchmarks).
  double kinetic_energy() const;

 private:
  // Held by pointer: the integrator and the grids point into the parts, which must not move.
  std::unique_ptr<EngineParts> parts_;
  std::unique_ptr<GlobalStepper> global_;  // one of the two steppers, the other null
  std::unique_ptr<LocalStepper> local_;
  mutable std::int64_t synced_step_ = -1;  // the step the sample's particles were written at
};

}  // namespace sedem
