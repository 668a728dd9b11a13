#pragma once

// The one pipeline: a scene's sample, the engine that moves it and the observers that look at
// it, driven through the union of the observers' times. `sedem run`, the benchmarks and the
// schedule design's DEM confirmation all go through it. What a run writes (folders, records,
// checkpoint files) is the caller's; what it computes is here.

#include <chrono>
#include <cstddef>
#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "core/model/engine_stats.h"
#include "core/model/sample.h"
#include "core/observe/instrument_observer.h"
#include "core/observe/observer_set.h"
#include "core/scene/scene.h"

namespace sedem {

class Engine;

// How a run on the engine's own thread is steered from the calling thread.
struct RunControl {
  // Snapshots the engine may run ahead of the observers (each one is 64 bytes a particle).
  // 0: none; the engine steps on the calling thread and waits while the observers look at its
  // particles in place (no copy: at ten million particles two snapshots were 1.3 GB).
  std::size_t capacity = 2;
  // Polled between snapshots, at least every `poll`: true ends the run at the next step.
  std::function<bool()> stop_requested;
  std::function<void(double simulated_time, double particle_steps)> progress;
  std::chrono::milliseconds poll{200};
  // Every `checkpoint_every` s of wall time (0: never), once the observers have seen every
  // snapshot before the engine's time and the engine rests between two steps, `checkpoint` is
  // called with a function that writes the engine's state to a path. The first comes sooner,
  // after `first_checkpoint` s, so that a kill early in a run loses no more than that either.
  double checkpoint_every = 0;
  double first_checkpoint = 10;
  std::function<void(const std::function<void(const std::string&)>& save)> checkpoint;
  // Something went wrong that does not end the run (a periodic checkpoint not written).
  std::function<void(const std::string& message)> warning;
};

// How a run ended. `engine_error` is set when the engine failed (an instability, memory).
struct RunEnd {
  bool completed = false;  // false: stopped, or failed
  std::string engine_error;
};

class Simulation {
 public:
  // The sample is the scene's (built from it, or given: a benchmark times its building).
  explicit Simulation(const Scene& scene);
  Simulation(const Scene& scene, Sample sample);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  const Scene& scene() const { return scene_; }
  // The sample as built (its particles: where the engine has them). Only between runs.
  const Sample& sample() const;
  // Where the engine is. Only between runs (the engine is then at rest).
  double time() const;
  const EngineStats& stats() const;
  const Particles& particles() const;
  int threads() const;  // the engine's
  // The engine's whole state, then the state of the observers that keep one
  // (Observer::keeps_state): a Simulation of the same scene and sample that resumes from it
  // goes on bit for bit.
  void save_checkpoint(const std::string& path) const;

  // An observer looks at the run from now on; the caller keeps it alive while it does.
  void watch(Observer& observer) { observers_.add(observer); }
  const ObserverSet& observers() const { return observers_; }
  // Goes on from a checkpoint this scene and sample wrote (save_checkpoint). The observers
  // that keep a state get it back once they are watched (restore_observers); those that
  // accumulate without one are shown the saved snapshots before it (observers().replay).
  void resume(const std::string& checkpoint);
  // After resume, once every observer is watched: restores the states the checkpoint holds.
  // Throws std::runtime_error naming the observer whose state is missing or damaged.
  void restore_observers();

  // The engine on a thread of its own, the observers on the calling thread in time order,
  // through every observer's time to the scene's end. Snapshots taken before a stop are shown
  // too. An observer's exception ends the run and is rethrown, the engine at rest.
  RunEnd run(const RunControl& control = {});
  // The same with no snapshot (RunControl::capacity = 0): stops, checkpoints and progress come
  // between two steps.
  RunEnd run_in_place(const RunControl& control);
  // Called after each engine step of run_here with the engine's time and counts, to see where
  // a run's time goes (the benchmarks). It only looks: the engine takes the same steps.
  using StepWatch = std::function<void(double time, const EngineStats& stats)>;
  // The engine on the calling thread, to the last time an observer wants (no further): the
  // observers look at the engine's particles in place, with no copy (64 MB at a million).
  void run_here(const StepWatch& after_step = {});
  // The largest Engine::bytes() seen at the observers' times of run_here.
  std::size_t peak_engine_bytes() const { return peak_engine_bytes_; }

 private:
  std::vector<double> remaining_times() const;
  // Writes the checkpoint file: `engine` writes the engine's part to the stream.
  void write_checkpoint(const std::string& path,
                        const std::function<void(std::ostream&)>& engine) const;
  Scene scene_;
  std::string checkpoint_;           // the checkpoint resumed from, until restore_observers
  std::streamoff observers_at_ = 0;  // where its observers' state begins
  std::unique_ptr<Engine> engine_;
  ObserverSet observers_;
  std::size_t peak_engine_bytes_ = 0;
};

// A whole test with no files and no pictures, on the calling thread: what benchmarks and
// accuracy studies need.
struct SimulationRun {
  TestResults results;
  EngineStats stats;
  std::size_t particles = 0;
  Particles last;  // the particles at the last reading, in sample order (if asked for)
  double wall_seconds = 0;
  double simulated_seconds = 0;       // the engine's time at the end (the last reading)
  std::size_t peak_engine_bytes = 0;  // largest Engine::bytes() seen at the readings
  int threads = 1;                    // threads the engine ran with
};

// The instruments read the engine's particles in place. `keep_last` copies them into
// SimulationRun::last at the end; `after_step` sees every step (Simulation::run_here). The run
// ends at the last reading (nothing later is read), or with `to_end_time` at the scene's end
// time: a short run that no reading reaches (the first steps at a large count, measured).
SimulationRun simulate(const Scene& scene, Sample sample, bool keep_last = false,
                       const Simulation::StepWatch& after_step = {}, bool to_end_time = false);

}  // namespace sedem
