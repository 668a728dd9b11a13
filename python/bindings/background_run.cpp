#include "python/bindings/background_run.h"

#include <exception>

#include "app/output_observers.h"
#include "core/run/simulation.h"

namespace sedem::python {

BackgroundRun::BackgroundRun(app::RunOptions options, ParticleKeeper keeper)
    : options_(std::move(options)), keeper_(std::move(keeper)) {}

BackgroundRun::~BackgroundRun() {
  if (thread_.joinable()) {
    stop_ = true;
    thread_.join();
  }
}

void BackgroundRun::start() {
  std::lock_guard lock(mutex_);
  if (started_) return;
  started_ = true;
  thread_ = std::thread([this] { body(); });
}

bool BackgroundRun::running() const {
  std::lock_guard lock(mutex_);
  return started_ && !ended_;
}

void BackgroundRun::body() {
  app::RunHooks hooks;
  hooks.stop_requested = [this] { return stop_.load(); };
  hooks.started = [this](const Simulation& simulation) {
    const Scene& scene = simulation.scene();
    keeper_.snap_to(simulation.observers().times(), scene.output.interval, scene.end_time);
    std::lock_guard lock(mutex_);
    progress_.end_time = simulation.scene().end_time;
    progress_.simulated_time = simulation.time();
  };
  hooks.observers = {&keeper_};
  hooks.progress = [this](double t, double steps) {
    {
      std::lock_guard lock(mutex_);
      // The run reports at every poll; the callback hears of a change only.
      if (t == progress_.simulated_time && steps == progress_.particle_steps) return;
      progress_.simulated_time = t;
      progress_.particle_steps = steps;
      progress_.fresh = true;
    }
    changed_.notify_all();
  };
  hooks.finished = [this](const Simulation& simulation, const app::RunObservers& observers) {
    simulated_time_ = simulation.time();
    if (observers.instruments) results_ = observers.instruments->results();
  };
  int status = -1;
  std::string error;
  try {
    status = app::run(options_, hooks);
  } catch (const std::exception& e) {
    error = e.what();
  } catch (...) {
    error = "unknown exception";
  }
  {
    std::lock_guard lock(mutex_);
    status_ = status;
    error_ = error;
    ended_ = true;
  }
  changed_.notify_all();
}

bool BackgroundRun::wait_for(std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  changed_.wait_for(lock, timeout, [this] { return ended_ || progress_.fresh; });
  if (ended_ && thread_.joinable()) {
    lock.unlock();
    thread_.join();
    return true;
  }
  return ended_;
}

BackgroundRun::Progress BackgroundRun::take_progress() {
  std::lock_guard lock(mutex_);
  Progress p = progress_;
  progress_.fresh = false;
  return p;
}

}  // namespace sedem::python
