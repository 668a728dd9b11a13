#include "core/engine/integrate/integrators.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <istream>
#include <ostream>
#include <vector>

#include "core/engine/integrate/contact_projection.h"
#include "core/physics/drag.h"
#include "core/physics/stokes.h"

namespace sedem {

double DragEvaluator::coefficient(double d, double weight, double speed, double x, double y) const {
  switch (model->drag) {
    case DragLaw::off:
      return 0;
    case DragLaw::stokes:
      return 3.0 * std::numbers::pi * model->viscosity * d;
    case DragLaw::di_felice: {
      // drag::di_felice_coefficient with eps^(2 - chi) = eps^-1.7 (per cell) eps^(0.65 g),
      // g = exp(-(1.5 - log10 Re)^2 / 2). Below tail_re the second factor is 1 to round-off
      // (its exponent is below 2^-54 for every voidage the floor allows): it is not computed.
      // The engine's terminal velocities are tested against drag::di_felice_terminal_velocity.
      const std::size_t cell = voidage->cell(x, y);
      double eps, log_eps, power;
      if (model->voidage_excludes_self && weight > 0) {
        eps = voidage->excluding(cell, weight * model->volume(d));
        log_eps = std::log(eps);
        power = std::exp(-1.7 * log_eps);
      } else {
        eps = voidage->voidage(cell);
        log_eps = voidage->log_voidage(cell);
        power = voidage->hindrance(cell);
      }
      const double mu = model->viscosity;
      const double re = model->fluid_density * eps * speed * d / mu;
      const double root = 0.63 * std::sqrt(re) + 4.8;
      if (re > tail_re && log_eps != 0) {
        const double l = 1.5 - std::log10(re);
        power *= std::exp(0.65 * std::exp(-0.5 * l * l) * log_eps);
      }
      const double area = std::numbers::pi * d * d / 4.0;
      return 0.5 * root * root * mu / (eps * d) * area * power;
    }
  }
  return 0;
}

double di_felice_tail_re(double min_voidage) {
  const double worst_log = -std::log(std::min(1.0, std::max(min_voidage, 1e-300)));
  if (worst_log <= 0) return HUGE_VAL;
  // 0.65 exp(-l0^2 / 2) worst_log = 2^-54 at l0; half that Re keeps a wide margin (g is then
  // smaller by exp(-0.3 l0)) over the round-off of log10 and exp.
  const double l0 = std::sqrt(2 * std::log(0.65 * worst_log * std::ldexp(1.0, 54)));
  return 0.5 * std::pow(10.0, 1.5 - l0);
}

namespace {

// Per-thread partial results of an integration pass, reduced in thread order.
struct ThreadSums {
  double max_change = 0;  // velocity change / own terminal speed, free particles
  double max_rate = 0;    // c/m, free particles
  double max_speed = 0;
  double max_radii_per_s = 0;  // speed / radius, moving particles
  Blowup blowup;
};

[[gnu::noinline]] void report(const EngineState& s, std::size_t i, double runaway, Blowup& b) {
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
    if (t.blowup.found && !total.blowup.found) total.blowup = t.blowup;
  }
  return total;
}

class ReferenceIntegrator final : public Integrator {
 public:
  ReferenceIntegrator(const IntegratorConfig& c, const IntegratorContext& x) : config_(c), ctx_(x) {
    step_ = std::min(config_.max_step, config_.step_factor * ctx_.min_response_time);
    ceiling_ = config_.max_step;
    // c/m of the smallest grain in clear water: t_tr(95 %) = ln(20) m / c.
    clear_rate_ = ctx_.min_response_time > 0 ? std::log(20.0) / ctx_.min_response_time : 0;
  }
  const char* name() const override { return "reference"; }

  double next_step(const PassFacts& last) override {
    double dt = step_;
    // Statistical weights can pack a voidage cell enough to make a grain's drag response several
    // times quicker than in clear water: the step shrinks in proportion, as the paper's rule
    // would with t_tr taken at that drag.
    if (rate_ > clear_rate_) dt *= clear_rate_ / rate_;
    if (last.min_contact_mass > 0) {
      const ForceModel& m = *ctx_.model;
      dt = std::min(dt, 0.1 * std::sqrt(last.min_contact_mass / (m.kn + m.kt)));
    }
    if (ctx_.model->contact && max_speed_ > 0)
      dt = std::min(dt, 0.5 * ctx_.model->skin * ctx_.min_radius / max_speed_);
    return dt;
  }

