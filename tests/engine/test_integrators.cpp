// The exponential integrator against the explicit one: its error shrinks with its step; runs are
// deterministic; a blow-up is reported with the particle, the time and the quantity.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/physics/stokes.h"
#include "core/run/stage_setups.h"
#include "tests/engine/engine_test_support.h"

namespace sedem {
namespace {

using test::Grain;
using test::sample_of;
using test::scene_with;

// A small dilute cloud of 5-60 um grains with Di Felice drag, a few of which meet: larger
// grains are placed just above smaller ones so they catch up and push them.
std::vector<Grain> cloud() {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Grain> g;
  for (int k = 0; k < 40; ++k) {
    const double x = -0.02 + 0.04 * u(rng), y = 0.3 + 0.01 * u(rng);
    const double d = 5e-6 + 55e-6 * u(rng);
    g.push_back({x, y, d, 0, 0, 1e4});
    if (k % 8 == 0) g.push_back({x + 0.3 * d, y - d - 2e-6, 8e-6, 0, 0, 1e4});
  }
  return g;
}

double max_position_error(const Engine& a, const Engine& b, double scale) {
  double e = 0;
  for (std::size_t i = 0; i < a.particles().size(); ++i)
    e = std::max(e, std::hypot(a.particles().x[i] - b.particles().x[i],
                               a.particles().y[i] - b.particles().y[i]));
  return e / scale;
}

TEST(ExponentialIntegrator, ConvergesToTheExplicitAsTheStepShrinks) {
  const double t = 0.005;
  // The explicit integrator at a tenth of the paper's step, so that its own error stays below the
  // differences measured here.
  Scene fine_scene = scene_with("di_felice", "explicit");
  fine_scene.integrator.adaptive = false;
  fine_scene.integrator.step_factor = 0.01;
  Engine fine(engine_setup(fine_scene), sample_of(cloud()));
  fine.advance_to(t);
  // The distance the fastest grain falls, to scale errors.
  const double scale = stokes::terminal_velocity(60e-6, 2500, fine_scene.fluid) * t;

  double previous = 1e9;
  for (double factor : {30.0, 10.0, 1.0}) {  // 300x, 100x and 10x the paper's step
    Scene scene = scene_with("di_felice", "exponential");
    scene.integrator.fast_step_factor = factor;
    scene.integrator.local_steps = false;  // the common step bounded by the factor
    Engine fast(engine_setup(scene), sample_of(cloud()));
    fast.advance_to(t);
    const double error = max_position_error(fast, fine, scale);
    EXPECT_LT(error, 0.5 * previous) << factor;
    EXPECT_LT(error, 0.01) << factor;
    EXPECT_LT(fast.stats().steps * 10, fine.stats().steps) << factor;
    previous = error;
  }
  EXPECT_LT(previous, 1e-4);
}

// The step lets no moving grain travel more than crossing_fraction of its radius: a 60 um grain
// falling sets it at first; once it rests on the bottom, the 5 um grain still settling sets it,
// 12x longer.
TEST(ExponentialIntegrator, StepGrowsOnceTheCoarseGrainHasSettled) {
  Scene scene = scene_with("stokes", "exponential");
  scene.integrator.local_steps = false;  // the common step of the global scheme
  scene.integrator.freeze_settled = false;
  scene.integrator.crossing_fraction = 0.5;
  const double large = 60e-6, small = 5e-6;
  Engine engine(engine_setup(scene),
                sample_of({{0, 0.5 * large + 2e-4, large, 0, 0, 1}, {0.01, 0.4, small, 0, 0, 1}}));
  const auto settling = [&](double d) {
    return stokes::terminal_velocity(d, 2500, scene.fluid) / 0.96;
  };
  engine.step(1.0);
  EXPECT_NEAR(engine.stats().last_step, 0.5 * 0.5 * large / settling(large), 1e-9);
  engine.advance_to(1.0);  // the large grain has fallen 0.2 mm and rests on the bottom
  ASSERT_LT(engine.particles().y[0], 0.51 * large);
  const double y = engine.particles().y[1];
  engine.step(2.0);
  const double expected = 0.5 * 0.5 * small / settling(small);
  EXPECT_NEAR(engine.stats().last_step, expected, 1e-3 * expected);
  EXPECT_LE(y - engine.particles().y[1], 0.5 * 0.5 * small * (1 + 1e-9));
}

TEST(Engine, SameSeedAndThreadsGiveTheSameBits) {
  for (const char* method : {"explicit", "exponential"}) {
    Scene scene = scene_with("di_felice", method, 2);
    scene.forces.lubrication = true;
    Engine a(engine_setup(scene), sample_of(cloud())), b(engine_setup(scene), sample_of(cloud()));
    a.advance_to(2e-3);
    b.advance_to(2e-3);
    ASSERT_EQ(a.stats().steps, b.stats().steps);
    for (std::size_t i = 0; i < a.particles().size(); ++i) {
      EXPECT_EQ(a.particles().x[i], b.particles().x[i]) << method;
      EXPECT_EQ(a.particles().vy[i], b.particles().vy[i]) << method;
      EXPECT_EQ(a.particles().omega[i], b.particles().omega[i]) << method;
    }
  }
}

// Both cores: 6000 grains (above the engine's threading threshold), friction and Di Felice
// drag, some dropped on the bottom; two runs with two threads agree bit for bit.
TEST(Engine, TwoThreadRunsGiveTheSameBits) {
  Scene scene = scene_with("di_felice", "exponential", 2);
  scene.integrator.fast_step_factor = 10;
  scene.integrator.local_steps = false;  // local steps are serial: one thread whatever is asked
  const auto grains = test::scattered(
      6000, -0.03, 0.03, 0.0, 0.004, [](int k) { return 5e-6 + 1e-6 * (k % 60); }, 21);
  Engine a(engine_setup(scene), sample_of(grains)), b(engine_setup(scene), sample_of(grains));
  ASSERT_EQ(a.threads(), 2);
  a.advance_to(0.02);
  b.advance_to(0.02);
  EXPECT_GT(a.stats().contacts, 0u);
  for (std::size_t i = 0; i < grains.size(); ++i) {
    ASSERT_EQ(a.particles().x[i], b.particles().x[i]) << i;
    ASSERT_EQ(a.particles().y[i], b.particles().y[i]) << i;
    ASSERT_EQ(a.particles().omega[i], b.particles().omega[i]) << i;
  }
}

// An explicit step far beyond the drag's stability bound (2 tau) blows the velocity up: the
// engine reports the grain, the time and the quantity instead of carrying NaN.
TEST(Engine, BlowUpIsReportedNotSilent) {
  Scene scene = scene_with("stokes", "explicit");
  scene.forces.contact = false;
  scene.integrator.step_factor = 3.0;  // dt = 3 t_tr(95 %) ~ 9 tau
  scene.integrator.adaptive = false;
  Engine engine(engine_setup(scene), sample_of({{0, 0.4, 70e-6}, {0.01, 0.4, 10e-6}}));
  try {
    engine.advance_to(1.0);
    FAIL() << "no instability reported";
  } catch (const InstabilityError& e) {
    EXPECT_EQ(e.particle_id, 101u);  // the 10 um grain, id 100 + index 1
    EXPECT_EQ(e.quantity, "speed");
    EXPECT_GT(e.time, 0);
    EXPECT_LT(e.time, 1.0);
    EXPECT_NE(std::string(e.what()).find("particle 101"), std::string::npos);
  }
}

// The explicit integrator's step grows once every grain has reached its terminal velocity
// (Sect. 4.6) and stays below the explicit drag's stability bound.
TEST(ExplicitIntegrator, StepGrowsAfterTerminalVelocity) {
  Scene scene = scene_with("stokes", "explicit");
  scene.forces.contact = false;
  const double d = 10e-6;
  Engine engine(engine_setup(scene), sample_of({{0, 0.4, d}}));
  engine.advance_to(1e-3);
  const double tau = stokes::relaxation_time(d, 2500, scene.fluid);
  const double first = 0.1 * stokes::response_time(d, 2500, scene.fluid, 0.95);
  engine.advance_to(0.05);
  engine.step(1.0);  // one unclipped step (advance_to shortens its last one to land on 0.05)
  EXPECT_GT(engine.stats().last_step, 2 * first);
  EXPECT_LT(engine.stats().last_step, 2 * tau);
  const double ut = stokes::terminal_velocity(d, 2500, scene.fluid);
  EXPECT_NEAR(-engine.particles().vy[0], ut, 1e-6 * ut);
}

}  // namespace
}  // namespace sedem
