#include "core/engine/schedule/engine_parts.h"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "core/engine/instability.h"
#include "core/physics/stokes.h"

namespace sedem {

namespace {

ForceModel force_model(const EngineSetup& setup, double particle_density) {
  const ForcesConfig& f = setup.forces;
  ForceModel m;
  m.weight = f.weight;
  m.buoyancy = f.buoyancy;
  m.contact = f.contact;
  m.suspension_contacts = f.suspension_contacts;
  m.friction = f.contact && f.friction > 0;
  m.lubrication = f.lubrication;
  m.drag = f.drag == "off"      ? DragLaw::off
           : f.drag == "stokes" ? DragLaw::stokes
                                : DragLaw::di_felice;
  m.voidage_excludes_self = f.voidage_excludes_self;
  m.kn = f.stiffness_normal;
  m.kt = f.stiffness_tangential;
  m.mu = f.friction;
  m.lubrication_intensity = f.lubrication_intensity;
  m.lubrication_range = f.lubrication_range;
  m.particle_density = particle_density;
  m.fluid_density = setup.fluid.density;
  m.viscosity = setup.fluid.viscosity;
  m.gravity = setup.fluid.gravity;
  m.half_width = setup.cylinder.half_width();
  return m;
}

// The margin of the candidate lists, in radii. The exponential integrator's grains move up to
// crossing_fraction radii a step; a margin of a few steps' travel keeps rebuilds to one every
// few steps (a dilute suspension has almost no candidates anyway, and a settled bed is mostly
// frozen), 3 radii at least.
double list_margin(const IntegratorConfig& c) {
  return integrator_method(c) == IntegratorMethod::explicit_euler
             ? 3.0
             : std::max(3.0, 4.0 * c.crossing_fraction);
}

}  // namespace

EngineParts::EngineParts(const EngineSetup& engine_setup, Sample engine_sample)
    : setup(engine_setup), sample(std::move(engine_sample)) {
  const Particles& p = sample.particles;
  const std::size_t n = p.size();
  threads = setup.integrator.threads > 0 ? int(setup.integrator.threads) : omp_get_max_threads();
  // Below a few thousand particles a step takes microseconds and forking threads costs more.
  if (n < 2048) threads = 1;
  model = force_model(setup, sample.particle_density);
  // Local time stepping needs no force pass, so not with lubrication. Its syncs are taken one
  // at a time, in time order, where grains meet, and the members' step (lists, integration,
  // projection) has the engine's threads when they are many (threads_for.h); where the free
  // grains pass each other (no suspension contacts), each column of voidage cells is a lane of
  // its own, the lanes go on the engine's threads (local_lanes.cpp), and the few members' step
  // has one. The voidage of the local steps changes a grain at a time, serially; its first
  // count is serial too, as a sum over threads would round differently on each thread count.
  local = takes_local_steps(setup);
  if (local && (!model.contact || !model.suspension_contacts)) {
    sync_threads = threads;
    threads = 1;
  }
  if (integrator_method(setup.integrator) == IntegratorMethod::explicit_euler)
    model.skin = 0.25;
  else
    model.contact_forces = false;  // the exponential integrator projects contacts

  state.resize(n);
  pass_needed = needs_force_pass(model);
  if (pass_needed) forces.resize(n);
  lists.search.resize(n);
  double dmin = 0, dmax = 0;
  for (std::size_t i = 0; i < n; ++i) {
    state.x[i] = p.x[i];
    state.y[i] = p.y[i];
    state.vx[i] = p.vx.empty() ? 0 : p.vx[i];
    state.vy[i] = p.vy.empty() ? 0 : p.vy[i];
    state.omega[i] = p.omega.empty() ? 0 : p.omega[i];
    state.diameter[i] = p.diameter[i];
    state.weight[i] = p.weight[i];
    state.origin[i] = std::uint32_t(i);
    state.frozen[i] = 0;
    dmin = i == 0 ? p.diameter[i] : std::min(dmin, p.diameter[i]);
    dmax = std::max(dmax, p.diameter[i]);
  }
  const double reach = model.lubrication_reach();
  lists.margin = list_margin(setup.integrator);
  for (std::size_t i = 0; i < n; ++i)
    lists.search[i] = 0.5 * state.diameter[i] * (1 + reach + model.skin + lists.margin);
  if (n == 0) dmin = dmax = 1e-6;

  const Cylinder& cyl = setup.cylinder;
  grid.configure(dmin * (1 + reach + model.skin + lists.margin),
                 dmax * (1 + reach + model.skin + lists.margin), cyl.half_width(), cyl.height,
                 threads);
  voidage.configure(setup.forces.voidage_cell, cyl.half_width(), cyl.height, cyl.slab_thickness(),
                    setup.forces.min_voidage, local ? 1 : threads);
  pass.configure(model, threads);
  lists.configure(threads);
  carried = local && setup.integrator.carried_fraction > 0 && model.contact;
  // Local steps size each grain's margin by its pace (CandidateLists::size_margins): the whole
  // test of sample 5 at 10^5 grains built the lists 29 % less often. Carried steps size them by
  // the carriers.
  lists.margin_per_grain = local && model.contact;
  lists.check_pairs = lists.margin_per_grain && !carried;
  lists.range = 1 + reach + model.skin;
  // Without suspension contacts the members are the few grains at the walls and the bed: their
  // boxes keep their radii, and ten million grains are spared 80 MB.
  paced = local && model.contact && (model.suspension_contacts || carried);  // filled by engage

  const Fluid& fluid = setup.fluid;
  IntegratorContext ctx;
  ctx.model = &model;
  ctx.drag = DragEvaluator{&model, &voidage, di_felice_tail_re(setup.forces.min_voidage)};
  ctx.threads = threads;
  ctx.min_response_time = stokes::response_time(dmin, model.particle_density, fluid, 0.95);
  ctx.min_terminal_speed = stokes::terminal_velocity(dmin, model.particle_density, fluid);
  // Contacts between the smallest grains legitimately reach ~1 m/s (a 1 nm overlap on a
  // 2.5 um grain stores that much); far beyond that a speed is a blow-up.
  ctx.runaway_speed =
      std::max(10.0, 1e4 * stokes::terminal_velocity(dmax, model.particle_density, fluid));
  ctx.min_radius = 0.5 * dmin;
  ctx.max_terminal_speed = stokes::terminal_velocity(dmax, model.particle_density, fluid) / 0.96;
  ctx.max_radius = 0.5 * dmax;
  ctx.grid = &grid;
  ctx.lists = &lists;
  ctx.grains = n;
  ctx.members_only = local;
  ctx.carried_steps = carried;
  ctx.sample_diameter = &sample.particles.diameter;
  ctx.allowance = paced ? &allowance : nullptr;
  ctx.state = &state;
  drag = ctx.drag;
  integrator = make_integrator(setup.integrator, ctx);
  freeze.height =
      setup.integrator.freeze_settled && model.contact ? setup.lowest_measured_height : 0.0;
  // Without the force pass, the freeze check reads the contacts the projection marks.
  if (!pass_needed && freeze.enabled()) forces.stiffness.resize(n);
}

// Carried steps: a member's margin covers what its carrier lets it travel between two
// builds; it only grows while it is a member (a step chosen before the build stays safe).
double EngineParts::carried_search(std::size_t k, const std::vector<double>& carrier) const {
  return 0.5 * state.diameter[k] * lists.range + lists.margin * carrier[state.origin[k]];
}

void EngineParts::widen_search(std::size_t from) {
  if (const std::vector<double>* carrier = carried ? integrator->carrier_radii() : nullptr)
    for (std::size_t k = from; k < state.size(); ++k)
      lists.search[k] = std::max(lists.search[k], carried_search(k, *carrier));
}

void EngineParts::widen_lists() {
  if (lists.stale) return;
  if (const std::vector<double>* carrier = carried ? integrator->carrier_radii() : nullptr)
    for (std::size_t k = 0; k < state.size(); ++k) {
      const double wanted = carried_search(k, *carrier);
      if (wanted > lists.search[k]) {
        lists.widen(grid, k, wanted);
        ++stats.widened_rows;
      }
    }
}

void EngineParts::rebuild_lists() {
  widen_search(0);
  lists.rebuild(state, grid, local);
  ++stats.list_builds;
}

void EngineParts::extend_lists() {
  if (lists.stale || lists.appended_to() >= state.size()) return;
  widen_search(lists.appended_to());
  lists.extend(state, grid);
}

bool EngineParts::resort_and_rebuild_lists() {
  // Before a re-sort moves the state away from the build positions' order.
  if (lists.margin_per_grain && !carried && lists.x0.size() == state.size())
    lists.size_margins(state);
  const bool resorted = resort.due(stats.steps);
  if (resorted) resort.run(state, lists.search, allowance, grid, stats.steps);
  rebuild_lists();
  return resorted;
}

void EngineParts::throw_blowup(const Blowup& b, double at) const {
  throw InstabilityError(sample.particles.id[b.particle], at, b.quantity, b.value);
}

}  // namespace sedem
