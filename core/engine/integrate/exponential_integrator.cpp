#include <algorithm>
#include <cmath>
#include <istream>
#include <memory>
#include <ostream>
#include <vector>

#include "core/engine/integrate/contact_projection.h"
#include "core/engine/integrate/integration_pass.h"
#include "core/engine/integrate/integrator.h"

namespace sedem {

namespace {

using integration::check;
using integration::integrate;
using integration::ThreadSums;

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
    const bool project = m.contact && !m.contact_forces && ctx_.grid && ctx_.lists;
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
      facts_ = projection_.run(s, *ctx_.grid, *ctx_.lists, drag_, dt,
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

std::unique_ptr<Integrator> make_exponential_integrator(const IntegratorConfig& config,
                                                        const IntegratorContext& context) {
  return std::make_unique<ExponentialIntegrator>(config, context);
}

}  // namespace sedem
