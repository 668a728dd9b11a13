#include "core/engine/engine.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/engine/integrate/simd_state.h"
#include "core/engine/state/checkpoint_io.h"
#include "core/physics/stokes.h"

namespace sedem {

InstabilityError::InstabilityError(std::uint32_t id, double t, std::string what, double v)
    : std::runtime_error([&] {
        std::ostringstream m;
        m << "instability: particle " << id << " at t = " << t << " s: " << what << " = " << v;
        return m.str();
      }()),
      particle_id(id),
      time(t),
      quantity(std::move(what)),
      value(v) {}

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

constexpr char kMagic[8] = {'S', 'E', 'D', 'E', 'M', 'C', 'K', '1'};

}  // namespace

// The margin of the candidate lists, in radii. The exponential integrator's grains move up to
// crossing_fraction radii a step; a margin of a few steps' travel keeps rebuilds to one every
// few steps (a dilute suspension has almost no candidates anyway, and a settled bed is mostly
// frozen), 3 radii at least.
static double list_margin(const IntegratorConfig& c) {
  return c.method == "reference" ? 3.0 : std::max(3.0, 4.0 * c.crossing_fraction);
}

Engine::Engine(const EngineSetup& setup, Sample sample)
    : setup_(setup), sample_(std::move(sample)) {
  const Particles& p = sample_.particles;
  const std::size_t n = p.size();
  threads_ = setup_.integrator.threads > 0 ? int(setup_.integrator.threads) : omp_get_max_threads();
  // Below a few thousand particles a step takes microseconds and forking threads costs more.
  if (n < 2048) threads_ = 1;
  model_ = force_model(setup_, sample_.particle_density);
  // Local time stepping is serial (its work is in syncs taken one at a time, in time order).
  // It needs no force pass, so not with lubrication.
  local_ = setup_.integrator.method == "exponential" && setup_.integrator.local_steps &&
           !model_.lubrication;
  if (local_) threads_ = 1;
  if (setup_.integrator.method == "reference")
    model_.skin = 0.25;
  else
    model_.contact_forces = false;  // the exponential integrator projects contacts

  state_.resize(n);
  pass_needed_ = needs_force_pass(model_);
  if (pass_needed_) forces_.resize(n);
  search_.resize(n);
  double dmin = 0, dmax = 0;
  for (std::size_t i = 0; i < n; ++i) {
    state_.x[i] = p.x[i];
    state_.y[i] = p.y[i];
    state_.vx[i] = p.vx.empty() ? 0 : p.vx[i];
    state_.vy[i] = p.vy.empty() ? 0 : p.vy[i];
    state_.omega[i] = p.omega.empty() ? 0 : p.omega[i];
    state_.diameter[i] = p.diameter[i];
    state_.weight[i] = p.weight[i];
    state_.origin[i] = std::uint32_t(i);
    state_.frozen[i] = 0;
    dmin = i == 0 ? p.diameter[i] : std::min(dmin, p.diameter[i]);
    dmax = std::max(dmax, p.diameter[i]);
  }
  const double reach = model_.lubrication_reach();
  margin_ = list_margin(setup_.integrator);
  for (std::size_t i = 0; i < n; ++i)
    search_[i] = 0.5 * state_.diameter[i] * (1 + reach + model_.skin + margin_);
  if (n == 0) dmin = dmax = 1e-6;

  const Cylinder& cyl = setup_.cylinder;
  grid_.configure(dmin * (1 + reach + model_.skin + margin_),
                  dmax * (1 + reach + model_.skin + margin_), cyl.half_width(), cyl.height,
                  threads_);
  voidage_.configure(setup_.forces.voidage_cell, cyl.half_width(), cyl.height, cyl.slab_thickness(),
                     setup_.forces.min_voidage, threads_);
  pass_.configure(model_, threads_);

  const Fluid& fluid = setup_.fluid;
  IntegratorContext ctx;
  ctx.model = &model_;
  ctx.drag = DragEvaluator{&model_, &voidage_, di_felice_tail_re(setup_.forces.min_voidage)};
  ctx.threads = threads_;
  ctx.min_response_time = stokes::response_time(dmin, model_.particle_density, fluid, 0.95);
  ctx.min_terminal_speed = stokes::terminal_velocity(dmin, model_.particle_density, fluid);
  // Contacts between the smallest grains legitimately reach ~1 m/s (a 1 nm overlap on a
  // 2.5 um grain stores that much); far beyond that a speed is a blow-up.
  ctx.runaway_speed =
      std::max(10.0, 1e4 * stokes::terminal_velocity(dmax, model_.particle_density, fluid));
  ctx.min_radius = 0.5 * dmin;
  ctx.max_terminal_speed = stokes::terminal_velocity(dmax, model_.particle_density, fluid) / 0.96;
  ctx.max_radius = 0.5 * dmax;
  ctx.grid = &grid_;
  ctx.pass = &pass_;
  ctx.grains = n;
  ctx.members_only = local_;
  drag_ = ctx.drag;
  integrator_ = make_integrator(setup_.integrator, ctx);
  freeze_height_ =
      setup_.integrator.freeze_settled && model_.contact ? setup_.lowest_measured_height : 0.0;
  // Without the force pass, the freeze check reads the contacts the projection marks.
  if (!pass_needed_ && freeze_height_ > 0) forces_.stiffness.resize(n);
  // Below the lowest instrument nothing rises back into any instrument's reach: a grain that
  // falls there can leave the dynamics (local steps; only where some instrument reads).
  if (local_ && model_.contact && setup_.integrator.retire_below && setup_.instruments_read)
    retire_height_ = std::max(0.0, setup_.lowest_measured_height);
  if (local_) {
    start_local();
    return;
  }
  // A first look at the contacts, so that the first step is chosen knowing them.
  if (n > 0) {
    rebuild_lists();
    if (pass_needed_) pass_.run(state_, grid_, springs_, next_springs_, 0.0, forces_, facts_);
    next_springs_ = PairHistory{};
  }
}

