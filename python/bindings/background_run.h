#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "app/run_command.h"
#include "core/observe/instrument_observer.h"
#include "python/bindings/particle_keeper.h"

namespace sedem::python {

// `sedem run` on a worker thread of its own: the same run path, folder and files as the
// program's (app::run), steered by a stop flag instead of signals, its progress and results
// kept for the calling thread, which holds Python and reads them between waits.
class BackgroundRun {
 public:
  BackgroundRun(app::RunOptions options, ParticleKeeper keeper);
  ~BackgroundRun();  // asks a running run to stop and waits for it
  BackgroundRun(const BackgroundRun&) = delete;
  BackgroundRun& operator=(const BackgroundRun&) = delete;

  void start();
  void stop() { stop_ = true; }
  bool stop_asked() const { return stop_; }
  // Waits until the run ends or `timeout` passes, or new progress comes; true once it ended.
  bool wait_for(std::chrono::milliseconds timeout);
  bool running() const;

  struct Progress {
    double simulated_time = 0, end_time = 0, particle_steps = 0;
    bool fresh = false;  // not yet taken
  };
  Progress take_progress();

  // After the run ended.
  int status() const { return status_; }
  const std::optional<TestResults>& results() const { return results_; }
  const std::vector<Snapshot>& particles() const { return keeper_.kept(); }
  double simulated_time() const { return simulated_time_; }
  const std::string& error() const { return error_; }

 private:
  void body();
  app::RunOptions options_;
  ParticleKeeper keeper_;
  std::thread thread_;
  std::atomic<bool> stop_{false};
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  bool started_ = false, ended_ = false;
  Progress progress_;
  int status_ = -1;
  std::optional<TestResults> results_;
  double simulated_time_ = 0;
  std::string error_;  // an exception that escaped the run
};

}  // namespace sedem::python
