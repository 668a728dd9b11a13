// The engine on its own thread: snapshots in order through the bounded queue, pause and stop,
// and checkpoint + resume giving the same bits as an uninterrupted run.
#include <gtest/gtest.h>

#include <fstream>
#include <random>

#include "core/engine/runner.h"
#include "core/run/stage_setups.h"
#include "tests/engine/engine_test_support.h"

namespace sedem {
namespace {

using test::Grain;
using test::sample_of;
using test::scene_with;

// Grains dropped onto the bottom so that contacts and their carried-over forces are in the state.
std::vector<Grain> heap() {
  return test::scattered(
      60, -1e-4, 1e-4, 2e-5, 4e-4, [](int k) { return 10e-6 + 3e-6 * (k % 10); }, 9);
}

Scene heap_scene() {
  Scene scene = scene_with("di_felice", "exponential", 2);
  scene.forces.friction = 0.5;
  scene.integrator.fast_step_factor = 10;
  return scene;
}

TEST(EngineRunner, HandsOverSnapshotsInOrder) {
  Scene scene = heap_scene();
  Engine engine(engine_setup(scene), sample_of(heap()));
  EngineRunner runner(engine, {0.01, 0.02, 0.03, 0.04, 0.05}, 2);
  runner.start();
  double last = 0;
  int count = 0;
  while (auto snap = runner.next()) {
    EXPECT_GT(snap->time, last);
    EXPECT_EQ(snap->particles.size(), 60u);
    last = snap->time;
    ++count;
  }
  EXPECT_EQ(count, 5);
  EXPECT_DOUBLE_EQ(last, 0.05);
  EXPECT_EQ(runner.state(), EngineRunner::State::finished);
}

TEST(EngineRunner, StopsCleanly) {
  Scene scene = heap_scene();
  Engine engine(engine_setup(scene), sample_of(heap()));
  EngineRunner runner(engine, {1e3}, 1);
  runner.start();
  runner.stop();
  EXPECT_EQ(runner.state(), EngineRunner::State::stopped);
  EXPECT_LT(engine.time(), 1e3);
  EXPECT_FALSE(runner.next().has_value());
}

TEST(EngineRunner, CheckpointAndResumeGiveTheSameBits) {
  const std::string path = std::string(SEDEM_TEST_OUTPUT) + "/engine_resume.ckpt";
  const std::vector<double> times{0.01, 0.02, 0.03};
  Scene scene = heap_scene();

  Engine straight(engine_setup(scene), sample_of(heap()));
  for (double t : times) straight.advance_to(t);

  {
    Engine first(engine_setup(scene), sample_of(heap()));
    EngineRunner runner(first, times, 1);
    runner.start();
    auto snap = runner.next();  // 0.01
    ASSERT_TRUE(snap);
    runner.pause();
    {
      std::ofstream out(path, std::ios::binary);
      runner.checkpoint(out);
    }
    runner.stop();
  }
  Engine resumed(engine_setup(scene), sample_of(heap()));
  resumed.load_checkpoint(path);
  EXPECT_GT(resumed.time(), 0.0);
  EXPECT_GT(resumed.stats().contacts, 0u);
  for (double t : times) resumed.advance_to(t);  // stops at the same output times
  EXPECT_EQ(resumed.stats().steps, straight.stats().steps);
  for (std::size_t i = 0; i < 60; ++i) {
    EXPECT_EQ(resumed.particles().x[i], straight.particles().x[i]) << i;
    EXPECT_EQ(resumed.particles().y[i], straight.particles().y[i]) << i;
    EXPECT_EQ(resumed.particles().omega[i], straight.particles().omega[i]) << i;
  }
}

}  // namespace
}  // namespace sedem
