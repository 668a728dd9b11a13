#pragma once

#include <QObject>
#include <QSemaphore>

#include <atomic>
#include <functional>
#include <memory>
#include <string>
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
  // Two snapshots waiting on each side keep the engine busy while files are written; above a
  // quarter of a million particles (16 MB a snapshot) one each: a million-particle run then
  // holds at most three snapshots instead of five (64 bytes a particle each).
  static int capacity_for(std::size_t particles) { return particles > 250000 ? 1 : 2; }

  EngineWorker(Engine& engine, std::vector<double> schedule, int capacity = 2);

  void stop() { stop_.store(true); }
  // The main thread takes no more snapshots (it is leaving): stop and hand nothing over.
  void abort() {
    abort_.store(true);
    stop();
  }
  // The main thread calls this when it has finished with a snapshot.
  void release() { slots_.release(); }

  // Every `seconds` of wall time (0: never) the engine pauses once the main thread has
  // finished with every snapshot before it, and `save` is called on this thread with a
  // function that writes the engine's state to a path: a checkpoint a kill cannot undo.
  using Checkpointer = std::function<void(const std::function<void(const std::string&)>&)>;
  void checkpoint_every(double seconds, Checkpointer save) {
    checkpoint_every_ = seconds;
    checkpointer_ = std::move(save);
  }

 public slots:
  void start();

 signals:
  void snapshotReady(std::shared_ptr<const sedem::Snapshot> snapshot);
  void progress(double simulated_time, double particle_steps);
  void failed(QString message);
  // Something went wrong that does not stop the run (a periodic checkpoint not written).
  void warning(QString message);
  // `completed` is false when the run was stopped before its last scheduled time.
  void finished(bool completed);

 private:
  EngineRunner runner_;
  QSemaphore slots_;
  std::atomic<bool> stop_{false}, abort_{false};
  bool hand_over(Snapshot snapshot);
  bool checkpoint_now();
  int capacity_;
  double checkpoint_every_ = 0;
  Checkpointer checkpointer_;
};

}  // namespace sedem::app
