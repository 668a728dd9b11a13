#include "core/run/simulation.h"

#include <algorithm>
#include <exception>
#include <fstream>
#include <stdexcept>
#include <string>

#include "core/engine/engine.h"
#include "core/engine/runner.h"
#include "core/run/stage_setups.h"
#include "core/sample/sample_builder.h"

namespace sedem {

Simulation::Simulation(const Scene& scene) : Simulation(scene, build_sample(sample_setup(scene))) {}

Simulation::Simulation(const Scene& scene, Sample sample)
    : scene_(scene), engine_(std::make_unique<Engine>(engine_setup(scene), std::move(sample))) {}

Simulation::~Simulation() = default;

const Sample& Simulation::sample() const {
  return engine_->sample();
}
double Simulation::time() const {
  return engine_->time();
}
const EngineStats& Simulation::stats() const {
  return engine_->stats();
}
const Particles& Simulation::particles() const {
  return engine_->particles();
}
int Simulation::threads() const {
  return engine_->threads();
}
void Simulation::write_checkpoint(const std::string& path,
                                  const std::function<void(std::ostream&)>& engine) const {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error("cannot write checkpoint " + path);
  engine(out);
  observers_.save_state(out);
  out.flush();
  if (!out) throw std::runtime_error("failed writing checkpoint " + path);
}

void Simulation::save_checkpoint(const std::string& path) const {
  write_checkpoint(path, [&](std::ostream& out) { engine_->save_checkpoint(out); });
}

void Simulation::resume(const std::string& checkpoint) {
  std::ifstream in(checkpoint, std::ios::binary);
  engine_->load_checkpoint(in, checkpoint);
  checkpoint_ = checkpoint;
  observers_at_ = in.tellg();
}

void Simulation::restore_observers() {
  if (checkpoint_.empty()) return;
  std::ifstream in(checkpoint_, std::ios::binary);
  in.seekg(observers_at_);
  try {
    observers_.load_state(in);
  } catch (const std::exception& e) {
    throw std::runtime_error("damaged checkpoint " + checkpoint_ + ": " + e.what());
  }
  if (in.peek() != std::char_traits<char>::eof())
    throw std::runtime_error("damaged checkpoint " + checkpoint_ + ": data after its end");
  checkpoint_.clear();
}

namespace {

// When the periodic checkpoints of a run are due, and taking one (a failure does not end the
// run: it is a warning).
class CheckpointClock {
 public:
  using clock = std::chrono::steady_clock;
  explicit CheckpointClock(const RunControl& c)
      : control_(c),
        periodic_(c.checkpoint && c.checkpoint_every > 0),
        every_(c.checkpoint_every),
        first_(c.first_checkpoint > 0 ? std::min(c.first_checkpoint, c.checkpoint_every)
                                      : c.checkpoint_every) {}
  bool periodic() const { return periodic_; }
  bool due() const { return periodic_ && clock::now() - last_ >= (done_ ? every_ : first_); }
  // `save` writes the engine's state to a path, the engine at rest.
  void take(const std::function<void(const std::string&)>& save) {
    try {
      control_.checkpoint(save);
    } catch (const std::exception& e) {
      if (control_.warning)
        control_.warning(std::string("the periodic checkpoint failed: ") + e.what());
    }
    last_ = clock::now();
    done_ = true;
  }

