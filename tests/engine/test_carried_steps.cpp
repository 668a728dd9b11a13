// Carried steps (integrator.carried_steps): a grain held against a coarser one steps at the
// coarser one's pace. What must not change: no grain passes through another, the local
// scheme's promise holds, a run resumes bit for bit; what must: far fewer common steps while a
// coarse grain pushes a fine one.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "core/physics/stokes.h"
#include "core/run/stage_setups.h"
#include "engine_test_support.h"

namespace sedem {
namespace {

// The fraction the benchmark and docs/engine.md compare (0.2: a fine grain's ride on a coarse
// one is resolved in steps of a fifth of the coarse radius).
constexpr double kFraction = 0.2;

Scene carried_scene(bool carried) {
  Scene scene = test::scene_with("stokes", "exponential");
  scene.integrator.local_steps = true;
  scene.integrator.carried_fraction = carried ? kFraction : 0.0;
  return scene;
}

// Carried sub-steps: the step the coarse grains alone allow (a carried fraction of
// crossing_fraction), the carried grains in sub-steps of their own radius.
Scene substep_scene() {
  Scene scene = carried_scene(true);
  scene.integrator.carried_fraction = scene.integrator.crossing_fraction;
  scene.integrator.carried_substeps = true;
  return scene;
}

// A coarse grain falling straight onto a fine one pushes it down ahead of itself, with or
// without carried steps; with them the pushing takes a fraction of the steps, since the fine
// grain no longer sets the step at its own radius (a fifteenth of the coarse one's).
TEST(CarriedSteps, ACoarseGrainStillPushesAFineOneAheadInFewerSteps) {
  const double coarse = 60e-6, fine = 4e-6;
  const double u = stokes::terminal_velocity(coarse, 2500, Fluid{});
  std::int64_t steps[2] = {0, 0};
  double fine_y[2] = {0, 0};
  for (bool carried : {false, true}) {
    Engine engine(engine_setup(carried_scene(carried)),
                  test::sample_of({{0, 0.2, coarse}, {0, 0.19, fine}}));
    double worst = 0;
    for (int k = 1; k <= 200; ++k) {
      engine.advance_to(k * 0.02 / u / 100);  // 2 cm of the coarse grain's fall in all
      const auto& p = engine.particles();
      ASSERT_GT(p.y[0], p.y[1]) << carried << " " << k;
      const double gap = std::hypot(p.x[0] - p.x[1], p.y[0] - p.y[1]) - 0.5 * (coarse + fine);
      worst = std::min(worst, gap);
      ASSERT_EQ(engine.local_violation(), "") << carried << " " << k;
    }
    EXPECT_GT(worst, -0.3 * 0.5 * fine) << carried;  // overlaps a fraction of the fine radius
    steps[carried] = engine.stats().steps;
    fine_y[carried] = engine.particles().y[1];
  }
  // The pair falls at the same speed either way (the fine grain carried ahead of the coarse).
  EXPECT_NEAR(fine_y[1], fine_y[0], 0.01 * 0.02) << fine_y[0] << " " << fine_y[1];
  EXPECT_LT(steps[1] * 2, steps[0]) << steps[0] << " " << steps[1];
}

// 1500 grains of 70, 30 and 5 um over half a second under Di Felice drag: each size class's
// mean fall (coarse, middle, fine) and the common steps taken.
struct CrowdFall {
  double fall[3] = {};
  std::int64_t steps = 0;
};
CrowdFall crowd_fall(Scene scene) {
  const double hw = scene.cylinder.half_width();
  const auto grains = test::crowd(-0.3 * hw, 0.3 * hw, 0.0005, 0.012);
  scene.forces.drag = "di_felice";
  Engine engine(engine_setup(scene), test::sample_of(grains));
  engine.advance_to(0.5);
  const auto& p = engine.particles();
  CrowdFall out;
  int count[3] = {};
  for (std::size_t i = 0; i < grains.size(); ++i) {
    const int size = grains[i].d > 50e-6 ? 0 : (grains[i].d > 20e-6 ? 1 : 2);
    out.fall[size] += grains[i].y - p.y[i];
    ++count[size];
  }
  for (int s = 0; s < 3; ++s) out.fall[s] /= count[s];
  out.steps = engine.stats().steps;
  return out;
}

// The crowd's coarse and middle grains fall as far with carried steps as without (within
// 0.5 %). The fine grains' mean fall is set by the few that ride on coarse ones, and larger
// steps let them slide off sooner: 3 % less at a fraction of 0.2 (and 8 % at 0.4;
// docs/engine.md), held here within 5 %, in under half the steps.
TEST(CarriedSteps, ACrowdFallsAsWithoutThem) {
  const CrowdFall own = crowd_fall(carried_scene(false)), carried = crowd_fall(carried_scene(true));
  for (int s = 0; s < 2; ++s)
    EXPECT_NEAR(carried.fall[s], own.fall[s], 0.005 * own.fall[s]) << "size class " << s;
  EXPECT_NEAR(carried.fall[2], own.fall[2], 0.05 * own.fall[2]);
  EXPECT_LT(carried.steps * 2, own.steps) << own.steps << " " << carried.steps;
}

// The carriers come from the contacts the checkpoint holds and the boxes' allowances from the
// boxes it holds: a run interrupted while fine grains are being carried resumes to the same
// bits. A checkpoint keeps no member's last blocker (LocalStepper::blocker_), so the resumed
// run's first release tries query the registry where the straight run's skip it: a skip that
// is not exact fails here (checked).
// `name` keeps the checkpoints of two tests apart (ctest runs them side by side).
void expect_resume_bit_for_bit(Scene scene, const std::string& name) {
  scene.forces.drag = "di_felice";
  const double hw = scene.cylinder.half_width();
  const auto grains = test::scattered(
      600, -0.2 * hw, 0.2 * hw, 0.0005, 0.008,
      [](int k) { return k % 3 == 0 ? 70e-6 : (k % 3 == 1 ? 20e-6 : 4e-6); }, 5, 0.0);
  auto checkpoint = [&](int k) {
    return (std::filesystem::temp_directory_path() /
            ("sedem_" + name + "_test_" + std::to_string(k) + ".ckpt"))
        .string();
  };
  // Interrupted at every 20 ms: some of those stops fall while grains are carried.
  constexpr int kStops = 12;
  Engine first(engine_setup(scene), test::sample_of(grains));
  for (int k = 1; k <= kStops; ++k) {
    first.advance_to(0.02 * k);
    first.save_checkpoint(checkpoint(k));
  }
  first.advance_to(0.3);
  const Particles& a = first.particles();
  for (int k = 1; k <= kStops; ++k) {
    Engine resumed(engine_setup(scene), test::sample_of(grains));
    resumed.load_checkpoint(checkpoint(k));
    for (int j = k + 1; j <= kStops; ++j) resumed.advance_to(0.02 * j);  // the same stops
    resumed.advance_to(0.3);
    const Particles& b = resumed.particles();
    for (std::size_t i = 0; i < grains.size(); ++i) {
      ASSERT_EQ(b.x[i], a.x[i]) << "stop " << k << ", grain " << i;
      ASSERT_EQ(b.y[i], a.y[i]) << "stop " << k << ", grain " << i;
      ASSERT_EQ(b.vy[i], a.vy[i]) << "stop " << k << ", grain " << i;
    }
    EXPECT_EQ(resumed.stats().steps, first.stats().steps) << k;
    std::filesystem::remove(checkpoint(k));
  }
  EXPECT_GT(first.stats().engaged, 50);  // grains met
}

TEST(CarriedSteps, ResumeBitForBit) {
  expect_resume_bit_for_bit(carried_scene(true), "carried");
}

// The fast set is found anew from the state each step, and the forces of its pairs are kept
// while the others step: a run stopped between two steps resumes to the same bits.
TEST(CarriedSubsteps, ResumeBitForBit) {
  expect_resume_bit_for_bit(substep_scene(), "carried_substeps");
}

// A coarse grain falling onto a fine one: with sub-steps the pair falls as with every grain
// at its own radius, in as few common steps as carried steps take, and overlaps no deeper.
TEST(CarriedSubsteps, ACoarseGrainPushesAFineOneAsAtItsOwnRadius) {
  const double coarse = 60e-6, fine = 4e-6;
  const double u = stokes::terminal_velocity(coarse, 2500, Fluid{});
  std::int64_t steps[2] = {0, 0};
  double fine_y[2] = {0, 0}, particle_steps[2] = {0, 0};
  for (int sub : {0, 1}) {
    Engine engine(engine_setup(sub ? substep_scene() : carried_scene(false)),
                  test::sample_of({{0, 0.2, coarse}, {0, 0.19, fine}}));
    double worst = 0;
    std::size_t fast = 0, substeps = 0;  // the most of any step
    for (int k = 1; k <= 200; ++k) {
      engine.advance_to(k * 0.02 / u / 100);
      fast = std::max(fast, engine.stats().fast_set);
      substeps = std::max(substeps, engine.stats().substeps);
      const auto& p = engine.particles();
      ASSERT_GT(p.y[0], p.y[1]) << sub << " " << k;
      const double gap = std::hypot(p.x[0] - p.x[1], p.y[0] - p.y[1]) - 0.5 * (coarse + fine);
      worst = std::min(worst, gap);
      ASSERT_EQ(engine.local_violation(), "") << sub << " " << k;
    }
    EXPECT_GT(worst, -0.3 * 0.5 * fine) << sub;
    steps[sub] = engine.stats().steps;
    fine_y[sub] = engine.particles().y[1];
    particle_steps[sub] = engine.stats().particle_steps;
    // The pair is the fast set, and takes the coarse grain's step in many sub-steps.
    if (sub) {
      EXPECT_EQ(fast, 2u);
      EXPECT_GT(substeps, 5u);
      EXPECT_LE(substeps, 100u);
    } else {
      EXPECT_EQ(fast + substeps, 0u);
    }
  }
  EXPECT_NEAR(fine_y[1], fine_y[0], 1e-3 * 0.02) << fine_y[0] << " " << fine_y[1];
  EXPECT_LT(steps[1] * 5, steps[0]) << steps[0] << " " << steps[1];
  // The fine grain's sub-steps are counted: about as many particle-steps as before.
  EXPECT_GT(particle_steps[1], 0.5 * particle_steps[0])
      << particle_steps[0] << " " << particle_steps[1];
}

// The crowd of CarriedSteps.ACrowdFallsAsWithoutThem. With carried steps alone at 0.8 the fine
// grains fall 8 % less than with every grain at its own radius (they slide off the coarse ones
// sooner); with sub-steps 2.1 % less, in a sixth of the common steps. (The fine grains' mean is
// set by the few riding on coarse ones, and moves with the syncs' sequence: 1.3 % when this
// test was written, 1.7 % before windows were bisected between their halvings, with the
// one-rate scheme's fall the same to 5 digits throughout.) (Against the own-radius
// rule at crossing_fraction 0.15, its converged value: own radius -1.3 %, sub-steps -2.5 %; a
// pushed grain's first contact comes at the coarse grain's step, where the one-rate scheme's
// step is what the pushed grains elsewhere leave it: docs/engine.md.) The coarse and middle
// grains fall as far, within 0.2 %.
TEST(CarriedSubsteps, ACrowdFallsAsAtItsOwnRadius) {
  Scene alone = carried_scene(true);  // carried steps without sub-steps, at 0.8
  alone.integrator.carried_fraction = alone.integrator.crossing_fraction;
  const CrowdFall own = crowd_fall(carried_scene(false)), carried = crowd_fall(alone),
                  sub = crowd_fall(substep_scene());
  for (int s = 0; s < 2; ++s)
    EXPECT_NEAR(sub.fall[s], own.fall[s], 0.003 * own.fall[s]) << "size class " << s;
  EXPECT_NEAR(sub.fall[2], own.fall[2], 0.025 * own.fall[2]);
  EXPECT_LT(std::abs(sub.fall[2] - own.fall[2]) * 3, std::abs(carried.fall[2] - own.fall[2]))
      << own.fall[2] << " " << carried.fall[2] << " " << sub.fall[2];
  EXPECT_LT(sub.steps * 4, own.steps) << own.steps << " " << sub.steps;
}

}  // namespace
}  // namespace sedem