Engine::~Engine() = default;

const Particles& Engine::particles() const {
  if (synced_step_ != stats_.steps) {
    Particles& p = sample_.particles;
    const std::size_t n = state_.size();
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t o = state_.origin[i];
      p.x[o] = state_.x[i];
      p.y[o] = state_.y[i];
      p.vx[o] = state_.vx[i];
      p.vy[o] = state_.vy[i];
      p.omega[o] = state_.omega[i];
    }
    if (local_) {
      for (std::uint32_t id = 0; id < kind_.size(); ++id) {
        if (kind_[id] == kMoving || kind_[id] == kFrozen) continue;
        const FreeFlight::Point q = kind_[id] == kCoasting ? coasting_at(id, time_)
                                    : kind_[id] == kRetired
                                        ? retired_at(id, time_)
                                        : FreeFlight::Point{flight_[id].x, flight_[id].y, 0, 0};
        p.x[id] = q.x;
        p.y[id] = q.y;
        p.vx[id] = q.vx;
        p.vy[id] = q.vy;
        p.omega[id] = 0;
      }
    }
    synced_step_ = stats_.steps;
  }
  return sample_.particles;
}

const Sample& Engine::sample() const {
  particles();
  return sample_;
}

void Engine::advance_to(double t) {
  while (time_ < t) step(t);
}

void Engine::step(double limit) {
  clean_simd_state();
  if (local_) {
    step_local(limit);
    return;
  }
  const std::size_t n = state_.size();
  double dt = integrator_->next_step(facts_);
  const bool last = time_ + dt >= limit;
  if (last) dt = limit - time_;

  if (model_.drag == DragLaw::di_felice)
    voidage_.compute(n, state_.x.data(), state_.y.data(), state_.diameter.data(),
                     state_.weight.data());
  if (lists_stale_) {
    if (stats_.steps - resorted_at_ >= 16) {
      resort();
      resorted_at_ = stats_.steps;
    }
    rebuild_lists();
  }
  if (pass_needed_) {
    pass_.run(state_, grid_, springs_, next_springs_, dt, forces_, facts_);
    if (facts_.blowup.found) {
      const auto& b = facts_.blowup;
      throw InstabilityError(sample_.particles.id[b.particle], time_, b.quantity, b.value);
    }
    if (model_.friction) std::swap(springs_, next_springs_);
  }

  Blowup blowup;
  integrator_->advance(state_, forces_, dt, blowup);
  if (!pass_needed_) integrator_->contact_facts(facts_);
  time_ = last ? limit : time_ + dt;
  stats_.steps += 1;
  stats_.particle_steps += double(n - stats_.frozen);
  stats_.last_step = dt;
  stats_.contacts = facts_.contacts;
  stats_.max_overlap_ratio = std::max(stats_.max_overlap_ratio, facts_.max_overlap_ratio);
  if (blowup.found)
    throw InstabilityError(sample_.particles.id[blowup.particle], time_, blowup.quantity,
                           blowup.value);
  if (!pass_needed_ && freeze_height_ > 0 && stats_.steps % 64 == 0)
    integrator_->mark_touching(forces_.stiffness);
  if (freeze_height_ > 0 && stats_.steps % 64 == 0) freeze_resting();
  lists_stale_ = moved_beyond_margin();
}