  void advance(EngineState& s, const ForceAccumulators& f, double dt, Blowup& blowup) override {
    const ForceModel& m = *ctx_.model;
    const bool spin = m.friction && m.contact;
    const ThreadSums sums =
        integrate(ctx_.threads, s.size(), sums_, [&](std::size_t i, ThreadSums& t) {
          if (s.frozen[i]) return;
          const double d = s.diameter[i];
          const double mass = m.mass(d);
          const double speed = std::sqrt(s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i]);
          const double c = ctx_.drag.coefficient(d, s.weight[i], speed, s.x[i], s.y[i]);
          const double ax = (f.fx[i] - c * s.vx[i]) / mass, ay = (f.fy[i] - c * s.vy[i]) / mass;
          s.vx[i] += dt * ax;
          s.vy[i] += dt * ay;
          s.x[i] += dt * s.vx[i];
          s.y[i] += dt * s.vy[i];
          if (spin) s.omega[i] += dt * f.torque[i] / (0.1 * mass * d * d);
          if (f.stiffness[i] == 0) {
            const double ut = stokes::terminal_velocity(
                d, m.particle_density, Fluid{m.fluid_density, m.viscosity, m.gravity});
            t.max_change = std::max(t.max_change, dt * std::sqrt(ax * ax + ay * ay) / ut);
            t.max_rate = std::max(t.max_rate, c / mass);
          }
          t.max_speed = std::max(t.max_speed, std::sqrt(s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i]));
          check(s, i, ctx_.runaway_speed, t.blowup);
        });
    if (sums.blowup.found && !blowup.found) blowup = sums.blowup;
    if (sums.max_rate > 0) rate_ = sums.max_rate;
    max_speed_ = sums.max_speed;
    adapt(sums.max_change);
  }

  void save(std::ostream& out) const override {
    for (double v : {step_, ceiling_, window_change_, rate_, max_speed_})
      out.write(reinterpret_cast<const char*>(&v), 8);
    out.write(reinterpret_cast<const char*>(&window_steps_), 8);
    out.write(reinterpret_cast<const char*>(&grown_), 1);
  }
  void load(std::istream& in) override {
    for (double* v : {&step_, &ceiling_, &window_change_, &rate_, &max_speed_})
      in.read(reinterpret_cast<char*>(v), 8);
    in.read(reinterpret_cast<char*>(&window_steps_), 8);
    in.read(reinterpret_cast<char*>(&grown_), 1);
  }

 private:
  void adapt(double change) {
    if (!config_.adaptive) return;
    if (change > 5e-2 && grown_) {  // unstable change after growth: back off, remember
      ceiling_ = 0.9 * step_;
      step_ = ceiling_;
      window_steps_ = 0;
      window_change_ = 0;
      return;
    }
    window_change_ = std::max(window_change_, change);
    if (++window_steps_ < 100) return;
    if (window_change_ < 1e-3) {
      double grown = std::min(1.1 * step_, std::min(ceiling_, config_.max_step));
      if (rate_ > 0) grown = std::min(grown, 1.9 / rate_);
      grown_ = grown_ || grown > step_;
      step_ = std::max(step_, grown);
    }
    window_steps_ = 0;
    window_change_ = 0;
  }

  IntegratorConfig config_;
  IntegratorContext ctx_;
  std::vector<ThreadSums> sums_;
  double step_ = 0, ceiling_ = 0, window_change_ = 0, rate_ = 0, max_speed_ = 0, clear_rate_ = 0;
  std::int64_t window_steps_ = 0;
  bool grown_ = false;
};

class ExponentialIntegrator final : public Integrator {
 public:
  ExponentialIntegrator(const IntegratorConfig& c, const IntegratorContext& x)
      : config_(c), ctx_(x) {
    ceiling_ = std::min(config_.max_step, config_.fast_step_factor * ctx_.min_response_time);
    const double d = 2 * ctx_.max_radius;
    settling_ = d > 0 ? ctx_.max_terminal_speed / (d * d) : 0;
    crossing_ = ctx_.model->contact || ctx_.model->drag == DragLaw::di_felice;
    // Before any velocity is known, the largest grain at its settling speed sets the step.
    step_ = limited(ctx_.max_radius > 0 ? ctx_.max_terminal_speed / ctx_.max_radius : 0);
    projection_.configure(*ctx_.model, ctx_.threads, ctx_.contact_sweeps, ctx_.grains);
  }
  const char* name() const override { return "exponential"; }
  double next_step(const PassFacts&) override { return step_; }

