#include "app/run_command.h"

#include <QCoreApplication>
#include <QThread>
#include <QTimer>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>

#include "app/engine_worker.h"
#include "app/exit_codes.h"
#include "app/output_observers.h"
#include "app/progress.h"
#include "app/run_folder.h"
#include "app/run_record.h"
#include "app/stop_signals.h"
#include "app/test_outputs.h"
#include "core/sample/sample_builder.h"
#include "core/scene/scene_loader.h"
#include "render/series_reader.h"

namespace sedem::app {
namespace fs = std::filesystem;

namespace {

const char* kCheckpoint = "checkpoint.bin";

struct Failure {
  int status;
  std::string message;
};

// Every time an observer wants, from `from` (a resumed run's start) to the end.
std::vector<double> schedule_of(const std::vector<std::unique_ptr<Observer>>& observers,
                                double end_time, double from) {
  std::vector<std::vector<double>> lists{{end_time}};
  for (const auto& o : observers) lists.push_back(o->wanted_times());
  std::vector<double> merged = merge_times(lists);
  std::erase_if(merged, [&](double t) { return t > end_time * (1 + 1e-12) || t < from; });
  return merged;
}

// A resumed run: its scene as the interrupted run resolved it.
Scene scene_of_run(const fs::path& dir) {
  std::ifstream in(dir / "run.json");
  if (!in)
    throw Failure{exit_code::invalid_scene, (dir / "run.json").string() + ": cannot read it"};
  const auto record = nlohmann::json::parse(in, nullptr, false);
  if (record.is_discarded() || !record.contains("scene"))
    throw Failure{exit_code::invalid_scene,
                  (dir / "run.json").string() + ": not a sedem run record"};
  if (record.value("status", "") == "complete")
    throw Failure{exit_code::ok, dir.string() + " holds a complete run: nothing to resume"};
  if (!fs::exists(dir / kCheckpoint))
    throw Failure{exit_code::invalid_scene, dir.string() + ": no " + kCheckpoint +
                                                " to resume from (only a run stopped by "
                                                "Ctrl-C or SIGTERM leaves one)"};
  try {
    return scene_from_json(record["scene"], (dir / "run.json").string());
  } catch (const SceneError& e) {
    throw Failure{exit_code::invalid_scene, e.what()};
  }
}

// The observers that accumulate see the saved snapshots before `until` again, so that a
// resumed run's readings are those of a run that never stopped.
void replay(const RunObservers& observers, const fs::path& dir, double until) {
  bool any = false;
  for (const auto& o : observers.all) any = any || o->accumulates();
  if (!any) return;
  for (const auto& [time, file] : render::read_pvd(dir / "particles.pvd")) {
    if (time >= until) break;
    const Snapshot snap = render::read_particles_vtp(dir / file);
    for (const auto& o : observers.all)
      if (o->accumulates() && contains_time(o->wanted_times(), snap.time)) o->observe(snap);
  }
}

}  // namespace

int run(const RunOptions& options) {
  auto& qt = *QCoreApplication::instance();
  qRegisterMetaType<std::shared_ptr<const Snapshot>>();
  const bool resuming = !options.resume_dir.empty();
  fs::path out = options.resume_dir;

  Scene scene;
  Sample sample;
  try {
    scene = resuming ? scene_of_run(out) : load_scene(options.scene, options.overrides);
    sample = build_sample(scene);
    if (!resuming)
      out = options.out_dir.empty() ? fs::path("out") / safe_folder_name(scene.name)
                                    : fs::path(options.out_dir);
  } catch (const SceneError& e) {
    std::cerr << "sedem: invalid scene: " << e.what() << '\n';
    return exit_code::invalid_scene;
  } catch (const Failure& f) {
    std::cerr << "sedem: " << f.message << '\n';
    return f.status;
  }

  RunRecord record;
  record.scene_file = resuming ? (out / "run.json").string() : options.scene;
  record.seed = scene.sample.seed;
  record.particle_count = sample.particles.size();
  std::optional<RunFolder> folder;  // locked until the run ends
  try {
    folder.emplace(out, resuming, options.overwrite);
    write_run_record(record, scene, out / "run.json");
  } catch (const RunFolder::Error& e) {
    std::cerr << "sedem: " << e.what() << '\n';
    return exit_code::output_unwritable;
  } catch (const std::exception& e) {
    std::cerr << "sedem: cannot write to the output folder " << out << ": " << e.what() << '\n';
    return exit_code::output_unwritable;
  }

  Engine engine(scene, sample);  // a copy: the observers need the sample too
  ObserverStart start;
  if (resuming) {
    try {
      engine.load_checkpoint((out / kCheckpoint).string());
    } catch (const std::exception& e) {
      std::cerr << "sedem: cannot resume from " << out / kCheckpoint << ": " << e.what() << '\n';
      return exit_code::invalid_scene;
    }
    start.resume_from = engine.time();
  }
  if (!options.quiet)
    std::printf("sedem: %s: %zu particles in %zu sizes, %s %.0f s, output in %s\n",
                scene.name.c_str(), sample.particles.size(), sample.classes.size(),
                resuming ? "resuming at" : "to simulate", resuming ? engine.time() : scene.end_time,
                out.c_str());

  RunObservers run_observers;
  try {
    run_observers = make_observers(scene, sample, out, start);
    if (resuming) replay(run_observers, out, engine.time());
  } catch (const std::exception& e) {
    std::cerr << "sedem: cannot prepare the outputs in " << out << ": " << e.what() << '\n';
    return exit_code::output_unwritable;
  }

  auto& observers = run_observers.all;
  EngineWorker worker(engine, schedule_of(observers, scene.end_time, engine.time()));
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
  worker.abort();
  thread.quit();
  thread.wait();
  progress.done();

  // The engine thread has ended: the engine rests between two steps.
  if (status == exit_code::interrupted) {
    try {
      engine.save_checkpoint((out / kCheckpoint).string());
    } catch (const std::exception& e) {
      record.message = std::string("the checkpoint could not be written: ") + e.what();
    }
  } else if (status == exit_code::ok) {
    fs::remove(out / kCheckpoint);
  }
  try {
    for (auto& o : observers) o->finish();
    record.results = write_test_outputs(scene, run_observers, out);
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
  record.files = run_files(out);
  try {
    write_run_record(record, scene, out / "run.json");
  } catch (const std::exception& e) {
    std::cerr << "sedem: " << e.what() << '\n';
    if (status == exit_code::ok) status = exit_code::io_failure;
  }
  if (status == exit_code::interrupted)
    std::cerr << "sedem: stopped at t = " << engine.time() << " s; what was computed is in "
              << out.string() << "; go on with: sedem run --resume " << out.string() << '\n';
  else if (status != exit_code::ok)
    std::cerr << "sedem: " << record.message << '\n';
  else if (!options.quiet)
    std::fputs(run_summary(record.results, record.wall_time, out).c_str(), stdout);
  return status;
}

}  // namespace sedem::app
