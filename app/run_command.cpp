#include "app/run_command.h"

#include <QCoreApplication>
#include <QThread>
#include <QTimer>

#include <cstdio>
#include <filesystem>
#include <iostream>

#include "app/engine_worker.h"
#include "app/exit_codes.h"
#include "app/output_observers.h"
#include "app/progress.h"
#include "app/run_record.h"
#include "app/stop_signals.h"
#include "app/test_outputs.h"
#include "core/sample/sample_builder.h"
#include "core/scene/scene_loader.h"

namespace sedem::app {
namespace fs = std::filesystem;

namespace {

std::vector<double> schedule_of(const std::vector<std::unique_ptr<Observer>>& observers,
                                double end_time) {
  std::vector<std::vector<double>> lists{{end_time}};
  for (const auto& o : observers) lists.push_back(o->wanted_times());
  std::vector<double> merged = merge_times(lists);
  std::erase_if(merged, [&](double t) { return t > end_time * (1 + 1e-12); });
  return merged;
}

}  // namespace

int run(const RunOptions& options) {
  auto& qt = *QCoreApplication::instance();
  qRegisterMetaType<std::shared_ptr<const Snapshot>>();

  Scene scene;
  Sample sample;
  try {
    scene = load_scene(options.scene, options.overrides);
    sample = build_sample(scene);
  } catch (const SceneError& e) {
    std::cerr << "sedem: invalid scene: " << e.what() << '\n';
    return exit_code::invalid_scene;
  }

  const fs::path out = options.out_dir;
  RunRecord record;
  record.scene_file = options.scene;
  record.seed = scene.sample.seed;
  record.particle_count = sample.particles.size();
  try {
    fs::create_directories(out);
    write_run_record(record, scene, out / "run.json");
  } catch (const std::exception& e) {
    std::cerr << "sedem: cannot write to the output folder " << out << ": " << e.what() << '\n';
    return exit_code::output_unwritable;
  }

  if (!options.quiet)
    std::printf("sedem: %s: %zu particles in %zu sizes, %.0f s to simulate, output in %s\n",
                scene.name.c_str(), sample.particles.size(), sample.classes.size(), scene.end_time,
                out.c_str());

  RunObservers run_observers;
  try {
    run_observers = make_observers(scene, sample, out);
  } catch (const std::exception& e) {
    std::cerr << "sedem: cannot prepare the outputs in " << out << ": " << e.what() << '\n';
    return exit_code::output_unwritable;
  }

  auto& observers = run_observers.all;
  Engine engine(scene, std::move(sample));
  EngineWorker worker(engine, schedule_of(observers, scene.end_time));
  QThread thread;
  worker.moveToThread(&thread);
  Progress progress(scene.end_time, options.quiet);
  int status = exit_code::ok;

  QObject::connect(&thread, &QThread::started, &worker, &EngineWorker::start);
  QObject::connect(
      &worker, &EngineWorker::snapshotReady, &qt,
      [&](std::shared_ptr<const Snapshot> snap) {
        try {
          dispatch(observers, *snap);
        } catch (const std::exception& e) {
          record.message = std::string("writing the outputs failed: ") + e.what();
          status = exit_code::io_failure;
          worker.stop();
          qt.exit(status);
        }
        worker.release();
      },
      Qt::QueuedConnection);
  QObject::connect(&worker, &EngineWorker::progress, &qt,
                   [&](double t, double steps) { progress.update(t, steps); });
  QObject::connect(&worker, &EngineWorker::failed, &qt, [&](const QString& message) {
    record.message = "the engine failed: " + message.toStdString();
    status = exit_code::engine_failure;
    qt.exit(status);
  });
  QObject::connect(&worker, &EngineWorker::finished, &qt, [&](bool completed) {
    if (status == exit_code::ok && !completed) status = exit_code::interrupted;
    qt.exit(status);
  });
  QTimer stop_poll;
  QObject::connect(&stop_poll, &QTimer::timeout, &qt, [&] {
    if (stop_requested()) worker.stop();
  });
  install_stop_handlers();
  stop_poll.start(100);
  thread.start();
  qt.exec();
  worker.stop();
  thread.quit();
  thread.wait();
  progress.done();

  try {
    for (auto& o : observers) o->finish();
    if (run_observers.instruments) record.results = write_test_outputs(scene, run_observers, out);
  } catch (const std::exception& e) {
    record.message = std::string("writing the test results failed: ") + e.what();
    if (status == exit_code::ok || status == exit_code::interrupted) status = exit_code::io_failure;
  }
  record.status = status == exit_code::ok            ? "complete"
                  : status == exit_code::interrupted ? "interrupted"
                                                     : "failed";
  record.steps = engine.stats().steps;
  record.simulated_time = engine.time();
  record.wall_time = progress.wall_seconds();
  record.particle_steps = engine.stats().particle_steps;
  try {
    write_run_record(record, scene, out / "run.json");
  } catch (const std::exception& e) {
    std::cerr << "sedem: " << e.what() << '\n';
    if (status == exit_code::ok) status = exit_code::io_failure;
  }
  if (status == exit_code::interrupted)
    std::cerr << "sedem: stopped at t = " << engine.time() << " s; what was computed is in " << out
              << '\n';
  else if (status != exit_code::ok)
    std::cerr << "sedem: " << record.message << '\n';
  else if (!options.quiet)
    std::printf("sedem: done in %.1f s; wrote %s\n", record.wall_time, out.c_str());
  return status;
}

}  // namespace sedem::app
