#pragma once

// Integrators of Eq. 5, one class each; they read the force pass's sums and move the state.
//
// explicit: symplectic Euler (v += dt a, then x += dt v), as close to the paper as an
//   explicit scheme gets. Step rule (Sect. 4.6): dt = step_factor * min t_tr (t_tr: time to 95 %
//   of the terminal velocity of the smallest grain; 0.1 in the paper). Once every free particle
//   has reached its terminal velocity (velocity change per step below 1e-3 u_tr over a check
//   window) the step grows by 10 % per window until velocity changes turn unstable (a jump
//   above 5 % of u_tr): the step is then cut by 10 % and kept below that ceiling. An explicit
//   scheme also needs the contact springs resolved: while any particle touches, dt is at most
//   0.1 sqrt(m / (K_N + K_T)) of the lightest touching particle. Contacts must be entered with
//   that small step, not discovered deep after a large one (the spring would return more energy
//   than the grain brought): pairs closer than a skin of 0.25 radii count as touching, and the
//   step keeps every grain from crossing half the smallest skin (0.5 skin r_min / v_max).
//   Where the drag felt in the last step is stiffer than the smallest grain's in clear water
//   (a packed voidage cell), the step shrinks in proportion.
//
// exponential: the drag is linear in the velocity over a step (Stokes exactly; Di Felice with its
//   coefficient frozen at the step's start), so m dv/dt = F - c v is solved exactly over the
//   step: v = v_inf + (v0 - v_inf) e^(-dt/tau), x advanced by the integral, with no contact
//   force. Contacts are then overdamped, compliant constraints (contact_projection.h): Jacobi
//   sweeps find each contact's force so that the overlap ends at force / K_N, each grain moving
//   in proportion to its mobility over the step; a touching pair falls at its mobility-weighted
//   mean velocity and a grain on the bed rests at overlap = net weight / K_N. Friction: a
//   tangential constraint per pair within the Coulomb limit, with the spins it turns.
//   Step: the exact drag update needs no step limit of its own; what binds is that no grain may
//   pass through another between two steps. After every step the next one is set so that no
//   moving grain travels more than crossing_fraction (0.8) of its own radius, at its speed or,
//   if nothing supports it, at least its clear-water settling speed: two grains then close by
//   less than 0.8 (r_i + r_j) in a step, and no centre passes another. Since that speed grows as
//   d^2, the largest grain still moving sets the step, which therefore grows as the coarse grains
//   settle out. It is also at most fast_step_factor * min t_tr and max_step. docs/engine.md has the
//   details. With carried steps (local steps only) a grain held against a coarser one, which
//   moves with it, may travel crossing_fraction of the coarser one's radius a step (bounded by
//   its lists' margin and its box), and every listed pair at most closes by its gap plus
//   crossing_fraction (r_i + r_j): the same bound on how deep two grains can meet, without a
//   pushed fine grain setting every member's step. With carried sub-steps the grains the step
//   would carry further than their own radius allows, and every member that could reach them
//   within it, take sub-steps of their own inside it at the own-radius rule, the others held
//   still: the one-rate scheme's contacts at carried steps' count of steps.

#include <algorithm>
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <vector>

#include "core/engine/contact/candidate_lists.h"
#include "core/engine/contact/neighbour_grid.h"
#include "core/engine/engine_config.h"
#include "core/engine/forces/drag_evaluator.h"
#include "core/engine/forces/force_model.h"
#include "core/engine/forces/force_pass.h"
#include "core/engine/state/engine_state.h"

