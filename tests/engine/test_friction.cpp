// Coulomb friction in the exponential integrator's contact projection, against the explicit
// integrator (the paper's explicit springs, Eqs. 1-5).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "engine_test_support.h"

namespace sedem {
namespace {

using test::sample_of;
using test::scene_with;

Scene friction_scene(const std::string& method, double mu, double crossing = 0.8) {
  Scene scene = scene_with("stokes", method);
  scene.forces.friction = mu;
  scene.integrator.local_steps = false;
  scene.integrator.crossing_fraction = crossing;
  return scene;
}

// A 20 um grain on a 70 um grain resting on the floor, 40 degrees off its top, just touching.
std::vector<test::Grain> grain_on_grain() {
  const double big = 70e-6, small = 20e-6, angle = 40.0 * std::acos(-1.0) / 180.0;
  const double reach = 0.5 * (big + small) * (1 + 1e-7);
  return {{0, 0.5 * big, big},
          {reach * std::sin(angle), 0.5 * big + reach * std::cos(angle), small}};
}

// It runs down the coarse grain's side and, with friction, rolls: its spin is what the
// explicit integrator gives (and close to its speed over its radius), its path the same.
TEST(Friction, AGrainRollsDownAnotherAsWithTheExplicitIntegrator) {
  const double t = 2e-3;
  auto run = [&](const std::string& method, double mu) {
    Engine engine(engine_setup(friction_scene(method, mu)), sample_of(grain_on_grain()));
    engine.advance_to(t);
    return engine.particles();
  };
  const Particles ref = run("explicit", 0.5), fast = run("exponential", 0.5);
  EXPECT_NEAR(fast.x[1], ref.x[1], 0.02e-6);
  EXPECT_NEAR(fast.y[1], ref.y[1], 0.02e-6);
  // Measured -21.6 against -23.7 rad/s; its speed over its radius is 21.4.
  EXPECT_LT(fast.omega[1], -15.0);
  EXPECT_NEAR(fast.omega[1], ref.omega[1], 0.15 * std::abs(ref.omega[1]));
  const double rolling = std::hypot(fast.vx[1], fast.vy[1]) / 10e-6;
  EXPECT_NEAR(-fast.omega[1], rolling, 0.1 * rolling);
  // Without friction nothing turns.
  EXPECT_EQ(run("exponential", 0.0).omega[1], 0.0);
  EXPECT_EQ(run("explicit", 0.0).omega[1], 0.0);
}

// A small pile: three 40 um grains in a row on the (frictionless) floor, two in the grooves
// above, one on top. Friction holds it: the bottom row spreads less than without. With a small
// step the exponential integrator's pile is the explicit integrator's.
std::vector<test::Grain> small_pile() {
  const double d = 40e-6, r = 0.5 * d, h = d * std::sqrt(3.0) / 2 * (1 + 1e-7);
  std::vector<test::Grain> g;
  for (int k = -1; k <= 1; ++k) g.push_back({k * d * (1 + 1e-7), r * (1 + 1e-7), d});
  g.push_back({-0.5 * d, r + h, d});
  g.push_back({0.5 * d, r + h, d});
  g.push_back({0.0, r + 2 * h, d});
  return g;
}

struct PileShape {
  double spread, top;  // x of the right bottom grain, y of the top grain
};

PileShape pile(const std::string& method, double mu, double crossing) {
  Engine engine(engine_setup(friction_scene(method, mu, crossing)), sample_of(small_pile()));
  engine.advance_to(0.02);
  const auto& p = engine.particles();
  return {p.x[2], p.y[5]};
}

TEST(Friction, SmallPileAsWithTheExplicitIntegrator) {
  const PileShape ref = pile("explicit", 0.5, 0.8), ref_free = pile("explicit", 0.0, 0.8);
  const PileShape fast = pile("exponential", 0.5, 0.01);
  // Measured at 20 ms: spread 46.93 um (explicit) against 47.05, top 84.79 against 84.71;
  // without friction the explicit integrator spreads to 51.03 um: friction's effect is 4.1 um, and
  // the two integrators agree on it within 3 %.
  EXPECT_GT(ref_free.spread - ref.spread, 3e-6);
  EXPECT_NEAR(fast.spread, ref.spread, 0.25e-6);
  EXPECT_NEAR(fast.top, ref.top, 0.25e-6);
  std::printf("spread %.3f / %.3f um, top %.3f / %.3f um\n", ref.spread * 1e6, fast.spread * 1e6,
              ref.top * 1e6, fast.top * 1e6);
  // At the default step (0.8 of a radius a step, here 1.5 ms against the pile's 20 ms) the pile
  // runs ahead: 51.8 um. The step, not the friction, sets that error: 47.5 at 0.1.
  const PileShape coarse = pile("exponential", 0.5, 0.1);
  EXPECT_NEAR(coarse.spread, ref.spread, 1.0e-6);
}

// The tangential forces are kept across steps and in checkpoints: a run resumed from one
// ends on the same bits.
TEST(Friction, ResumesBitForBit) {
  const Scene scene = friction_scene("exponential", 0.5, 0.1);
  const std::string checkpoint =
      (std::filesystem::temp_directory_path() / "sedem_friction_test.ckpt").string();
  Engine first(engine_setup(scene), sample_of(small_pile()));
  first.advance_to(0.005);
  first.save_checkpoint(checkpoint);
  first.advance_to(0.01);
  Engine resumed(engine_setup(scene), sample_of(small_pile()));
  resumed.load_checkpoint(checkpoint);
  resumed.advance_to(0.01);
  const Particles& a = first.particles();
  const Particles& b = resumed.particles();
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a.x[i], b.x[i]) << i;
    EXPECT_EQ(a.y[i], b.y[i]) << i;
    EXPECT_EQ(a.omega[i], b.omega[i]) << i;
  }
  std::filesystem::remove(checkpoint);
}

}  // namespace
}  // namespace sedem
