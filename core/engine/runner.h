#pragma once

// The engine on its own thread (std::thread; no Qt in core). It stops at each requested
// output time, copies an immutable Snapshot and hands it over through a bounded queue: when
// the consumer lags the engine waits, it never drops or overwrites. pause() returns once the
// engine rests between two steps, so the caller may then checkpoint it; stop() ends the run
// at the next step boundary. An exception in the engine (InstabilityError) ends the run and
// is reported by error().

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <iosfwd>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "core/engine/engine.h"

namespace sedem {

class EngineRunner {
 public:
  enum class State { idle, running, paused, finished, stopped, failed };

  EngineRunner(Engine& engine, std::vector<double> output_times, std::size_t capacity = 4);
  ~EngineRunner();
  EngineRunner(const EngineRunner&) = delete;
  EngineRunner& operator=(const EngineRunner&) = delete;

  void start();
  // Blocks until the engine rests between steps (or the run has ended).
  void pause();
  void resume();
  // Ends the run at the next step boundary and joins the thread; queued snapshots stay.
  void stop();
  // The next snapshot in time order; blocks; nullopt once the run has ended and the queue
  // is drained.
  std::optional<Snapshot> next();
  // The same, waiting at most `timeout`: nullopt also when none came in time (then ended()
  // tells the two apart).
  std::optional<Snapshot> next(std::chrono::milliseconds timeout);
  // The run has ended and every snapshot has been taken.
  bool ended() const;

  // Where the engine is, readable from any thread while it runs.
  struct Progress {
    double time = 0;
    double particle_steps = 0;
  };
  Progress progress() const { return {progress_time_.load(), progress_steps_.load()}; }
  // Saves the engine's state; only while paused or after the run has ended.
  void checkpoint(std::ostream& out);

  State state() const;
  std::string error() const;

 private:
  void run();
  bool wait_if_paused(std::unique_lock<std::mutex>& lock);  // false: stop requested

  Engine& engine_;
  std::vector<double> times_;
  std::size_t capacity_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Snapshot> queue_;
  State state_ = State::idle;
  bool pause_requested_ = false, stop_requested_ = false, resting_ = false, done_ = false;
  std::string error_;
  std::thread thread_;
  std::atomic<double> progress_time_{0}, progress_steps_{0};
};

}  // namespace sedem