  void advance(EngineState& s, const ForceAccumulators& f, double dt, Blowup& blowup) override {
    const ForceModel& m = *ctx_.model;
    const bool project = m.contact && !m.contact_forces && ctx_.grid && ctx_.pass;
    // Without the force pass a free particle feels only weight, buoyancy and drag.
    const bool pass_forces = needs_force_pass(m);
    if (project) drag_.resize(s.size());
    // Friction needs the tangential motion over the step: the positions before it.
    const bool friction = project && projection_.friction();
    if (friction) {
      start_x_.assign(s.x.begin(), s.x.end());
      start_y_.assign(s.y.begin(), s.y.end());
    }
    // Free update: the forces of the pass (no contact force when contacts are projected), the
    // lubrication's stiffness folded into the damping.
    const ThreadSums sums =
        integrate(ctx_.threads, s.size(), sums_, [&](std::size_t i, ThreadSums& t) {
          if (s.frozen[i]) return;
          const double d = s.diameter[i];
          const double mass = m.mass(d);
          const double vx = s.vx[i], vy = s.vy[i];
          double c =
              ctx_.drag.coefficient(d, s.weight[i], std::sqrt(vx * vx + vy * vy), s.x[i], s.y[i]);
          if (pass_forces) c += f.lubrication_stiffness[i] * dt;
          const double fx = pass_forces ? f.fx[i] : 0.0;
          const double fy = pass_forces ? f.fy[i] : m.gravity_force(d);
          if (project) drag_[i] = c;
          if (c > 0) {
            const double rate = c / mass, a = dt * rate;
            // decay - 1 from one call; past 40 response times it is -1 to round-off.
            const double lost = a > 40 ? -1.0 : std::expm1(-a);
            const double decay = 1.0 + lost;
            const double relax = -lost / rate;      // integral of the decay over dt
            const double ux = fx / c, uy = fy / c;  // velocity the step tends to
            s.x[i] += ux * dt + (vx - ux) * relax;
            s.y[i] += uy * dt + (vy - uy) * relax;
            s.vx[i] = ux + (vx - ux) * decay;
            s.vy[i] = uy + (vy - uy) * decay;
          } else {
            const double ax = fx / mass, ay = fy / mass;
            s.x[i] += dt * (vx + 0.5 * dt * ax);
            s.y[i] += dt * (vy + 0.5 * dt * ay);
            s.vx[i] += dt * ax;
            s.vy[i] += dt * ay;
          }
          check(s, i, ctx_.runaway_speed, t.blowup);
        });
    if (sums.blowup.found && !blowup.found) blowup = sums.blowup;
    facts_ = ProjectionFacts{};
    if (project && dt > 0) {
      facts_ = projection_.run(s, *ctx_.grid, *ctx_.pass, drag_, dt,
                               friction ? start_x_.data() : nullptr,
                               friction ? start_y_.data() : nullptr);
      if (facts_.blowup.found && !blowup.found) blowup = facts_.blowup;
      Blowup moved;
      for (std::uint32_t p : projection_.participants())
        if (!s.frozen[p]) check(s, p, ctx_.runaway_speed, moved);
      if (moved.found && !blowup.found) blowup = moved;
    }
    step_ = limited(fastest(s));
  }

  void refresh_step(const EngineState& s) override { step_ = limited(fastest(s)); }

  void contact_facts(PassFacts& facts) const override {
    facts.contacts = facts_.touching;
    facts.max_overlap_ratio = facts_.max_overlap_ratio;
    facts.min_contact_mass = 0;
  }
  void mark_touching(std::vector<double>& touching) const override {
    projection_.mark_touching(touching);
  }

  void save(std::ostream& out) const override {
    out.write(reinterpret_cast<const char*>(&step_), 8);
    projection_.save(out);
  }
  void load(std::istream& in) override {
    in.read(reinterpret_cast<char*>(&step_), 8);
    projection_.load(in);
  }
  std::size_t bytes() const override {
    return projection_.bytes() + (drag_.capacity() + start_x_.capacity() + start_y_.capacity()) * 8;
  }

 private:
  IntegratorConfig config_;
  IntegratorContext ctx_;
  std::vector<ThreadSums> sums_;
  ContactProjection projection_;
  std::vector<double> start_x_, start_y_;  // friction: the positions at the step's start
  // The ceiling, or less where a grain moving at `radii_per_s` would cross too far.
  double limited(double radii_per_s) const {
    if (!crossing_ || radii_per_s <= 0) return ceiling_;
    return std::min(ceiling_, config_.crossing_fraction / radii_per_s);
  }
  // The fastest moving grain, in its radii per second. A free grain may reach its settling
  // speed within the next step; one in a contact constraint moves as the projection left it.
  double fastest(const EngineState& s) {
    if (!crossing_) return 0;
    constrained_.resize(s.size());
    const bool marked = !ctx_.members_only;
    if (marked)
      for (std::uint32_t p : projection_.participants()) constrained_[p] = 1;
    const ThreadSums sums =
        integrate(ctx_.threads, s.size(), sums_, [&](std::size_t i, ThreadSums& t) {
          if (s.frozen[i]) return;
          const double d = s.diameter[i];
          const double v2 = s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i];
          const double settling = constrained_[i] ? 0.0 : settling_ * d * d;
          const double speed = std::sqrt(std::max(v2, settling * settling));
          t.max_radii_per_s = std::max(t.max_radii_per_s, 2 * speed / d);
        });
    if (marked)
      for (std::uint32_t p : projection_.participants()) constrained_[p] = 0;
    return sums.max_radii_per_s;
  }

  std::vector<double> drag_;               // per particle: its drag coefficient over this step
  std::vector<std::uint8_t> constrained_;  // per particle, zero between steps
  ProjectionFacts facts_;
  double step_ = 0, ceiling_ = 0;
  double settling_ = 0;  // clear-water settling speed / d^2
  bool crossing_ = false;
};

}  // namespace

std::unique_ptr<Integrator> make_integrator(const IntegratorConfig& config,
                                            const IntegratorContext& context) {
  if (config.method == "reference") return std::make_unique<ReferenceIntegrator>(config, context);
  return std::make_unique<ExponentialIntegrator>(config, context);
}

}  // namespace sedem
