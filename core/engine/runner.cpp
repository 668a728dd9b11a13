#include "core/engine/runner.h"

#include <stdexcept>

namespace sedem {

EngineRunner::EngineRunner(Engine& engine, std::vector<double> output_times, std::size_t capacity)
    : engine_(engine), times_(std::move(output_times)), capacity_(capacity < 1 ? 1 : capacity) {}

EngineRunner::~EngineRunner() {
  stop();
}

void EngineRunner::start() {
  std::lock_guard lock(mutex_);
  if (state_ != State::idle) return;
  state_ = State::running;
  thread_ = std::thread([this] { run(); });
}

bool EngineRunner::wait_if_paused(std::unique_lock<std::mutex>& lock) {
  while (pause_requested_ && !stop_requested_) {
    resting_ = true;
    state_ = State::paused;
    changed_.notify_all();
    changed_.wait(lock);
  }
  if (state_ == State::paused) state_ = State::running;
  resting_ = false;
  return !stop_requested_;
}

void EngineRunner::run() {
  try {
    for (double t : times_) {
      while (engine_.time() < t) {
        {
          std::unique_lock lock(mutex_);
          if (!wait_if_paused(lock)) break;
        }
        engine_.step(t);
        progress_time_.store(engine_.time());
        progress_steps_.store(engine_.stats().particle_steps);
      }
      std::unique_lock lock(mutex_);
      if (stop_requested_) break;
      lock.unlock();
      Snapshot snap = engine_.snapshot();
      lock.lock();
      while (queue_.size() >= capacity_ && !stop_requested_) {
        // Waiting for the consumer is a rest between steps too: a pause may be granted.
        resting_ = true;
        state_ = pause_requested_ ? State::paused : State::running;
        changed_.notify_all();
        changed_.wait(lock);
      }
      resting_ = false;
      if (!wait_if_paused(lock)) break;
      queue_.push_back(std::move(snap));
      changed_.notify_all();
    }
    std::lock_guard lock(mutex_);
    state_ = stop_requested_ ? State::stopped : State::finished;
  } catch (const std::exception& e) {
    std::lock_guard lock(mutex_);
    state_ = State::failed;
    error_ = e.what();
  }
  std::lock_guard lock(mutex_);
  done_ = true;
  resting_ = true;
  changed_.notify_all();
}

void EngineRunner::pause() {
  std::unique_lock lock(mutex_);
  pause_requested_ = true;
  changed_.notify_all();
  changed_.wait(lock, [&] { return resting_ || done_ || state_ == State::idle; });
}

void EngineRunner::resume() {
  std::lock_guard lock(mutex_);
  pause_requested_ = false;
  changed_.notify_all();
}

void EngineRunner::stop() {
  {
    std::lock_guard lock(mutex_);
    stop_requested_ = true;
    changed_.notify_all();
  }
  if (thread_.joinable()) thread_.join();
}

std::optional<Snapshot> EngineRunner::next() {
  return next(std::chrono::milliseconds::max());
}

std::optional<Snapshot> EngineRunner::next(std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  const auto ready = [&] { return !queue_.empty() || done_ || state_ == State::idle; };
  if (timeout == std::chrono::milliseconds::max())
    changed_.wait(lock, ready);
  else
    changed_.wait_for(lock, timeout, ready);
  if (queue_.empty()) return std::nullopt;
  Snapshot s = std::move(queue_.front());
  queue_.pop_front();
  changed_.notify_all();
  return s;
}

bool EngineRunner::ended() const {
  std::lock_guard lock(mutex_);
  return done_ && queue_.empty();
}

void EngineRunner::checkpoint(std::ostream& out) {
  std::lock_guard lock(mutex_);
  if (!(resting_ || done_ || state_ == State::idle))
    throw std::logic_error("checkpoint needs a paused or ended run");
  engine_.save_checkpoint(out);
}

EngineRunner::State EngineRunner::state() const {
  std::lock_guard lock(mutex_);
  return state_;
}

std::string EngineRunner::error() const {
  std::lock_guard lock(mutex_);
  return error_;
}

}  // namespace sedem
