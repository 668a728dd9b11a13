#pragma once

// Contacts of the exponential integrator as overdamped constraints (XPBD-like). After the free
// update (drag, weight, buoyancy, lubrication; no contact force), each touching pair or wall
// gets a force lambda >= 0 that, applied constantly over the step, moves particle i by w_i lambda
// along the normal (w_i: its mobility, the displacement per unit force over the step) and leaves
// the overlap at lambda / K_N (compliance 1/K_N: a backward-Euler normal spring). The forces are
// found by Jacobi sweeps over the constraints,
//   dlambda = max(-lambda, (overlap - lambda / K_N) / (n_a w_a + n_b w_b + 1 / K_N)),
// n the number of contacts of each particle: a Gershgorin bound on the constraint system, so
// every sweep is a contraction. Each pair's dlambda is computed once and moves both partners
// (exact action and reaction). The sweeps go on until every overlap is within a tolerance of
// its target; each *island* (particles linked by constraints, touching or within the skin, which
// move only each other) stops on its own once it is within it: one deep pile no longer keeps
// every other pair of the step sweeping to the last of the sweeps.
//
// One pass over the candidate lists (contact/candidate_lists.h), at the free positions, collects
// the constraints: every pair or wall closer than a skin of half the smaller radius, or that held a
// force at the end of the last step (each step starts from those forces, kept by sample indices
// so that re-sorting and list rebuilds keep them; saved in checkpoints: a resting bed is held
// from the first sweep). The sweeps then run over that compact list only, so a dilute
// suspension, where almost nothing touches, pays for the one pass. Within a sweep every
// constraint reads the positions the sweep started from (Jacobi), and every particle sums its
// constraints' moves in a fixed order: the result does not depend on the thread count. Pairs
// pushed into contact from beyond the skin within one step are resolved at the next step.
//
// Friction (forces.friction > 0; walls stay frictionless, as in the explicit integrator):
// each touching pair also gets a tangential force lambda_t, the compliant spring of Eq. 2,
// lambda_t = -K_T g, with g the tangential displacement of a's contact point against b's
// accumulated over the contact's life (the last step's -lambda_t / K_T plus this step's
// relative motion, spins r w dt included), held by the Coulomb limit |lambda_t| <= mu lambda_n
// of Eq. 4 (sliding when it binds). Its Jacobi update is the normal one's, along t, with the
// rotations' mobility r^2 dt^2 / (2 I) added (I = m d^2 / 10; no drag on the spin, as in the
// explicit integrator); the spins change by the torques r lambda_t. lambda_t does not depend on
// which grain is a, and is kept across steps with lambda_n.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <vector>

#include "core/engine/contact/candidate_lists.h"
#include "core/engine/contact/neighbour_grid.h"
#include "core/engine/forces/force_model.h"
#include "core/engine/instability.h"
#include "core/engine/state/disjoint_sets.h"
#include "core/engine/state/engine_state.h"
#include "core/engine/state/pair_history.h"

