// Contacts (Eqs. 1-4) against hand computation: a grain resting on the bottom, a head-on
// collision, the rolling/sliding switch, and momentum conservation in a 1:28 cluster.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "core/engine/forces/force_model.h"
#include "core/run/stage_setups.h"
#include "tests/engine/engine_test_support.h"

namespace sedem {
namespace {

using test::Grain;
using test::sample_of;
using test::scene_with;

double net_weight(double d) {
  return 1500 * 9.81 * std::numbers::pi / 6 * d * d * d;
}

// At rest on the floor the spring carries the net weight: overlap = (m - m_f) g / K_N.
TEST(EngineContact, GrainRestsOnTheBottom) {
  for (const char* method : {"exponential", "explicit"}) {
    Scene scene = scene_with("stokes", method);
    const double d = 50e-6;
    Engine engine(engine_setup(scene), sample_of({{0, 0.5 * d + 2e-6, d}}));
    // ~30 drag response times after landing; the explicit integrator bounces (restitution 1) until
    // the drag has taken the energy.
    engine.advance_to(std::string(method) == "explicit" ? 0.012 : 0.2);
    const double overlap = 0.5 * d - engine.particles().y[0];
    const double expected = net_weight(d) / scene.forces.stiffness_normal;
    // The explicit integrator still rings (restitution 1, drag the only damping) by ~1e-3. The
    // exponential step is long (the grain is supported): the contact cancels a free fall of
    // ~0.1 mm per step to leave a 1e-12 m overlap, so round-off is ~1e-6 of it.
    const double tolerance = std::string(method) == "explicit" ? 1e-2 : 1e-5;
    EXPECT_NEAR(overlap, expected, tolerance * expected) << method;
    EXPECT_NEAR(engine.particles().vy[0], 0.0, 1e-6) << method;
  }
}

// A grain resting on the bottom below every instrument, and one still settling high up; the
// engine advanced to `t`, the resting grain checked frozen at the force balance's overlap.
// Returns the particle-steps and steps taken over one more second, and the engine's members.
struct RestingAfter {
  double particle_steps;
  std::int64_t steps;
  std::size_t members;
};
RestingAfter resting_grain_frozen(bool local_steps, double t) {
  Scene scene = scene_with("stokes", "exponential");
  scene.integrator.freeze_settled = true;
  scene.integrator.local_steps = local_steps;
  const double d = 50e-6;
  Engine engine(engine_setup(scene), sample_of({{0, 0.5 * d + 2e-6, d}, {0.01, 0.4, d}}));
  EXPECT_GT(engine.freeze_height(), 0.1);
  EXPECT_LT(engine.freeze_height(), 0.4);
  engine.advance_to(t);
  EXPECT_EQ(engine.stats().frozen, 1u);
  const double y = engine.particles().y[0];
  const double before = engine.stats().particle_steps;
  const auto steps = engine.stats().steps;
  engine.advance_to(t + 1.0);
  EXPECT_EQ(engine.particles().y[0], y);
  EXPECT_NEAR(0.5 * d - y, net_weight(d) / scene.forces.stiffness_normal,
              1e-3 * net_weight(d) / 1e3);
  return {engine.stats().particle_steps - before, engine.stats().steps - steps,
          engine.stats().members};
}

// The global step: the frozen grain stops costing steps and stays where the force balance put
// it; the one still settling high up takes one particle-step a step.
TEST(EngineContact, RestingGrainBelowTheInstrumentsIsFrozen) {
  const RestingAfter r = resting_grain_frozen(false, 1.0);
  EXPECT_EQ(r.particle_steps, double(r.steps));
}

// Local steps: the resting grain is frozen, then settled out of the common step (nothing
// moving can reach it) and costs nothing; the other grain coasts on windows of its own, a
// sync or two in a second.
TEST(EngineContact, RestingGrainIsSettledOutOfTheLocalSteps) {
  const RestingAfter r = resting_grain_frozen(true, 100.0);
  EXPECT_LE(r.particle_steps, 2.0);
  EXPECT_GT(r.steps, 0);
  EXPECT_EQ(r.members, 0u);
}

// Two equal grains meet head on at +-v0 with no fluid: a linear spring of K_N between masses
// m, reduced mass m/2: the largest overlap is 2 v0 sqrt(m / (2 K_N)), the contact lasts
// pi sqrt(m / (2 K_N)), and they leave with their velocities reversed (restitution 1).
TEST(EngineContact, HeadOnCollisionMatchesTheSpring) {
  Scene scene = scene_with("off", "explicit");
  scene.forces.weight = scene.forces.buoyancy = false;
  scene.integrator.max_step = 1e-10;
  scene.integrator.adaptive = false;
  const double d = 20e-6, v0 = 1e-3, gap = 1e-8;
  Engine engine(engine_setup(scene),
                sample_of({{-0.5 * d - gap, 0.2, d, v0, 0}, {0.5 * d + gap, 0.2, d, -v0, 0}}));
  const double m = 2500 * std::numbers::pi / 6 * d * d * d;
  const double duration = std::numbers::pi * std::sqrt(m / (2 * scene.forces.stiffness_normal));
  const double t_meet = gap / v0;
  double max_overlap = 0;
  for (int k = 1; k <= 400; ++k) {
    engine.advance_to(t_meet + 1.2 * duration * k / 400);
    const auto& p = engine.particles();
    max_overlap = std::max(max_overlap, d - (p.x[1] - p.x[0]));
  }
  const double expected = 2 * v0 * std::sqrt(m / (2 * scene.forces.stiffness_normal));
  EXPECT_NEAR(max_overlap, expected, 2e-3 * expected);
  EXPECT_NEAR(engine.particles().vx[0], -v0, 1e-3 * v0);
  EXPECT_NEAR(engine.particles().vx[1], v0, 1e-3 * v0);
  EXPECT_NEAR(engine.particles().vy[0], 0.0, 1e-12);
}

// Eq. 4 by hand: below mu f_N the tangential spring holds (rolling), above it the contact
// slides at mu f_N and the spring is reset to the slip limit.
TEST(ContactForce, RollingAndSlidingAgainstHandComputation) {
  ForceModel m;
  m.kn = 1e3;
  m.kt = 500;
  m.mu = 0.5;
  const double overlap = 1e-9, ra = 5e-6, rb = 10e-6, dt = 1e-6;
  // n along +x: t = (0, 1). a moves up at 1e-4 m/s against b at rest, no spin.
  const double fn = m.kn * overlap;  // 1e-6 N
  {
    const ContactResult c = contact_force(m, 1, 0, overlap, ra, rb, 0, 1e-4, 0, 0, 0, 0, 0, dt);
    const double g = 1e-4 * dt;  // 1e-10 m: K_T g = 5e-8 N < mu f_N = 5e-7 N
    EXPECT_DOUBLE_EQ(c.fx, -fn);
    EXPECT_DOUBLE_EQ(c.fy, -m.kt * g);
    EXPECT_DOUBLE_EQ(c.spring, g);
    EXPECT_DOUBLE_EQ(c.torque_a, ra * -m.kt * g);
    EXPECT_DOUBLE_EQ(c.torque_b, rb * -m.kt * g);
  }
  {
    // An accumulated spring of 2e-9 m: K_T g = 1e-6 N > mu f_N: slides.
    const ContactResult c =
        contact_force(m, 1, 0, overlap, ra, rb, 0, 1e-4, 0, 0, 0, 0, 2e-9 - 1e-10, dt);
    EXPECT_DOUBLE_EQ(c.fy, -m.mu * fn);
    EXPECT_DOUBLE_EQ(c.spring, m.mu * fn / m.kt);
  }
  {
    // Spin counts: a spinning at w with its contact point moving at w ra along t.
    const double w = 1e-4 / ra;
    const ContactResult c = contact_force(m, 1, 0, overlap, ra, rb, 0, 0, w, 0, 0, 0, 0, dt);
    EXPECT_DOUBLE_EQ(c.fy, -m.kt * 1e-4 * dt);
  }
}

// Two grains pressed together along y slide past each other along x (no fluid, no gravity):
// once the tangential spring reaches mu f_N (after ~1.5 ns) the contact slides, so the
// tangential impulse each grain receives is mu times the normal one, slightly less for the
// short sticking start. Equal grains: momentum conserved, equal spins.
TEST(EngineContact, SlidingContactTransfersMuTimesTheNormalImpulse) {
  Scene scene = scene_with("off", "explicit");
  scene.forces.weight = scene.forces.buoyancy = false;
  scene.forces.friction = 0.3;
  scene.integrator.max_step = 2e-11;
  scene.integrator.adaptive = false;
  const double d = 20e-6, v = 0.1;
  Engine engine(engine_setup(scene), sample_of({{0, 0.2, d, v, 0}, {0, 0.2 + d - 1e-9, d, -v, 0}}));
  engine.advance_to(2e-8);
  const auto& p = engine.particles();
  const double tangential = v - p.vx[0], normal = -p.vy[0];  // impulses / m on grain 0
  EXPECT_GT(normal, 0);
  EXPECT_LE(tangential, 0.3 * normal * (1 + 1e-9));
  EXPECT_GE(tangential, 0.9 * 0.3 * normal);
  EXPECT_NEAR(p.vx[0] + p.vx[1], 0.0, 1e-15);
  EXPECT_NEAR(p.vy[0] + p.vy[1], 0.0, 1e-15);
  EXPECT_NE(p.omega[0], 0.0);
  EXPECT_NEAR(p.omega[0], p.omega[1], 1e-9 * std::abs(p.omega[0]));
}

// Every pair force has its opposite: with no fluid and no gravity, a random 1:28 cluster of
// overlapping grains flying apart keeps its total momentum at zero.
TEST(EngineContact, PairForcesSumToZero) {
  for (const char* method : {"explicit", "exponential"}) {
    Scene scene = scene_with("off", method, 2);
    scene.forces.weight = scene.forces.buoyancy = false;
    // Soft springs so that deep random overlaps fly apart at moderate speeds.
    scene.forces.stiffness_normal = scene.forces.stiffness_tangential = 1e-3;
    scene.integrator.max_step = 1e-9;
    scene.integrator.fast_step_factor = 1e-3;
    // Packed tightly enough that most grains touch, 1:28 in size.
    const auto grains = test::scattered(
        150, -200e-6, 200e-6, 0.2, 0.2 + 400e-6,
        [](int k) { return k % 10 == 0 ? 70e-6 : 2.5e-6 + k % 7 * 1e-6; }, 3, 0.5);
    Engine engine(engine_setup(scene), sample_of(grains));
    engine.advance_to(5e-8);
    const auto& p = engine.particles();
    double px = 0, py = 0, scale = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double m = std::pow(p.diameter[i], 3);
      px += m * p.vx[i];
      py += m * p.vy[i];
      scale += m * std::hypot(p.vx[i], p.vy[i]);
    }
    EXPECT_GT(scale, 0) << method;
    EXPECT_GT(engine.stats().max_overlap_ratio, 0.0) << method;
    // The explicit integrator applies the pair forces as they are; the exponential integrator's
    // projection gives both partners of a pair the same force change, and each particle's
    // velocity change is its displacement times m / (force dt): both exact to round-off.
    const double tolerance = 1e-12;
    EXPECT_LT(std::abs(px), tolerance * scale) << method;
    EXPECT_LT(std::abs(py), tolerance * scale) << method;
  }
}

// Touching grains in a viscous fluid fall together (overdamped): equal grains side by side or
// stacked at the single grain's terminal velocity; an unequal stacked pair, the faster above,
// at (W1 + W2) / (c1 + c2). The contacts must not hold them up.
TEST(EngineContact, TouchingPairsFallTogether) {
  Scene scene = scene_with("stokes", "exponential");
  const double d = 40e-6, y = 0.3, tight = 1e-3 * d;
  const double c = 3 * std::numbers::pi * 1e-3 * d;
  const double terminal = net_weight(d) / c;
  for (const auto& pair : {std::vector<Grain>{{-0.5 * d, y, d}, {0.5 * d - tight, y, d}},
                           std::vector<Grain>{{0, y, d}, {0, y + d - tight, d}}}) {
    Engine engine(engine_setup(scene), sample_of(pair));
    engine.advance_to(0.05);
    const auto& p = engine.particles();
    for (int i : {0, 1}) EXPECT_NEAR(p.vy[i], -terminal, 1e-2 * terminal) << pair[1].x;
    EXPECT_LT(std::hypot(p.x[1] - p.x[0], p.y[1] - p.y[0]), d * (1 + 1e-3)) << pair[1].x;
  }
  // 60 um on top of 20 um: alone they would fall at 9:1, together they stay in contact.
  const double big = 60e-6, small = 20e-6;
  Engine engine(engine_setup(scene),
                sample_of({{0, y, small}, {0, y + 0.5 * (big + small) - 1e-9, big}}));
  engine.advance_to(0.05);
  const double together =
      (net_weight(big) + net_weight(small)) / (3 * std::numbers::pi * 1e-3 * (big + small));
  const auto& p = engine.particles();
  for (int i : {0, 1}) EXPECT_NEAR(p.vy[i], -together, 1e-2 * together) << i;
  const double overlap = 0.5 * (big + small) - (p.y[1] - p.y[0]);
  EXPECT_GT(overlap, 0.0);
  // The contact carries what the big grain's drag at the common speed does not.
  const double force = net_weight(big) - 3 * std::numbers::pi * 1e-3 * big * together;
  EXPECT_NEAR(overlap, force / scene.forces.stiffness_normal,
              1e-2 * force / scene.forces.stiffness_normal);
}

// A dense pile settled on the bottom: the projected contacts keep every overlap a fraction of the
// smaller radius. The springs alone would give ~1e-11 m here; the rest is what the bounded number
// of Jacobi sweeps per step leaves while the frictionless pile still spreads. It shrinks with
// the step, and it depends on the exact path the pile took: over the scattered layouts of seeds
// 1-8, 0.007-0.06 at crossing_fraction 0.1, and 0.07-0.86 at the default 0.8 (0.13-0.85 before
// each island of contacts converged on its own; one seed alone gave 0.18 then, 0.09 now). So the
// bounds hold for each of four layouts, with room for the spread: at 0.1 a few hundredths, at
// 0.8 less than the smaller radius.
double worst_overlap_in_pile(double crossing_fraction, bool local_steps, int seed) {
  Scene scene = scene_with("stokes", "exponential");
  scene.integrator.crossing_fraction = crossing_fraction;
  scene.integrator.local_steps = local_steps;
  const auto grains = test::scattered(
      300, -200e-6, 200e-6, 50e-6, 1.5e-3, [](int k) { return 20e-6 + k % 5 * 5e-6; }, seed);
  Engine engine(engine_setup(scene), sample_of(grains));
  engine.advance_to(6.0);
  const auto& p = engine.particles();
  double worst = 0, top = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    top = std::max(top, p.y[i]);
    worst = std::max(worst, (0.5 * p.diameter[i] - p.y[i]) / (0.5 * p.diameter[i]));
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      const double overlap =
          0.5 * (p.diameter[i] + p.diameter[j]) - std::hypot(p.x[j] - p.x[i], p.y[j] - p.y[i]);
      worst = std::max(worst, overlap / (0.5 * std::min(p.diameter[i], p.diameter[j])));
    }
  }
  EXPECT_LT(top, 1e-3);  // it did settle
  return worst;
}

TEST(EngineContact, DensePileHasNoDeepOverlap) {
  for (int seed = 1; seed <= 4; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    EXPECT_LT(worst_overlap_in_pile(0.1, false, seed), 0.06);
    EXPECT_LT(worst_overlap_in_pile(0.8, false, seed), 1.0);
    EXPECT_LT(worst_overlap_in_pile(0.8, true, seed), 1.0);  // local steps: the same projection
  }
}

}  // namespace
}  // namespace sedem