void Engine::rebuild_lists() {
  const std::size_t n = state_.size();
  x0_ = state_.x;
  y0_ = state_.y;
  grid_.build(n, x0_.data(), y0_.data(), search_.data());
  pass_.build_lists(grid_, n, x0_.data(), y0_.data(), search_.data(),
                    local_ ? state_.frozen.data() : nullptr);
  lists_stale_ = false;
  ++stats_.list_builds;
}

// A pair's distance shrinks by at most the sum of both moves; the lists hold every pair within
// the interaction range plus margin_ (r_i + r_j), so they stay complete while
// move_i + move_j < margin_ (r_i + r_j) for every pair, i.e. while the two largest excesses
// e = move - margin_ r (1% kept in reserve) sum to less than zero. A small grain carried
// along by a large one thus uses the margin of its partners too, not its own margin alone.
bool Engine::moved_beyond_margin() {
  const std::size_t n = state_.size();
  const double* x = state_.x.data();
  const double* y = state_.y.data();
  const double* d = state_.diameter.data();
  const double share = 0.99 * 0.5 * margin_;
  const int threads = threads_;
  std::vector<double>& top = top_excess_;
  top.assign(2 * std::size_t(threads), -HUGE_VAL);  // no allocation after the first step
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
    double first = -HUGE_VAL, second = -HUGE_VAL;
#pragma omp for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      const double dx = x[i] - x0_[i], dy = y[i] - y0_[i];
      const double excess = std::sqrt(dx * dx + dy * dy) - share * d[i];
      if (excess > second) {
        second = std::max(std::min(first, excess), second);
        first = std::max(first, excess);
      }
    }
    const std::size_t t = std::size_t(omp_get_thread_num());
    top[2 * t] = first;
    top[2 * t + 1] = second;
  }
  std::sort(top.begin(), top.end());
  return n > 1 && top[top.size() - 1] + top[top.size() - 2] >= 0;
}

// A particle is at rest when it touches something and moves at less than 1e-3 of its
// terminal speed; below every instrument nothing it could still do is measured.
void Engine::freeze_resting() {
  const Fluid& fluid = setup_.fluid;
  std::size_t frozen = 0;
  for (std::size_t i = 0; i < state_.size(); ++i) {
    if (!state_.frozen[i] && state_.y[i] < freeze_height_ && forces_.stiffness[i] > 0) {
      const double ut =
          stokes::terminal_velocity(state_.diameter[i], model_.particle_density, fluid);
      if (std::hypot(state_.vx[i], state_.vy[i]) < 1e-3 * ut) {
        state_.frozen[i] = 1;
        state_.vx[i] = state_.vy[i] = state_.omega[i] = 0;
      }
    }
    frozen += state_.frozen[i];
  }
  stats_.frozen = frozen;
}

// Puts the state in the neighbour grid's bucket order, so that a particle's neighbours are
// near it in memory for the next steps.
void Engine::resort() {
  const auto& order = grid_.order();
  const std::size_t n = state_.size();
  if (order.size() != n) return;
  scratch_.resize(n);
  auto permute = [&](auto& v, auto& tmp) {
    tmp.resize(n);
    for (std::size_t k = 0; k < n; ++k) tmp[k] = v[order[k]];
    std::swap(v, tmp);
  };
  for (auto* v : {&state_.x, &state_.y, &state_.vx, &state_.vy, &state_.omega, &state_.diameter,
                  &state_.weight, &search_})
    permute(*v, scratch_);
  permute(state_.origin, scratch_index_);
  permute(state_.frozen, scratch_flag_);
}