namespace sedem {

struct IntegratorContext {
  const ForceModel* model = nullptr;
  DragEvaluator drag;
  int threads = 1;
  double min_response_time = 0;  // t_tr (95 %) of the smallest grain
  double min_terminal_speed = 0;
  double runaway_speed = 1;  // above this a speed counts as a blow-up
  double min_radius = 0;
  double max_terminal_speed = 0;  // Stokes / 0.96 of the largest grain: no free grain is faster
  double max_radius = 0;
  // exponential: the candidate lists its contact projection gathers over (the engine's).
  const NeighbourGrid* grid = nullptr;
  const CandidateLists* lists = nullptr;
  int contact_sweeps = 32;  // at most, per step
  std::size_t grains = 0;   // the sample's size (sample indices run below it)
  // Local time stepping: the state holds only the grains near a contact, few and about to
  // part, so the step counts every moving grain at least at its settling speed (a grain a
  // contact slowed may fall free within the step), not only the unsupported ones.
  bool members_only = false;
  // Local steps: by state index, the radius in which each member's box lets it move (its
  // pace; null: its own radius, as in the global scheme and without suspension contacts): a
  // step lets a member travel crossing_fraction of it. Carried steps (integrator.carried_fraction >
  // 0): also the sample's diameters. Both are owned by the engine.
  bool carried_steps = false;
  const std::vector<double>* sample_diameter = nullptr;
  const std::vector<double>* allowance = nullptr;
  const EngineState* state = nullptr;  // the engine's (carried steps: its frozen grains on load)
};

// What set the step with local steps (the bench reports it, docs/engine.md): the members
// moving faster than kPushedSpeedRatio times their settling speed, which only a push from a
// coarser grain gives them, and the step the other members alone would allow. Their ratio to
// the step taken is what stepping the pushed grains apart could save.
struct StepLimit {
  static constexpr double kPushedSpeedRatio = 3;
  std::size_t pushed = 0;
  double unpushed_step = 0;  // s; 0: not known (the global scheme, carried steps)
};

struct SubstepReport {
  std::size_t fast = 0, taken = 0;
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual const char* name() const = 0;
  // The step to take next, given the facts of the previous force pass.
  virtual double next_step(const PassFacts& last) = 0;
  // Moves every particle that is not frozen over dt; notes the first blow-up it sees.
  virtual void advance(EngineState& s, const ForceAccumulators& f, double dt, Blowup& blowup) = 0;
  virtual void save(std::ostream& out) const = 0;
  virtual void load(std::istream& in) = 0;
  virtual std::size_t bytes() const { return 0; }  // working memory
  // When the force pass did not run (see needs_force_pass): the contacts the last advance
  // found, into `facts`, and touching[i] > 0 for every particle then in contact.
  virtual void contact_facts(PassFacts&) const {}
  virtual void mark_touching(std::vector<double>& touching) const {
    std::fill(touching.begin(), touching.end(), 0.0);
  }
  // The particles the state holds changed (local time stepping, where the step counts every
  // moving particle at least at its settling speed): the next step is chosen again. With
  // `appended_from` < s.size(), only particles appended from there on changed since the step
  // was last chosen (and their candidate lists' rows): the step is bounded by them too, the same
  // bits as chosen afresh.
  virtual void refresh_step(const EngineState&, std::size_t /*appended_from*/ = 0) {}
  // Carried steps: by sample index, each grain's pace radius: the largest radius among the
  // grains it touches, directly or through others, at the end of the last step, times
  // carried_fraction / crossing_fraction, or its own radius if that is more (or it touches
  // none); a step lets it travel crossing_fraction of that. nullptr without carried steps.
  virtual const std::vector<double>* carrier_radii() const { return nullptr; }
  // Local steps: how far member k (state index) may travel in the step last chosen, at its
  // speed or at least its settling speed (what the step's rule counts); 0 if none was chosen.
  virtual double travel_in_step(const EngineState&, std::size_t /*k*/) const { return 0; }
  // Carried sub-steps: the fast set of the last advance and the sub-steps it took ({0, 0}: the
  // step was not split).
  virtual SubstepReport substeps() const { return {}; }
  // For the step next_step gives; see StepLimit.
  virtual StepLimit step_limit() const { return {}; }
  // Own steps (integrator.own_steps): a step taken in parts instead of one advance. Between
  // begin_parts and end_parts each advance_part moves the members `only` (state indices, none
  // frozen) over its own dt, the caller holding every other particle frozen and, by sample
  // index, `aside` (whose pairs' forces the projection keeps); the projection reads `rows` only
  // (those holding a pair with one of them). end_parts reports the contacts of every part
  // (contact_facts, mark_touching) and chooses the next step as advance would.
  virtual void begin_parts() {}
  virtual void advance_part(EngineState&, const ForceAccumulators&, double /*dt*/,
                            const std::vector<std::uint32_t>& /*only*/,
                            const std::vector<std::uint32_t>& /*rows*/,
                            const std::uint8_t* /*aside*/, Blowup&) {}
  virtual void end_parts(const EngineState&) {}
  // Own steps: the rate of members `only` (state indices; all if nullptr) under the step rule,
  // into rate (sized to the state): its speed, at least its settling speed, over its pace
  // radius (0 if frozen). And the longest step a rate allows: crossing_fraction over it, at most
  // the ceiling.
  virtual void own_rates(const EngineState&, const std::vector<std::uint32_t>* /*only*/,
                         std::vector<double>& rate) const {
    rate.clear();
  }
  virtual double step_at_rate(double /*radii_per_s*/) const { return 0; }
};

std::unique_ptr<Integrator> make_integrator(const IntegratorConfig& config,
                                            const IntegratorContext& context);
// One per integrator (explicit_integrator.cpp, exponential_integrator.cpp); make_integrator
// chooses.
std::unique_ptr<Integrator> make_explicit_integrator(const IntegratorConfig& config,
                                                     const IntegratorContext& context);
std::unique_ptr<Integrator> make_exponential_integrator(const IntegratorConfig& config,
                                                        const IntegratorContext& context);

}  // namespace sedem
