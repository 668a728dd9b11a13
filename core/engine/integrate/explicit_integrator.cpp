#include <algorithm>
#include <cmath>
#include <istream>
#include <memory>
#include <ostream>
#include <vector>

#include "core/engine/integrate/integration_pass.h"
#include "core/engine/integrate/integrator.h"
#include "core/physics/stokes.h"

namespace sedem {

namespace {

using integration::check;
using integration::integrate;
using integration::ThreadSums;

class ExplicitIntegrator final : public Integrator {
 public:
  ExplicitIntegrator(const IntegratorConfig& c, const IntegratorContext& x) : config_(c), ctx_(x) {
    step_ = std::min(config_.max_step, config_.step_factor * ctx_.min_response_time);
    ceiling_ = config_.max_step;
    // c/m of the smallest grain in clear water: t_tr(95 %) = ln(20) m / c.
    clear_rate_ = ctx_.min_response_time > 0 ? std::log(20.0) / ctx_.min_response_time : 0;
  }
  const char* name() const override { return "explicit"; }

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

}  // namespace

std::unique_ptr<Integrator> make_explicit_integrator(const IntegratorConfig& config,
                                                     const IntegratorContext& context) {
  return std::make_unique<ExplicitIntegrator>(config, context);
}

}  // namespace sedem
