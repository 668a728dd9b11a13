#pragma once

#include <QObject>
#include <QSemaphore>

#include <atomic>
#include <memory>
#include <vector>

#include "core/engine/engine.h"
#include "core/engine/runner.h"

Q_DECLARE_METATYPE(std::shared_ptr<const sedem::Snapshot>)

namespace sedem::app {

// The Qt side of the engine's thread (core's EngineRunner): on a QThread of its own it takes
// the runner's snapshots and hands them to the main thread by queued signals, with progress
// in between. At most `capacity` snapshots wait in the runner and `capacity` more on the main
// thread, so a slow observer slows the engine instead of filling memory; the engine never
// waits on anything else. stop() ends the run at the next step.
class EngineWorker : public QObject {
  Q_OBJECT
 public:
  EngineWorker(Engine& engine, std::vector<double> schedule, int capacity = 2);

  void stop() { stop_.store(true); }
  // The main thread takes no more snapshots (it is leaving): stop and hand nothing over.
  void abort() {
    abort_.store(true);
    stop();
  }
  // The main thread calls this when it has finished with a snapshot.
  void release() { slots_.release(); }

 public slots:
  void start();

 signals:
  void snapshotReady(std::shared_ptr<const sedem::Snapshot> snapshot);
  void progress(double simulated_time, double particle_steps);
  void failed(QString message);
  // `completed` is false when the run was stopped before its last scheduled time.
  void finished(bool completed);

 private:
  EngineRunner runner_;
  QSemaphore slots_;
  std::atomic<bool> stop_{false}, abort_{false};
  bool hand_over(Snapshot snapshot);
};

}  // namespace sedem::app
