// The one pipeline: the observers see the snapshots they asked for, in time order, whether
// the engine runs on its own thread or on the caller's; a stopped run resumed from its
// checkpoint reads what a run that never stopped reads.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/run/simulation.h"
#include "core/run/stage_setups.h"
#include "core/sample/sample_builder.h"
#include "core/scene/scene_loader.h"

namespace sedem {
namespace {

Scene small_scene(double end_time = 120) {
  return load_scene(std::filesystem::path(SEDEM_SOURCE_DIR) / "scenes" / "sample5.toml",
                    {"sample.simulated_count=600", "run.end_time_s=" + std::to_string(end_time)});
}

// Remembers the times it was shown and the particle count each time.
class TimeLog : public Observer {
 public:
  explicit TimeLog(std::vector<double> times) : times_(std::move(times)) {}
  std::string name() const override { return "log"; }
  std::vector<double> wanted_times() const override { return times_; }
  void observe(double time, const Particles& particles) override {
    seen.push_back(time);
    counts.push_back(particles.size());
  }
  std::vector<double> seen;
  std::vector<std::size_t> counts;

 private:
  std::vector<double> times_;
};

std::vector<double> dem_percent(const TestResults& r) {
  std::vector<double> out;
  for (const auto& test : r.dem())
    for (const auto& reading : test.rows) out.push_back(reading.percent_finer);
  return out;
}

TEST(Simulation, RunShowsEachObserverItsTimesInOrderAndGoesOnToTheEnd) {
  const Scene scene = small_scene(100);
  Simulation simulation(scene);
  TimeLog early({10, 30}), late({20, 30, 250});  // 250 s lies past the end: never shown
  simulation.watch(early);
  simulation.watch(late);
  const RunEnd end = simulation.run();
  EXPECT_TRUE(end.completed);
  EXPECT_TRUE(end.engine_error.empty());
  EXPECT_EQ(early.seen, (std::vector<double>{10, 30}));
  EXPECT_EQ(late.seen, (std::vector<double>{20, 30}));
  EXPECT_EQ(early.counts.front(), simulation.sample().particles.size());
  EXPECT_DOUBLE_EQ(simulation.time(), 100.0);  // the scene's end, wanted or not
}

// With snapshots (the engine on its own thread) or none (the engine waits while the observers
// look at its particles in place, RunControl::capacity = 0).
TEST(Simulation, EngineOnItsOwnThreadReadsWhatTheCallersThreadReads) {
  const Scene scene = small_scene();
  const SimulationRun here = simulate(scene, build_sample(sample_setup(scene)));
  for (std::size_t capacity : {2, 0}) {
    Simulation threaded(scene);
    InstrumentObserver instruments(test_setup(scene), threaded.sample());
    threaded.watch(instruments);
    RunControl control;
    control.capacity = capacity;
    ASSERT_TRUE(threaded.run(control).completed);
    const auto a = dem_percent(instruments.results()), b = dem_percent(here.results);
    ASSERT_FALSE(a.empty());
    EXPECT_EQ(a, b) << capacity;
    EXPECT_EQ(threaded.stats().steps, here.stats.steps) << capacity;
  }
}

TEST(Simulation, StopsWhenAskedAndShowsWhatWasComputed) {
  const Scene scene = small_scene();
  for (std::size_t capacity : {1, 0}) {
    Simulation simulation(scene);
    TimeLog log({10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 110});
    simulation.watch(log);
    RunControl control;
    control.capacity = capacity;
    control.poll = std::chrono::milliseconds(1);
    // Asked before the first snapshot is taken: the engine, one snapshot ahead at most, waits
    // for room in the queue and cannot reach the end; with none, it stops before its first step.
    control.stop_requested = [] { return true; };
    const RunEnd end = simulation.run(control);
    EXPECT_FALSE(end.completed);
    EXPECT_TRUE(end.engine_error.empty());
    EXPECT_LE(log.seen.size(), capacity == 0 ? 0u : 2u);
    EXPECT_LT(simulation.time(), 120.0);
    for (std::size_t k = 1; k < log.seen.size(); ++k) EXPECT_LT(log.seen[k - 1], log.seen[k]);
  }
}

// The first leg with snapshots, or with none.
class ResumedFromItsCheckpoint : public ::testing::TestWithParam<std::size_t> {};

TEST_P(ResumedFromItsCheckpoint, ReadsWhatAStraightRunReads) {
  const Scene scene = small_scene();
  const auto dir =
      std::filesystem::path(SEDEM_TEST_OUTPUT) / ("simulation_resume" + std::to_string(GetParam()));
  std::filesystem::create_directories(dir);
  const std::string checkpoint = (dir / "run.checkpoint").string();

  // The first leg stops after the 60 s readings; what it showed is kept as a saved series.
  std::vector<Snapshot> saved;
  class Keeper : public Observer {
   public:
    Keeper(std::vector<double> t, std::vector<Snapshot>& out) : times_(std::move(t)), out_(out) {}
    std::string name() const override { return "keeper"; }
    std::vector<double> wanted_times() const override { return times_; }
    void observe(double time, const Particles& p) override { out_.push_back(Snapshot{time, p}); }

   private:
    std::vector<double> times_;
    std::vector<Snapshot>& out_;
  };
  {
    Simulation first(scene);
    InstrumentObserver instruments(test_setup(scene), first.sample());
    Keeper keeper(instruments.wanted_times(), saved);
    first.watch(instruments);
    first.watch(keeper);
    RunControl control;
    control.capacity = GetParam();
    control.poll = std::chrono::milliseconds(1);
    control.stop_requested = [&] { return !saved.empty() && saved.back().time >= 60; };
    ASSERT_FALSE(first.run(control).completed);
    first.save_checkpoint(checkpoint);
  }
  const double stopped_at = saved.back().time;

  Simulation resumed(scene);
  InstrumentObserver instruments(test_setup(scene), resumed.sample());
  resumed.watch(instruments);
  resumed.resume(checkpoint);
  EXPECT_GE(resumed.time(), stopped_at);
  // The instruments' readings so far come back from the checkpoint: no snapshot is replayed.
  resumed.restore_observers();
  EXPECT_FALSE(resumed.observers().needs_replay(resumed.time()));
  EXPECT_FALSE(instruments.results().granulometry.tests.empty());
  ASSERT_TRUE(resumed.run().completed);

  const SimulationRun straight = simulate(scene, build_sample(sample_setup(scene)));
  EXPECT_EQ(dem_percent(instruments.results()), dem_percent(straight.results));

  // A checkpoint cut short in the instruments' part, or with bytes after it, is refused with
  // what is wrong, once the observers are to be restored.
  const auto size = std::filesystem::file_size(checkpoint);
  for (const bool cut : {true, false}) {
    const std::string damaged = checkpoint + (cut ? ".cut" : ".long");
    std::filesystem::copy_file(checkpoint, damaged,
                               std::filesystem::copy_options::overwrite_existing);
    if (cut)
      std::filesystem::resize_file(damaged, size - 12);
    else
      std::ofstream(damaged, std::ios::binary | std::ios::app) << "extra";
    Simulation again(scene);
    InstrumentObserver watching(test_setup(scene), again.sample());
    again.watch(watching);
    again.resume(damaged);
    try {
      again.restore_observers();
      ADD_FAILURE() << "a damaged checkpoint was restored: " << damaged;
    } catch (const std::runtime_error& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("damaged checkpoint"), std::string::npos) << what;
      EXPECT_NE(what.find(cut ? "truncated" : "after its end"), std::string::npos) << what;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Simulation, ResumedFromItsCheckpoint, ::testing::Values(1, 0));

TEST(Simulation, PeriodicCheckpointsAreTakenWhileTheEngineRests) {
  for (std::size_t capacity : {2, 0}) {
    const Scene scene = small_scene(60);
    const auto dir = std::filesystem::path(SEDEM_TEST_OUTPUT) / "simulation_periodic";
    std::filesystem::create_directories(dir);
    Simulation simulation(scene);
    TimeLog log({10, 20, 30, 40, 50});
    simulation.watch(log);
    RunControl control;
    control.capacity = capacity;
    control.checkpoint_every = 1e-9;  // due at every look
    int taken = 0;
    control.checkpoint = [&](const std::function<void(const std::string&)>& save) {
      save((dir / "periodic.checkpoint").string());
      ++taken;
    };
    ASSERT_TRUE(simulation.run(control).completed);
    EXPECT_GE(taken, 1);
    // The last one written loads into an engine of the same scene.
    Simulation again(scene);
    again.resume((dir / "periodic.checkpoint").string());
    EXPECT_GT(again.time(), 0.0);
    EXPECT_LE(again.time(), 60.0);
  }
}

}  // namespace
}  // namespace sedem
