#include "app/engine_worker.h"

#include <algorithm>
#include <chrono>
#include <exception>

namespace sedem::app {

EngineWorker::EngineWorker(Engine& engine, std::vector<double> schedule, int capacity)
    : engine_(engine), schedule_(std::move(schedule)), slots_(capacity) {}

void EngineWorker::start() {
  using clock = std::chrono::steady_clock;
  try {
    auto last_report = clock::now();
    for (double target : schedule_) {
      if (target < engine_.time()) continue;  // a resumed run starts past these
      // The engine chooses its steps; only the output times cut them, so a run stopped and
      // resumed between two outputs takes the very same steps as one that never stopped.
      while (engine_.time() < target) {
        if (stop_.load()) {
          emit finished(false);
          return;
        }
        engine_.step(target);
        if (clock::now() - last_report > std::chrono::milliseconds(500)) {
          emit progress(engine_.time(), engine_.stats().particle_steps);
          last_report = clock::now();
        }
      }
      // Wait for room in the queue, but keep listening for stop().
      while (!slots_.tryAcquire(1, 100))
        if (stop_.load()) {
          emit finished(false);
          return;
        }
      emit snapshotReady(std::make_shared<const Snapshot>(engine_.snapshot()));
      emit progress(engine_.time(), engine_.stats().particle_steps);
    }
    emit finished(true);
  } catch (const std::exception& e) {
    emit failed(QString::fromStdString(e.what()));
  }
}

}  // namespace sedem::app
