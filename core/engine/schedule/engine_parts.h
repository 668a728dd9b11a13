#pragma once

// What the engine owns and its stepper works on: the setup, the sample, the state of the
// particles in the engine's order, the forces, the contact search, the integrator, the time
// and the counters. Engine (engine.h) owns one; the global or the local stepper advances it.

#include <cstddef>
#include <cstdint>
#include <memory>

#include "core/engine/contact/candidate_lists.h"
#include "core/engine/contact/neighbour_grid.h"
#include "core/engine/engine_setup.h"
#include "core/engine/forces/drag_evaluator.h"
#include "core/engine/forces/force_model.h"
#include "core/engine/forces/force_pass.h"
#include "core/engine/forces/voidage_grid.h"
#include "core/engine/integrate/integrator.h"
#include "core/engine/schedule/periodic_tasks.h"
#include "core/engine/state/engine_state.h"
#include "core/engine/state/pair_history.h"
#include "core/model/engine_stats.h"
#include "core/model/sample.h"

namespace sedem {

struct EngineParts {
  // Builds everything from the setup and the sample, the integrator included; the stepper then
  // takes its first look (GlobalStepper, LocalStepper).
  EngineParts(const EngineSetup& setup, Sample sample);
  // The integrator and the grids point into the parts: they stay where they were built.
  EngineParts(const EngineParts&) = delete;
  EngineParts& operator=(const EngineParts&) = delete;

  // Rebuilds the candidate lists at the current positions and counts it.
  void rebuild_lists();
  // The same, the state first re-sorted in grid order if the resort task is due; true if it was
  // (the state's order changed).
  bool resort_and_rebuild_lists();
  // Rows for the members appended since (CandidateLists::extend), unless the lists are stale.
  void extend_lists();
  // Throws InstabilityError for a blow-up the integrator or the force pass noted.
  [[noreturn]] void throw_blowup(const Blowup& b, double at) const;
  // Carried steps: the search radii of particles from..end follow their carriers.
  void widen_search(std::size_t from);
  // Carried steps: the members whose carrier asks for a wider search than their lists' rows
  // hold get it (CandidateLists::widen), unless the lists are stale.
  void widen_lists();
  // Carried steps: the search radius member k's carrier asks for.
  double carried_search(std::size_t k, const std::vector<double>& carrier) const;

  EngineSetup setup;
  Sample sample;  // its particles are brought up to date on demand (Engine::particles)
  EngineState state;
  ForceAccumulators forces;
  ForceModel model;
  NeighbourGrid grid;
  CandidateLists lists;
  VoidageGrid voidage;
  ForcePass pass;
  PairHistory springs, next_springs;
  PassFacts facts;
  DragEvaluator drag;
  std::unique_ptr<Integrator> integrator;
  ResortTask resort;
  FreezeTask freeze;
  int threads = 1;
  // Local time stepping's syncs, taken lane by lane when the free grains pass each other
  // (schedule/local_lanes.cpp); the members' step has `threads` (one there; the engine's
  // where grains meet everywhere).
  int sync_threads = 1;
  bool pass_needed = true;  // see needs_force_pass
  // Whether free grains coast on windows of their own (the local stepper).
  bool local = false;
  // integrator.carried_fraction in effect (local steps with contacts): the lists' margins follow
  // each member's carrier.
  bool carried = false;
  // Local steps where grains meet, or carried steps (`paced`): by state index, the radius in
  // which each member's box lets it move (its pace radius; the local stepper's, and the
  // integrator's step respects it). In the state's order because the step's choice reads it
  // for every member at every step: by sample index, that load missed the cache for most members
  // at a million grains (half of the choice's time). Not paced: every member's box allows its
  // own radius.
  bool paced = false;
  std::vector<double> allowance;
  double time = 0;
  EngineStats stats;
};

}  // namespace sedem
