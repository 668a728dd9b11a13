#pragma once

// Integrators of Eq. 5, one class each; they read the force pass's sums and move the state.
//
// reference: explicit (symplectic Euler: v += dt a, then x += dt v), as close to the paper as an
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
//   The step never exceeds 1.9 m/c of the stiffest drag (the explicit drag's stability bound).
//
// exponential: the drag is linear in the velocity over a step (Stokes exactly; Di Felice with its
//   coefficient frozen at the step's start), so m dv/dt = F - c v is solved exactly over the
//   step: v = v_inf + (v0 - v_inf) e^(-dt/tau), x advanced by the integral, with no contact
//   force. Contacts are then overdamped, compliant constraints (contact_projection.h): Jacobi
//   sweeps find each contact's force so that the overlap ends at force / K_N, each grain moving
//   in proportion to its mobility over the step; a touching pair falls at its mobility-weighted
//   mean velocity and a grain on the bed rests at overlap = net weight / K_N. No friction.
//   Fixed step: fast_step_factor * min t_tr (default 100, i.e. 1000x the reference's start),
//   at most r_min / u_max so that no grain passes through another between two steps (u_max:
//   the largest grain's clear-water settling speed). docs/engine.md has the details.

#include <algorithm>
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <vector>

#include "core/engine/engine_config.h"
#include "core/engine/engine_state.h"
#include "core/engine/force_pass.h"
#include "core/engine/forces.h"
#include "core/engine/neighbour_grid.h"
#include "core/engine/voidage_grid.h"

namespace sedem {

// The drag as a linear coefficient c (F = -c v), for the integrators.
struct DragEvaluator {
  const ForceModel* model = nullptr;
  const VoidageGrid* voidage = nullptr;
  double tail_re = 0;  // below it the Di Felice exponent's Re term is lost to round-off
  double coefficient(double d, double speed, double x, double y) const;
};

// The Reynolds number below which 0.65 exp(-(1.5 - log10 Re)^2 / 2) |ln eps| < 2^-54 for every
// voidage down to `min_voidage`, with a margin.
double di_felice_tail_re(double min_voidage);

struct IntegratorContext {
  const ForceModel* model = nullptr;
  DragEvaluator drag;
  int threads = 1;
  double min_response_time = 0;  // t_tr (95 %) of the smallest grain
  double min_terminal_speed = 0;
  double runaway_speed = 1;  // above this a speed counts as a blow-up
  double min_radius = 0;
  double max_terminal_speed = 0;  // Stokes / 0.96 of the largest grain: no free grain is faster
  // exponential: the candidate lists its contact projection gathers over (the engine's).
  const NeighbourGrid* grid = nullptr;
  const ForcePass* pass = nullptr;
  int contact_sweeps = 32;  // at most, per step
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
};

std::unique_ptr<Integrator> make_integrator(const IntegratorConfig& config,
                                            const IntegratorContext& context);

}  // namespace sedem
