#include "app/engine_worker.h"

#include <QThread>

#include <chrono>

namespace sedem::app {

EngineWorker::EngineWorker(Engine& engine, std::vector<double> schedule, int capacity)
    : runner_(engine, std::move(schedule), std::size_t(capacity)),
      slots_(capacity),
      capacity_(capacity) {}

// Waits for room on the main thread, which makes room until it aborts.
bool EngineWorker::hand_over(Snapshot snapshot) {
  while (!slots_.tryAcquire(1, 100))
    if (abort_.load()) return false;
  emit snapshotReady(std::make_shared<const Snapshot>(std::move(snapshot)));
  return true;
}

// Pauses the engine, hands every snapshot it made over and waits until the main thread has
// finished with them (their files are written), then saves: a resumed run replays those
// files and goes on from the saved state. False if the main thread aborted meanwhile.
bool EngineWorker::checkpoint_now() {
  using namespace std::chrono_literals;
  runner_.pause();
  bool ok = true;
  while (auto snapshot = runner_.next(0ms))
    if (!(ok = hand_over(std::move(*snapshot)))) break;
  while (ok && slots_.available() < capacity_) {
    if (abort_.load()) ok = false;
    QThread::msleep(5);
  }
  if (ok && !stop_.load()) {
    runner_.pause();  // the engine rests between two steps
    try {
      checkpointer_([&](const std::string& path) { runner_.checkpoint(path); });
    } catch (const std::exception& e) {
      emit warning(
          QString::fromStdString(std::string("the periodic checkpoint failed: ") + e.what()));
    }
  }
  runner_.resume();
  return ok;
}

void EngineWorker::start() {
  using namespace std::chrono_literals;
  runner_.start();
  auto report = [&] {
    const auto p = runner_.progress();
    emit progress(p.time, p.particle_steps);
  };
  using clock = std::chrono::steady_clock;
  auto last_checkpoint = clock::now();
  const auto every = std::chrono::duration<double>(checkpoint_every_);
  while (!runner_.ended()) {
    if (stop_.load()) break;
    if (checkpointer_ && checkpoint_every_ > 0 && clock::now() - last_checkpoint >= every) {
      if (!checkpoint_now()) break;
      last_checkpoint = clock::now();
    }
    auto snapshot = runner_.next(checkpointer_ && checkpoint_every_ > 0 && checkpoint_every_ < 0.2
                                     ? std::chrono::milliseconds(20)
                                     : 200ms);
    report();
    if (!snapshot) continue;
    if (!hand_over(std::move(*snapshot))) break;
  }
  runner_.stop();  // joins the engine's thread: the engine rests between two steps
  // Snapshots computed before the stop are results: hand them over too.
  while (auto snapshot = runner_.next(0ms))
    if (!hand_over(std::move(*snapshot))) break;
  report();
  switch (runner_.state()) {
    case EngineRunner::State::failed:
      emit failed(QString::fromStdString(runner_.error()));
      break;
    case EngineRunner::State::finished:
      emit finished(!stop_.load());
      break;
    default:
      emit finished(false);
  }
}

}  // namespace sedem::app
