#include "app/engine_worker.h"

#include <chrono>

namespace sedem::app {

EngineWorker::EngineWorker(Engine& engine, std::vector<double> schedule, int capacity)
    : runner_(engine, std::move(schedule), std::size_t(capacity)), slots_(capacity) {}

// Waits for room on the main thread, which makes room until it aborts.
bool EngineWorker::hand_over(Snapshot snapshot) {
  while (!slots_.tryAcquire(1, 100))
    if (abort_.load()) return false;
  emit snapshotReady(std::make_shared<const Snapshot>(std::move(snapshot)));
  return true;
}

void EngineWorker::start() {
  using namespace std::chrono_literals;
  runner_.start();
  auto report = [&] {
    const auto p = runner_.progress();
    emit progress(p.time, p.particle_steps);
  };
  while (!runner_.ended()) {
    if (stop_.load()) break;
    auto snapshot = runner_.next(200ms);
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