double Engine::kinetic_energy() const {
  double e = 0;
  if (local_) {
    const Particles& p = particles();
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double d = p.diameter[i], m = model_.mass(d);
      e += 0.5 * m * (p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i]) +
           0.5 * 0.1 * m * d * d * p.omega[i] * p.omega[i];
    }
    return e;
  }
  for (std::size_t i = 0; i < state_.size(); ++i) {
    const double d = state_.diameter[i], m = model_.mass(d);
    e += 0.5 * m * (state_.vx[i] * state_.vx[i] + state_.vy[i] * state_.vy[i]) +
         0.5 * 0.1 * m * d * d * state_.omega[i] * state_.omega[i];
  }
  return e;
}

std::size_t Engine::bytes() const {
  auto cap = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  const Particles& p = sample_.particles;
  std::size_t b = cap(p.x) + cap(p.y) + cap(p.vx) + cap(p.vy) + cap(p.omega) + cap(p.diameter) +
                  cap(p.weight) + cap(p.size_class) + cap(p.id);
  b += cap(state_.x) + cap(state_.y) + cap(state_.vx) + cap(state_.vy) + cap(state_.omega) +
       cap(state_.diameter) + cap(state_.weight) + cap(state_.origin) + cap(state_.frozen);
  b += cap(forces_.fx) + cap(forces_.fy) + cap(forces_.torque) + cap(forces_.stiffness) +
       cap(forces_.spin_stiffness) + cap(forces_.lubrication_stiffness);
  b +=
      cap(search_) + cap(x0_) + cap(y0_) + cap(scratch_) + cap(scratch_index_) + cap(scratch_flag_);
  b += grid_.bytes() + voidage_.bytes() + pass_.bytes() + springs_.bytes() + next_springs_.bytes();
  b += integrator_->bytes();
  b += cap(kind_) + cap(flight_) + cap(t0_) + cap(t1_) + cap(member_) + cap(deposit_cell_) +
       cap(syncs_) + cap(near_) + cap(wake_) + boxes_.bytes() + cap(land_y_) + cap(bed_) +
       cap(ahead_slot_) + cap(ahead_) + cap(widened_);
  return b;
}

void Engine::save_checkpoint(const std::string& path) const {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error("cannot write checkpoint " + path);
  out.write(kMagic, sizeof kMagic);
  write_value(out, std::uint64_t(state_.size()));
  write_value(out, time_);
  write_value(out, stats_);
  write_value(out, facts_.contacts);
  write_value(out, facts_.min_contact_mass);
  for (const auto* v : {&state_.x, &state_.y, &state_.vx, &state_.vy, &state_.omega,
                        &state_.diameter, &state_.weight, &search_})
    write_vector(out, *v);
  write_vector(out, state_.origin);
  write_vector(out, state_.frozen);
  write_vector(out, x0_);
  write_vector(out, y0_);
  write_value(out, lists_stale_);
  write_value(out, resorted_at_);
  const auto springs = springs_.sorted_entries();
  const std::uint64_t count = springs.size();
  write_value(out, count);
  out.write(reinterpret_cast<const char*>(springs.data()),
            std::streamsize(count * sizeof(PairHistory::Entry)));
  integrator_->save(out);
  if (local_) save_local(out);
  if (!out) throw std::runtime_error("failed writing checkpoint " + path);
}