 private:
  const RunControl& control_;
  bool periodic_;
  std::chrono::duration<double> every_, first_;
  clock::time_point last_ = clock::now();
  bool done_ = false;
};

}  // namespace

// The observers' times from the engine's on, and the scene's end.
std::vector<double> Simulation::remaining_times() const {
  const double end = scene_.end_time, from = engine_->time();
  std::vector<double> times = merge_times({observers_.times(), {end}});
  std::erase_if(times, [&](double t) { return t > end * (1 + 1e-12) || t < from; });
  return times;
}

RunEnd Simulation::run(const RunControl& control) {
  if (control.capacity == 0) return run_in_place(control);
  EngineRunner runner(*engine_, remaining_times(), control.capacity);
  auto report = [&] {
    if (!control.progress) return;
    const auto p = runner.progress();
    control.progress(p.time, p.particle_steps);
  };
  CheckpointClock checkpoints(control);
  // A checkpoint due more often than the poll is looked for more often.
  const auto poll = checkpoints.periodic() && control.checkpoint_every < 0.2
                        ? std::min(control.poll, std::chrono::milliseconds(20))
                        : control.poll;
  bool stopped = false;
  runner.start();
  while (!runner.ended()) {
    if (control.stop_requested && control.stop_requested()) {
      stopped = true;
      break;
    }
    if (checkpoints.due()) {
      // Every snapshot before the engine's time is shown first: a resumed run replays those
      // and goes on from the saved state.
      runner.pause();
      while (auto snapshot = runner.next(std::chrono::milliseconds(0))) observers_.show(*snapshot);
      // Taking a snapshot off a full queue wakes the engine for a moment before it rests on
      // the pause again: wait for that rest, or the checkpoint would find it stepping.
      runner.pause();
      checkpoints.take([&](const std::string& path) {
        write_checkpoint(path, [&](std::ostream& out) { runner.checkpoint(out); });
      });
      runner.resume();
    }
    auto snapshot = runner.next(poll);
    report();
    if (snapshot) observers_.show(*snapshot);
  }
  runner.stop();  // joins the engine's thread: the engine rests between two steps
  // Snapshots computed before the stop are results: they are shown too.
  while (auto snapshot = runner.next(std::chrono::milliseconds(0))) observers_.show(*snapshot);
  report();
  RunEnd result;
  if (runner.state() == EngineRunner::State::failed)
    result.engine_error = runner.error();
  else
    result.completed = runner.state() == EngineRunner::State::finished && !stopped;
  return result;
}

RunEnd Simulation::run_in_place(const RunControl& control) {
  using clock = std::chrono::steady_clock;
  const double end = scene_.end_time;
  auto report = [&] {
    if (control.progress) control.progress(engine_->time(), engine_->stats().particle_steps);
  };
  RunEnd result;
  CheckpointClock checkpoints(control);
  auto last_report = clock::time_point{};  // a stop asked before the run comes before a step
  for (double t : remaining_times()) {
    while (engine_->time() < t) {
      const auto now = clock::now();
      if (now - last_report >= control.poll) {
        report();
        last_report = now;
        if (control.stop_requested && control.stop_requested()) return result;
      }
      // Every observer has seen every time before the engine's: a resumed run replays those
      // and goes on from the saved state.
      if (checkpoints.due())
        checkpoints.take([&](const std::string& path) { save_checkpoint(path); });
      try {
        engine_->step(t);
      } catch (const std::exception& e) {  // an instability, memory: the run ends here
        result.engine_error = e.what();
        report();
        return result;
      }
    }
    // An observer's exception ends the run and goes to the caller, the engine at rest.
    observers_.show_in_place(engine_->time(), engine_->particles());
    if (control.stop_requested && engine_->time() < end && control.stop_requested()) {
      report();
      return result;
    }
  }
  report();
  result.completed = true;
  return result;
}

void Simulation::run_here(const StepWatch& after_step) {
  for (double t : observers_.times()) {
    if (t < engine_->time()) continue;
    while (engine_->time() < t) {  // Engine::advance_to, each step watched
      engine_->step(t);
      if (after_step) after_step(engine_->time(), engine_->stats());
    }
    observers_.show_in_place(engine_->time(), engine_->particles());
    peak_engine_bytes_ = std::max(peak_engine_bytes_, engine_->bytes());
  }
  peak_engine_bytes_ = std::max(peak_engine_bytes_, engine_->bytes());
}

namespace {

// Asks for the engine at one time and reads nothing: a run to its end time with no reading there.
class EndTime final : public Observer {
 public:
  explicit EndTime(double t) : t_(t) {}
  std::string name() const override { return "end time"; }
  std::vector<double> wanted_times() const override { return {t_}; }
  void observe(double, const Particles&) override {}

 private:
  double t_;
};

}  // namespace

SimulationRun simulate(const Scene& scene, Sample sample, bool keep_last,
                       const Simulation::StepWatch& after_step, bool to_end_time) {
  const auto start = std::chrono::steady_clock::now();
  SimulationRun run;
  run.particles = sample.particles.size();
  Simulation simulation(scene, std::move(sample));
  InstrumentObserver instruments(test_setup(scene), simulation.sample());
  simulation.watch(instruments);
  EndTime end(scene.end_time);
  if (to_end_time) simulation.watch(end);
  simulation.run_here(after_step);
  run.results = instruments.results();
  run.stats = simulation.stats();
  if (keep_last) run.last = simulation.particles();
  run.simulated_seconds = simulation.time();
  run.peak_engine_bytes = simulation.peak_engine_bytes();
  run.threads = simulation.threads();
  run.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace sedem