namespace sedem {

// A constant force over a step of a particle under linear drag c (0: none), mass m: the
// displacement it gives per unit force (`mobility`) and the velocity change per unit of that
// displacement (`response`). With rate = c/m and a = rate dt, the force F moves the particle by
// F (a + e^(-a) - 1) / (rate c) and changes its velocity by F (1 - e^(-a)) / c.
struct Mobility {
  double mobility = 0, response = 0;
};

// The decay's loss over a step, e^(-dt c / m) - 1 from one call (c > 0); past 40 response times
// it is -1 to round-off. The free update's and the mobility's, the same bits.
inline double decay_lost(double c, double mass, double dt) {
  const double a = dt * (c / mass);
  return a > 40 ? -1.0 : std::expm1(-a);
}

// `lost`: decay_lost(c, mass, dt) (unused where c = 0).
inline Mobility mobility_of(double c, double mass, double dt, double lost) {
  if (c > 0) {
    const double rate = c / mass, a = dt * rate;
    // a + lost = a^2/2 - a^3/6 + ... cancels for small a: its series there.
    const double drift = a < 1e-3 ? a * a * (0.5 - a * (1.0 / 6 - a / 24)) : a + lost;
    return {drift / (rate * c), -lost * rate / drift};
  }
  return {0.5 * dt * dt / mass, 2.0 / dt};
}

inline Mobility mobility_of(double c, double mass, double dt) {
  return mobility_of(c, mass, dt, c > 0 ? decay_lost(c, mass, dt) : 0.0);
}

struct ProjectionFacts {
  std::size_t touching = 0;      // particles touching at the free positions
  double max_overlap_ratio = 0;  // after the projection: overlap / smaller radius, worst
  Blowup blowup;
};

class ContactProjection {
 public:
  // `grains`: the sample's size; particles are keyed by their sample index (`origin`), which
  // with local time stepping may exceed the count of particles the state holds.
  void configure(const ForceModel& model, int threads, int sweeps, std::size_t grains);
  // `drag[i]`: the linear drag coefficient particle i had over the step (mobility_of gives its
  // mobility); `lost[i]` (or nullptr): its decay_lost, which the free update computed already.
  // Moves (x, y) from their free values and adds the matching velocity change. With friction
  // (friction()), (start_x, start_y) are the positions at the start of the step (before the free
  // update), for the tangential motion over it; required. `aside` (by sample index, or nullptr):
  // grains this run leaves out, held frozen in `s` by the caller while others take a step of their
  // own (carried sub-steps). The forces of their pairs that no moving grain of this run is part of
  // stay as the last run left them. `rows` (ascending, or nullptr: all): the only rows of the lists
  // that hold a pair with a grain this run moves.
  ProjectionFacts run(EngineState& s, const NeighbourGrid& grid, const CandidateLists& lists,
                      const std::vector<double>& drag, double dt, const double* start_x = nullptr,
                      const double* start_y = nullptr, const std::uint8_t* aside = nullptr,
                      const std::vector<std::uint32_t>* rows = nullptr,
                      const std::vector<double>* lost = nullptr);
  bool friction() const { return friction_; }
  // touching[i] > 0 for every particle in contact after the last run, 0 otherwise (size n).
  void mark_touching(std::vector<double>& touching) const;
  // The particles the last run's constraints involved (engine order): the only ones it moved.
  const std::vector<std::uint32_t>& participants() const { return particle_; }
  // Appends the particles (engine order) in contact after the last run.
  void append_touching(std::vector<std::uint32_t>& out) const;
  // The pairs (sample indices; a wall as partner kSide or kFloor) that held a force at the end
  // of the last run, or that a loaded checkpoint says did.
  const std::vector<PairHistory::Entry>& held_pairs() const { return kept_; }
  static bool is_wall(std::uint32_t partner) { return partner >= kSide; }
  std::size_t bytes() const;
  void save(std::ostream& out) const;
  void load(std::istream& in);

 private:
  static constexpr std::uint32_t kSide = 0xFFFFFFFE, kFloor = 0xFFFFFFFF;  // partner b
  static constexpr std::uint32_t kNone = 0xFFFFFFFF;
  struct Constraint {
    std::uint32_t a, b;            // engine indices; b = kSide or kFloor for a wall
    std::uint32_t slot_a, slot_b;  // in the participants (slot_b unused for a wall)
    double lambda;
    double mx, my;        // this sweep: a moves by w_a (mx, my), b by -w_b (mx, my)
    bool active;          // touching or pushing at this sweep's positions
    double lambda_t = 0;  // tangential force on a along t = (-n_y, n_x), n from a to b
    double spring = 0;    // g carried from the last step: -lambda_t / K_T then
    double mt = 0;        // this sweep: a turns by wr_a r_a mt, b by wr_b r_b mt
  };
  struct Incidence {
    std::uint32_t constraint;
    bool is_b;
  };
  enum class Mode {
    start,  // count each particle's contacts; the forces of the last step
    warm,   // displacements of the current forces, unchanged
    solve,  // one Jacobi sweep: change the forces, their displacements
  };
  void collect(const EngineState& s, const NeighbourGrid& grid, const CandidateLists& lists,
               const std::vector<std::uint32_t>* rows);
  void index_participants(const EngineState& s, const std::vector<double>& drag,
                          const std::vector<double>* lost, double dt);
  // The tangential force's change of constraint c in a solving sweep (sets c.mt), friction on.
  double friction_change(Constraint& c, const EngineState& s, double dx, double dy, double dist,
                         double share_a, double share_b);
  // One sweep at the current positions; moves the participants. Solving, it notes each active
  // constraint's overlap beyond its compliant target / smaller radius, and leaves the islands
  // already converged as they are.
  void sweep(EngineState& s, Mode mode);
  // The islands: participants linked by pairs' constraints (touching or within the skin), which
  // move only each other.
  void find_islands();
  // After a solving sweep: marks the islands it found converged; true once all are.
  bool mark_converged();
  // Keeps in the active lists only the constraints, participants and islands not converged.
  void narrow();
  void keep(const EngineState& s, const std::uint8_t* aside);

