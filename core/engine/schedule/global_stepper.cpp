#include "core/engine/schedule/global_stepper.h"

#include <algorithm>
#include <utility>

namespace sedem {

GlobalStepper::GlobalStepper(EngineParts& parts) : e_(parts) {
  if (e_.state.size() > 0) {
    e_.rebuild_lists();
    if (e_.pass_needed)
      e_.pass.run(e_.state, e_.grid, e_.lists, e_.springs, e_.next_springs, 0.0, e_.forces,
                  e_.facts);
    e_.next_springs = PairHistory{};
  }
}

void GlobalStepper::step(double limit) {
  const std::size_t n = e_.state.size();
  double dt = e_.integrator->next_step(e_.facts);
  const bool last = e_.time + dt >= limit;
  if (last) dt = limit - e_.time;

  if (e_.model.drag == DragLaw::di_felice)
    e_.voidage.compute(n, e_.state.x.data(), e_.state.y.data(), e_.state.diameter.data(),
                       e_.state.weight.data());
  if (e_.lists.stale) e_.resort_and_rebuild_lists();
  if (e_.pass_needed) {
    e_.pass.run(e_.state, e_.grid, e_.lists, e_.springs, e_.next_springs, dt, e_.forces, e_.facts);
    if (e_.facts.blowup.found) e_.throw_blowup(e_.facts.blowup, e_.time);
    if (e_.model.friction) std::swap(e_.springs, e_.next_springs);
  }

  Blowup blowup;
  e_.integrator->advance(e_.state, e_.forces, dt, blowup);
  if (!e_.pass_needed) e_.integrator->contact_facts(e_.facts);
  e_.time = last ? limit : e_.time + dt;
  EngineStats& stats = e_.stats;
  stats.steps += 1;
  stats.particle_steps += double(n - stats.frozen);
  stats.last_step = dt;
  stats.contacts = e_.facts.contacts;
  stats.max_overlap_ratio = std::max(stats.max_overlap_ratio, e_.facts.max_overlap_ratio);
  if (blowup.found) e_.throw_blowup(blowup, e_.time);
  if (e_.freeze.due(stats.steps)) {
    if (!e_.pass_needed) e_.integrator->mark_touching(e_.forces.stiffness);
    stats.frozen = e_.freeze.run(e_.state, e_.forces.stiffness, e_.model, e_.setup.fluid);
  }
  e_.lists.stale = e_.lists.moved_beyond_margin(e_.state);
}

}  // namespace sedem
