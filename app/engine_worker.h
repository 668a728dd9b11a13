#pragma once

#include <QObject>
#include <QSemaphore>

#include <atomic>
#include <memory>
#include <vector>

#include "core/engine/engine.h"

Q_DECLARE_METATYPE(std::shared_ptr<const sedem::Snapshot>)

namespace sedem::app {

// Runs the engine on a worker thread. At each scheduled time it hands an immutable snapshot
// to the main thread through a queued signal; at most `capacity` snapshots may wait there,
// so a slow observer slows the engine instead of filling memory, and the engine never waits
// on anything else. stop() is honoured within one slice of simulated time.
class EngineWorker : public QObject {
  Q_OBJECT
 public:
  EngineWorker(Engine& engine, std::vector<double> schedule, int capacity = 4);

  void stop() { stop_.store(true); }
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
  Engine& engine_;
  std::vector<double> schedule_;
  QSemaphore slots_;
  std::atomic<bool> stop_{false};
};

}  // namespace sedem::app
