#pragma once

// The DEM engine: Eq. 5 for every particle, forces of Sect. 3 and 4.2 (see forces.h), the
// integrators of Sect. 4.6 (see integrators.h), neighbour search in neighbour_grid.h.
// One step: voidage grid (Di Felice only) -> neighbour grid -> force pass -> integrator;
// Candidate lists (Verlet) are rebuilt from the grid when a particle has moved more than its
// radius since the last build (the search radii carry a margin of two radii); at most
// every 16 steps the rebuild first re-sorts the state in grid order. Every 64 steps resting
// particles below the lowest instrument are frozen. A blow-up throws InstabilityError.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/engine/contact/box_registry.h"
#include "core/engine/contact/neighbour_grid.h"
#include "core/engine/engine_setup.h"
#include "core/engine/forces/force_model.h"
#include "core/engine/forces/force_pass.h"
#include "core/engine/forces/voidage_grid.h"
#include "core/engine/instability.h"
#include "core/engine/integrate/free_flight.h"
#include "core/engine/integrate/integrators.h"
#include "core/engine/state/engine_state.h"
#include "core/engine/state/pair_history.h"
#include "core/model/engine_stats.h"
#include "core/model/particles.h"
#include "core/model/sample.h"
#include "core/model/snapshot.h"

namespace sedem {

class Engine {
 public:
  Engine(const EngineSetup& setup, Sample sample);
  ~Engine();

  double time() const { return time_; }
  // The particles in the sample's order, brought up to date on demand.
  const Particles& particles() const;
  const Sample& sample() const;
  const EngineStats& stats() const { return stats_; }

  // Advances to exactly `t` (no-op if t <= time()). Throws InstabilityError on a blow-up.
  void advance_to(double t);
  // One step of the integrator's choosing (the last one shortened to land on `limit`).
  void step(double limit);
  Snapshot snapshot() const { return Snapshot{time_, particles()}; }

  // The full state (positions, velocities, spins, frozen flags, tangential springs, time,
  // step rule): resuming with the same scene, sample and thread count continues bit for bit.
  void save_checkpoint(const std::string& path) const;
  void load_checkpoint(const std::string& path);

  const char* integrator_name() const { return integrator_->name(); }
  int threads() const { return threads_; }
  // Whether free grains coast on windows of their own (integrator.local_steps).
  bool local_steps() const { return local_; }
  // With local steps, the first broken promise of the scheme (a grain outside its box, a
  // window ended unlooked-at, two boxes overlapping that must not), or "" (for tests).
  std::string local_violation() const;
  double freeze_height() const { return freeze_height_; }
  // With local steps: below this height grains leave the dynamics for the coarse bed (0: none).
  double retire_height() const { return retire_height_; }
  // Heap bytes held by the engine, its copy of the sample included.
  std::size_t bytes() const;
  // Kinetic energy of translation and rotation, J (a diagnostic for tests and benchmarks).
  double kinetic_energy() const;

 private:
  void freeze_resting();
  // Local time stepping (engine_local.cpp).
  void start_local();
  void step_local(double limit);
  bool coast(std::uint32_t id, double t, const FreeFlight::Point& p, bool commit,
             Box* needed = nullptr);
  bool make_room(std::uint32_t id, double t, const FreeFlight::Point& p);
  void note_ahead(std::uint32_t id, double t, const Box& before, double t0_before);
  bool resync_clear_of(std::uint32_t id, const Box& reach);
  bool passes(std::uint32_t j) const;
  void hold_coasting_box(std::uint32_t id, const Box& box);
  FreeFlight flight_of(std::uint32_t id, const FreeFlight::Point& p) const;
  FreeFlight::Point coasting_at(std::uint32_t id, double t) const;
  void engage(std::uint32_t id, const FreeFlight::Point& p, bool frozen);
  void wake_around(std::uint32_t id);
  void anchor(std::size_t k);
  void remove_member(std::size_t k);
  void release_members();
  void settle_members();
  void index_members();
  void move_deposit(std::uint32_t id, double x, double y);
  void retire(std::uint32_t id, double t, const FreeFlight::Point& p);
  void retire_members();
  FreeFlight::Point retired_at(std::uint32_t id, double t) const;
  Box member_box(std::size_t k) const;
  void save_local(std::ostream& out) const;
  void load_local(std::istream& in);
  void resort();
  void rebuild_lists();
  bool moved_beyond_margin();

  EngineSetup setup_;
  mutable Sample sample_;
  mutable std::int64_t synced_step_ = -1;
  EngineState state_;
  ForceAccumulators forces_;
  std::vector<double> search_;      // search radius: radius + lubrication reach + skins + margin
  std::vector<double> x0_, y0_;     // positions when the candidate lists were built
  std::vector<double> top_excess_;  // per thread: the two largest moves beyond the margin
  bool lists_stale_ = true;
  bool pass_needed_ = true;  // see needs_force_pass
  std::int64_t resorted_at_ = 0;
  std::vector<double> scratch_;
  std::vector<std::uint32_t> scratch_index_;
  std::vector<std::uint8_t> scratch_flag_;
  ForceModel model_;
  NeighbourGrid grid_;
  VoidageGrid voidage_;
  ForcePass pass_;
  PairHistory springs_, next_springs_;
  PassFacts facts_;
  std::unique_ptr<Integrator> integrator_;
  int threads_ = 1;
  double freeze_height_ = 0;
  double margin_ = 2;  // of the candidate lists, in radii
  double time_ = 0;
  EngineStats stats_;

  // Local time stepping: each grain is coasting (on its exact free trajectory `flight_` from
  // t0_ until t1_), a member of the common step (in state_, at index member_), or settled (a
  // frozen grain no member can reach, kept out of state_), or retired (below every instrument,
  // falling on flight_ from t0_ onto the coarse bed, to rest at (t1_, land_y_)). See
  // engine_local.cpp.
  enum : std::uint8_t { kCoasting = 0, kMoving = 1, kFrozen = 2, kSettled = 3, kRetired = 4 };
  bool local_ = false;
  bool members_changed_ = false;
  std::vector<std::uint8_t> kind_;
  std::vector<FreeFlight> flight_;  // coasting: from t0_; members: anchor of their box in x, y
  std::vector<double> t0_, t1_;
  std::vector<std::uint32_t> member_, deposit_cell_;
  std::vector<std::pair<double, std::uint32_t>> syncs_;  // min-heap of (t1_, id)
  BoxRegistry boxes_;
  std::vector<std::uint32_t> near_, wake_, failed_;  // scratch
  struct Ahead {
    std::uint32_t id;
    double time;
    Box before, after;
    bool widened;
  };
  std::vector<Ahead> ahead_;               // synced within this step, with the box they had
  std::vector<std::uint32_t> ahead_slot_;  // per grain: its latest entry in ahead_
  std::vector<Ahead> widened_;  // synced ahead of a shortened step: boxes to narrow later
  struct Room {
    std::uint32_t id;
    FreeFlight::Point at;  // where it is at the sync that moves it
    Box before;            // its box until then
    double t0;             // its window's start until then
  };
  std::vector<Room> room_;            // scratch of make_room
  std::vector<std::uint32_t> found_;  // scratch of wake_around
  DragEvaluator drag_;
  double registry_cell_ = 1e-3, travel_ = 1e-3;
  std::size_t settled_ = 0;
  double retire_height_ = 0;    // 0: no grain retires
  std::vector<double> land_y_;  // retired grains: the height of their centre on the bed
  std::vector<double> bed_;     // the coarse bed: the height of each column's top
  double bed_column_ = 1e-4;    // the columns' width
};

}  // namespace sedem