  ForceModel model_;
  int threads_ = 1, sweeps_ = 32;
  std::size_t grains_ = 0;
  std::vector<std::vector<Constraint>> found_;  // per thread, at collection
  std::vector<Constraint> constraints_;
  std::vector<Incidence> incidences_;  // grouped by participant, in constraint order
  // Per participant: engine index, mobility, response, contact counts, first incidence,
  // correction summed apart from the position (x - x_free would lose it to round-off).
  std::vector<std::uint32_t> particle_, count_, first_;
  std::vector<double> mobility_, response_, moved_x_, moved_y_;
  // Friction: per participant, the spin's mobility (turn per unit torque over the step) and its
  // turn so far (spin * dt, then the corrections); during run(), the step's start positions
  // (engine order, the integrator's).
  std::vector<double> spin_mobility_, turned_;
  const double *start_x_ = nullptr, *start_y_ = nullptr;
  bool friction_ = false;
  std::vector<std::uint32_t> slot_of_;  // per particle (engine order): its slot, or kNone
  // Islands: per slot its island; per constraint its island and its excess in the last sweep
  // (overlap beyond its compliant target / smaller radius); per island whether it converged.
  std::vector<std::uint32_t> island_of_slot_, island_of_constraint_;
  std::vector<double> excess_, island_worst_;
  std::vector<std::uint8_t> converged_;
  // While narrowed_, the solving sweeps visit only these: the islands not yet converged and
  // their constraints and participants, in order. At a million grains a step's sweeps ran on
  // while one pile needed them, and 95 % of the constraints they visited were converged.
  std::vector<std::uint32_t> active_constraints_, active_slots_, active_islands_;
  bool narrowed_ = false;
  DisjointSets islands_;  // find_islands' union-find over slots
  // Per particle (sample order): a bit for each partner that held a force with it at the end
  // of the last step (partner_bit; 0: none). A pair is looked up in warm_ only where each has
  // the other's bit: most pairs of held grains did not touch, and the lookup is a cache miss.
  std::vector<std::uint8_t> held_;
  static std::uint8_t partner_bit(std::uint32_t partner) {
    return std::uint8_t(1u << ((partner * 0x9E3779B1u) >> 29));
  }
  std::vector<std::uint32_t> held_list_;  // the grains whose held_ is not 0
  void hold_both(std::uint64_t key);
  // The forces held at the end of the last step, in the constraints' order (then those set
  // aside): collect reads them in that order where it can (WarmCursor), and warm_ otherwise.
  std::vector<PairHistory::Entry> kept_;
  PairHistory warm_;  // forces at the end of the last step; walls as partners kSide, kFloor
  PairHistory warm_tangential_;  // friction: the pairs' lambda_t at the end of the last step
  std::vector<PairHistory::Entry> kept_tangential_;
  std::vector<PairHistory::Entry> set_aside_, set_aside_tangential_;  // keep's scratch
  std::vector<std::uint8_t> moving_;  // keep's scratch, by sample index: moved in this run
};

}  // namespace sedem