void Engine::load_checkpoint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[sizeof kMagic];
  in.read(magic, sizeof magic);
  if (!in || std::memcmp(magic, kMagic, sizeof kMagic) != 0)
    throw std::runtime_error("not a sedem checkpoint: " + path);
  std::uint64_t members = 0;
  read_value(in, members);
  if (local_ && in && members <= sample_.particles.size()) {  // local steps: the members only
    state_.resize(members);
    search_.resize(members);
    x0_.resize(members);
    y0_.resize(members);
  } else if (!local_ && members != sample_.particles.size()) {
    throw std::runtime_error("checkpoint does not match this sample: " + path);
  }
  // Every value read back is checked before it is used: a damaged file is refused with the
  // field it got wrong, never a crash or a silently shorter run.
  auto validate_loaded_state = [&](std::uint64_t springs) {
    auto bad = [&](const std::string& what) {
      throw std::runtime_error("damaged checkpoint " + path + ": " + what);
    };
    if (!in) bad("truncated");
    if (!std::isfinite(time_) || time_ < 0 || time_ > setup_.end_time * (1 + 1e-9))
      bad("time " + std::to_string(time_) + " s is outside the run (0 to " +
          std::to_string(setup_.end_time) + " s)");
    if (stats_.steps < 0 || !std::isfinite(stats_.particle_steps) || stats_.particle_steps < 0)
      bad("negative step counts");
    // Sample indices: all of them, or with local steps those of the members.
    const std::size_t n = state_.size(), ids = sample_.particles.size();
    std::vector<std::uint8_t> seen(ids, 0);
    for (std::uint32_t o : state_.origin) {
      if (o >= ids || seen[o]) bad("particle order entry " + std::to_string(o) + " is no particle");
      seen[o] = 1;
    }
    for (const auto* v : {&state_.x, &state_.y, &state_.vx, &state_.vy, &state_.omega,
                          &state_.diameter, &state_.weight, &search_, &x0_, &y0_})
      for (double x : *v)
        if (!std::isfinite(x)) bad("a particle's position, velocity or size is no number");
    for (std::size_t i = 0; i < n; ++i)
      if (!(state_.diameter[i] > 0) || !(state_.weight[i] >= 0) || state_.frozen[i] > 1)
        bad("particle " + std::to_string(i) + " has a bad size, weight or frozen flag");
    if (resorted_at_ < 0 || resorted_at_ > stats_.steps) bad("resort step out of range");
    // The springs follow: no more of them than the file holds.
    const auto here = in.tellg();
    in.seekg(0, std::ios::end);
    const auto end = in.tellg();
    in.seekg(here);
    if (here < 0 || end < here || springs > std::uint64_t(end - here) / sizeof(PairHistory::Entry))
      bad(std::to_string(springs) + " contacts announced, more than the file holds");
  };
  read_value(in, time_);
  read_value(in, stats_);
  facts_ = PassFacts{};
  read_value(in, facts_.contacts);
  read_value(in, facts_.min_contact_mass);
  for (auto* v : {&state_.x, &state_.y, &state_.vx, &state_.vy, &state_.omega, &state_.diameter,
                  &state_.weight, &search_})
    read_vector(in, *v);
  read_vector(in, state_.origin);
  read_vector(in, state_.frozen);
  read_vector(in, x0_);
  read_vector(in, y0_);
  read_value(in, lists_stale_);
  read_value(in, resorted_at_);
  std::uint64_t count = 0;
  read_value(in, count);
  validate_loaded_state(count);
  std::vector<PairHistory::Entry> springs(count);
  in.read(reinterpret_cast<char*>(springs.data()),
          std::streamsize(count * sizeof(PairHistory::Entry)));
  springs_.assign(&springs, 1);
  const std::uint64_t n = sample_.particles.size();
  for (const auto& e : springs)
    if (e.key != PairHistory::kEmpty &&
        ((e.key >> 32) >= n || (e.key & 0xffffffffu) >= n || !std::isfinite(e.spring)))
      throw std::runtime_error("damaged checkpoint " + path + ": a contact names no particle");
  integrator_->load(in);
  if (local_) load_local(in);
  if (!in) throw std::runtime_error("truncated checkpoint " + path);
  if (in.peek() != std::char_traits<char>::eof())
    throw std::runtime_error("damaged checkpoint " + path + ": data after its end");
  // The lists as they were: built from the saved build positions, in the saved order.
  if (!lists_stale_) {
    grid_.build(state_.size(), x0_.data(), y0_.data(), search_.data());
    pass_.build_lists(grid_, state_.size(), x0_.data(), y0_.data(), search_.data(),
                      local_ ? state_.frozen.data() : nullptr);
  }
  synced_step_ = -1;
}

}  // namespace sedem
