// What sets the members' step (StepLimit, reported by the scale benchmark): a fine grain that a
// coarse one pushes moves at the coarse one's speed and, at 0.8 of its own radius a step, sets
// the step for every member; the step the others alone would allow is the coarse grain's own.
// And what clusters of members on steps of their own would save (EngineStats::own_step_share).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/physics/stokes.h"
#include "core/run/stage_setups.h"
#include "engine_test_support.h"

namespace sedem {
namespace {

Scene local_scene() {
  Scene scene = test::scene_with("stokes", "exponential");
  scene.integrator.local_steps = true;
  return scene;
}

// A coarse grain falling onto a fine one: while it pushes, the fine grain is counted pushed and
// the step the coarse grain alone would allow is about their radii's ratio (15) times the step
// taken; before they meet nothing is pushed and that step is the step itself.
TEST(StepLimit, AFineGrainPushedByACoarseOneIsWhatSetsTheStep) {
  const double coarse = 60e-6, fine = 4e-6;
  const double u = stokes::terminal_velocity(coarse, 2500, Fluid{});
  Engine engine(engine_setup(local_scene()), test::sample_of({{0, 0.2, coarse}, {0, 0.19, fine}}));
  int pushed_steps = 0, free_steps = 0;
  double least_ratio = HUGE_VAL, most_ratio = 0;
  const double end = 0.02 / u;  // 2 cm of the coarse grain's fall
  while (engine.time() < end) {
    engine.step(end);
    const EngineStats& s = engine.stats();
    if (s.members < 2 || s.last_step <= 0) continue;  // the pair not yet stepping together
    ASSERT_GE(s.unpushed_step, s.last_step);
    if (s.pushed == 0) {
      ++free_steps;
      if (engine.time() < end) {
        EXPECT_EQ(s.unpushed_step, s.last_step);
      }
      continue;
    }
    ASSERT_EQ(s.pushed, 1u);
    if (engine.time() > 0.9 * end) break;  // the last steps: the run's end limits them too
    ++pushed_steps;
    least_ratio = std::min(least_ratio, s.unpushed_step / s.last_step);
    most_ratio = std::max(most_ratio, s.unpushed_step / s.last_step);
  }
  EXPECT_GT(free_steps, 0);  // stepping together before they met, nothing pushed
  EXPECT_GT(pushed_steps, 100);
  EXPECT_GT(least_ratio, 5) << most_ratio;
  EXPECT_LT(most_ratio, 15 * 1.5) << least_ratio;
}

// Grains side by side that fall apart without touching share the step for a while, and nothing
// is pushed: the step is what they all allow.
TEST(StepLimit, GrainsFallingApartPushNothing) {
  Engine engine(engine_setup(local_scene()),
                test::sample_of({{0, 0.2, 60e-6}, {52e-6, 0.2, 40e-6}, {89e-6, 0.2, 30e-6}}));
  int shared = 0;
  for (int k = 0; k < 200; ++k) {
    engine.step(1.0);
    EXPECT_EQ(engine.stats().pushed, 0u);
    if (engine.stats().unpushed_step == 0) continue;  // no member moving
    ++shared;
    EXPECT_EQ(engine.stats().unpushed_step, engine.stats().last_step);
  }
  EXPECT_GT(shared, 10);
}

// A pushed pair alone is one cluster: its own step is the common step, and nothing is saved.
// Looks come every 64th step only.
TEST(OwnStepShare, APushedPairAloneIsOneCluster) {
  const double coarse = 60e-6, fine = 4e-6;
  const double u = stokes::terminal_velocity(coarse, 2500, Fluid{});
  Engine engine(engine_setup(local_scene()), test::sample_of({{0, 0.2, coarse}, {0, 0.19, fine}}));
  int looks = 0;
  const double end = 0.02 / u;  // they meet after about 1 cm of the coarse grain's fall
  while (engine.time() < 0.9 * end) {
    engine.step(end);
    const EngineStats& s = engine.stats();
    if (s.steps % 64 != 0) {
      ASSERT_EQ(s.own_step_share, 0) << "looked at step " << s.steps;
      continue;
    }
    if (s.contacts != 2) continue;  // not touching yet: maybe two clusters
    ++looks;
    ASSERT_EQ(s.own_step_share, 1.0) << "at " << engine.time() << " s";
    ASSERT_EQ(s.largest_cluster, 1.0);
  }
  EXPECT_GT(looks, 10);
}

// Two pushed pairs far apart are two clusters: each could take the step its own fastest grain
// allows. A 4 um grain pushed by a 60 um one sets the common step; a 30 um grain pushed by
// another 60 um one would allow about a tenth of that (both falling at their pair's speed, 0.94
// and 0.75 of the coarse grain's alone, over radii of 2 and 15 um), so the four members'
// particle-steps at their clusters' own steps are (2 + 2 x 0.106) / 4 = 0.553 of the common
// step's.
TEST(OwnStepShare, TwoPushedPairsFarApartAreTwoClusters) {
  const double coarse = 60e-6;
  const double u = stokes::terminal_velocity(coarse, 2500, Fluid{});
  Engine engine(
      engine_setup(local_scene()),
      test::sample_of(
          {{-5e-3, 0.2, coarse}, {-5e-3, 0.19, 4e-6}, {5e-3, 0.2, coarse}, {5e-3, 0.19, 30e-6}}));
  int looks = 0;
  const double end = 0.02 / u;
  while (engine.time() < 0.9 * end) {
    engine.step(end);
    const EngineStats& s = engine.stats();
    if (s.contacts != 4 || s.own_step_share == 0) continue;  // both pairs touching, a look
    ++looks;
    EXPECT_NEAR(s.own_step_share, 0.553, 0.01) << "at " << engine.time() << " s";
    EXPECT_EQ(s.largest_cluster, 0.5);  // two moving members of four
  }
  EXPECT_GT(looks, 20);
}

}  // namespace
}  // namespace sedem
