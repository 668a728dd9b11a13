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

// 1500 grains of 70, 30 and 5 um. Over half a second the coarse and middle grains fall as far
// with carried steps as without (within 0.5 %). The fine grains' mean fall is set by the few that
// ride on coarse ones, and larger steps let them slide off sooner: 3 % less at a fraction of
// 0.2 (and 8 % at 0.4; docs/engine.md), held here within 5 %, in under half the steps.
TEST(CarriedSteps, ACrowdFallsAsWithoutThem) {
  const double hw = Scene{}.cylinder.half_width();
  const auto grains = test::crowd(-0.3 * hw, 0.3 * hw, 0.0005, 0.012);
  double fall[2][3] = {};
  std::int64_t steps[2] = {0, 0};
  for (bool carried : {false, true}) {
    Scene scene = carried_scene(carried);
    scene.forces.drag = "di_felice";
    Engine engine(engine_setup(scene), test::sample_of(grains));
    engine.advance_to(0.5);
    const auto& p = engine.particles();
    int count[3] = {};
    for (std::size_t i = 0; i < grains.size(); ++i) {
      const int size = grains[i].d > 50e-6 ? 0 : (grains[i].d > 20e-6 ? 1 : 2);
      fall[carried][size] += grains[i].y - p.y[i];
      ++count[size];
    }
    for (int s = 0; s < 3; ++s) fall[carried][s] /= count[s];
    steps[carried] = engine.stats().steps;
  }
  for (int s = 0; s < 2; ++s)
    EXPECT_NEAR(fall[1][s], fall[0][s], 0.005 * fall[0][s]) << "size class " << s;
  EXPECT_NEAR(fall[1][2], fall[0][2], 0.05 * fall[0][2]);
  EXPECT_LT(steps[1] * 2, steps[0]) << steps[0] << " " << steps[1];
}

// The carriers come from the contacts the checkpoint holds and the boxes' allowances from the
// boxes it holds: a run interrupted while fine grains are being carried resumes to the same
// bits.
TEST(CarriedSteps, ResumeBitForBit) {
  Scene scene = carried_scene(true);
  scene.forces.drag = "di_felice";
  const double hw = scene.cylinder.half_width();
  const auto grains = test::scattered(
      600, -0.2 * hw, 0.2 * hw, 0.0005, 0.008,
      [](int k) { return k % 3 == 0 ? 70e-6 : (k % 3 == 1 ? 20e-6 : 4e-6); }, 5, 0.0);
  auto checkpoint = [](int k) {
    return (std::filesystem::temp_directory_path() /
            ("sedem_carried_test_" + std::to_string(k) + ".ckpt"))
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

}  // namespace
}  // namespace sedem
