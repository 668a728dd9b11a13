#include "app/run_command.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>

#include "app/checkpoint_file.h"
#include "app/exit_codes.h"
#include "app/output_observers.h"
#include "app/progress.h"
#include "app/run_folder.h"
#include "app/run_preflight.h"
#include "app/run_record.h"
#include "app/run_report.h"
#include "app/stop_signals.h"
#include "app/test_outputs.h"
#include "core/instruments/plausibility.h"
#include "core/run/simulation.h"
#include "core/run/stage_setups.h"
#include "core/sample/sample_builder.h"
#include "core/scene/scene_loader.h"
#include "render/series_reader.h"

namespace sedem::app {
namespace fs = std::filesystem;

namespace {

const char* kCheckpoint = kCheckpointFile;

struct Failure {
  int status;
  std::string message;
};

// A resumed run: its scene as the interrupted run resolved it. `from_start` is set when the
// run was stopped before its first checkpoint (none is there): it starts again from the
// beginning, in its own folder.
Scene scene_of_run(const fs::path& dir, std::string& scene_file, bool& from_start) {
  std::ifstream in(dir / "run.json");
  if (!in)
    throw Failure{exit_code::invalid_scene, (dir / "run.json").string() + ": cannot read it"};
  const auto record = nlohmann::json::parse(in, nullptr, false);
  if (record.is_discarded() || !record.contains("scene"))
    throw Failure{exit_code::invalid_scene,
                  (dir / "run.json").string() + ": not a sedem run record"};
  if (record.value("status", "") == "complete")
    throw Failure{exit_code::ok, dir.string() + " holds a complete run: nothing to resume"};
  // Neither half of a checkpoint: killed before its first one (a lone half is damage, refused
  // when it is read).
  from_start = !fs::exists(dir / kCheckpoint) && !fs::exists(dir / kCheckpointRecordFile);
  if (!from_start && !fs::exists(dir / kCheckpoint))
    throw Failure{exit_code::invalid_scene, dir.string() + ": no " + kCheckpoint +
                                                " to resume from (a run leaves one when stopped "
                                                "by Ctrl-C or SIGTERM, and every "
                                                "run.checkpoint_interval_s while it runs)"};
  if (record.contains("scene_file") && record["scene_file"].is_string())
    scene_file = record["scene_file"].get<std::string>();
  if (!record["scene"].is_object())
    throw Failure{exit_code::invalid_scene,
                  (dir / "run.json").string() + ": not a sedem run record (no scene)"};
  try {
    return scene_from_json(record["scene"], (dir / "run.json").string());
  } catch (const SceneError& e) {
    throw Failure{exit_code::invalid_scene, e.what()};
  }
}

// The observers that accumulate see the saved snapshots before the engine's time again, so
// that a resumed run's readings are those of a run that never stopped.
void replay(const Simulation& simulation, const fs::path& dir) {
  const double until = simulation.time();
  if (!simulation.observers().needs_replay(until)) return;
  const std::size_t expected_particles = simulation.sample().particles.size();
  for (const auto& [time, file] : render::read_pvd(dir / "particles.pvd")) {
    if (time >= until) break;
    const Snapshot snap = render::read_particles_vtp(dir / file);
    if (snap.particles.size() != expected_particles)
      throw std::runtime_error((dir / file).string() + ": holds " +
                               std::to_string(snap.particles.size()) + " particles, not " +
                               std::to_string(expected_particles));
    if (snap.time != time)
      throw std::runtime_error((dir / file).string() + ": its time " + std::to_string(snap.time) +
                               " s differs from particles.pvd's " + std::to_string(time) + " s");
    simulation.observers().replay(snap);
  }
}

}  // namespace

namespace {

// What the handler of an allocation failure needs to finish run.json.
struct RunContext {
  Scene scene;
  RunRecord record;
  fs::path out;
  bool record_started = false;
};

// The first failure is the one reported: a later one (often its consequence) does not
// replace it.
void fail(RunRecord& record, int& status, int code, const std::string& message) {
  if (record.message.empty()) record.message = message;
  if (status == exit_code::ok || status == exit_code::interrupted) status = code;
}

std::string engine_message(const std::string& what) {
  if (what.find("bad_alloc") != std::string::npos)
    return "out of memory: the simulation could not allocate what it needs (" + what +
           "); lower sample.simulated_count or raise forces.voidage_cell_mm";
  return "the engine failed: " + what;
}

int run_in(const RunOptions& options, const RunHooks& hooks, RunContext& ctx) {
  // From the first instruction: a stop asked during the set-up ends the run at its start.
  if (!hooks.stop_requested) install_stop_handlers();
  const std::function<bool()> stop =
      hooks.stop_requested ? hooks.stop_requested : std::function<bool()>(stop_requested);
  bool resuming = !options.resume_dir.empty();
  bool overwrite = options.overwrite;
  fs::path out = options.resume_dir;
  Scene& scene = ctx.scene;
  RunRecord& record = ctx.record;

  Sample sample;
  std::string first_scene_file = options.scene;
  try {
    bool from_start = false;
    scene = resuming                 ? scene_of_run(out, first_scene_file, from_start)
            : !options.scene.empty() ? load_scene(options.scene, options.overrides)
                                     : parse_scene(options.scene_text, "scene", options.overrides);
    if (from_start) {
      // Nothing computed was kept: the run starts again, replacing its own outputs only.
      std::cerr << "sedem: " << out.string()
                << " holds no checkpoint (the run was stopped before its first): starting it "
                   "again from the beginning\n";
      resuming = false;
      overwrite = true;
    }
    if (const std::string refusal = memory_refusal(scene); !refusal.empty())
      throw Failure{exit_code::invalid_scene, refusal};
    if (options.resume_dir.empty())
      out = options.out_dir.empty() ? fs::path("out") / safe_folder_name(scene.name)
                                    : fs::path(options.out_dir);
    sample = build_sample(sample_setup(scene));
  } catch (const SceneError& e) {
    std::cerr << "sedem: invalid scene: " << e.what() << '\n';
    return exit_code::invalid_scene;
  } catch (const Failure& f) {
    std::cerr << "sedem: " << f.message << '\n';
    return f.status;
  }

  ctx.out = out;
  std::optional<RunFolder> folder;  // one run per folder, locked until the run ends
  try {
    folder.emplace(out, resuming, overwrite);
  } catch (const RunFolder::Error& e) {
    std::cerr << "sedem: " << e.what() << '\n';
    return exit_code::output_unwritable;
  }

  // A resumed run goes on from a checkpoint that proves it belongs to this run.
  const std::string identity = run_identity(scene);
  CheckpointRecord previous;
  if (resuming) {
    try {
      previous = read_checkpoint_record(out, identity);
    } catch (const std::exception& e) {
      std::cerr << "sedem: cannot resume: " << e.what() << '\n';
      return exit_code::invalid_scene;
    }
    if (!previous.scene_file.empty()) first_scene_file = previous.scene_file;
  }

  // Every place the run writes to, checked before anything is simulated.
  if (const std::string unwritable = check_writable(out, scene); !unwritable.empty()) {
    std::cerr << "sedem: cannot write to the output folder: " << unwritable << '\n';
    return exit_code::output_unwritable;
  }
  record.scene_file = first_scene_file;
  record.seed = scene.sample.seed;
  record.particle_count = sample.particles.size();
  record.legs = resuming ? previous.legs + 1 : 1;
  // Doubts known before anything runs (too few particles in an instrument's volume, coupling,
  // dilution): printed now and kept in run.json with those on the results.
  const TestSetup doubts_setup = test_setup(scene);
  const double doubts_count = double(sample.particles.size());
  record.warnings = nlohmann::json::array();
  for (const auto& d : setup_doubts(doubts_setup, doubts_count)) {
    std::cerr << "sedem: warning: " << d.message << '\n';
    record.warnings.push_back({{"code", d.code}, {"message", d.message}});
  }
  try {
    // A new run into a folder: a checkpoint left there by another run is not this one's.
    if (!resuming) remove_checkpoint(out);
    write_run_record(record, scene, out / "run.json");
  } catch (const std::exception& e) {
    std::cerr << "sedem: cannot write to the output folder " << out << ": " << e.what() << '\n';
    return exit_code::output_unwritable;
  }
  ctx.record_started = true;

  // The engine gets the sample; the observers read it back from the simulation.
  const std::size_t particle_count = sample.particles.size(), size_count = sample.classes.size();
  Simulation simulation(scene, std::move(sample));
  ObserverStart start;
  int status = exit_code::ok;
  auto finish_failed = [&](int code, const std::string& message) {
    fail(record, status, code, message);
    record.status = "failed";
    try {
      write_run_record(record, scene, out / "run.json");
    } catch (const std::exception&) {
      write_failed_record_in_place(record, out / "run.json");
    }
    remove_temporary_files(out);
    std::cerr << "sedem: " << record.message << '\n';
    return status;
  };
  if (resuming) {
    try {
      simulation.resume((out / kCheckpoint).string());
      if (!(simulation.time() == previous.time))
        throw std::runtime_error("its time " + std::to_string(simulation.time()) +
                                 " s differs from the record's " + std::to_string(previous.time) +
                                 " s");
    } catch (const std::exception& e) {
      std::cerr << "sedem: cannot resume from " << out / kCheckpoint << ": " << e.what() << '\n';
      return exit_code::invalid_scene;
    }
    start.resume_from = simulation.time();
  }
  if (!options.quiet)
    std::printf("sedem: %s: %zu particles in %zu sizes, %s %.0f s, output in %s\n",
                scene.name.c_str(), particle_count, size_count,
                resuming ? "resuming at" : "to simulate",
                resuming ? simulation.time() : scene.end_time, out.c_str());

  RunObservers run_observers;
  try {
    run_observers = make_observers(scene, simulation.sample(), out, start);
  } catch (const render::SeriesError& e) {
    std::cerr << "sedem: cannot resume: the saved series is damaged: " << e.what() << '\n';
    return exit_code::invalid_scene;
  } catch (const std::exception& e) {
    return finish_failed(exit_code::output_unwritable,
                         "cannot prepare the outputs in " + out.string() + ": " + e.what());
  }
  for (auto& o : run_observers.all) simulation.watch(*o);
  if (hooks.started) hooks.started(simulation);
  for (Observer* o : hooks.observers) simulation.watch(*o);
  if (resuming) {
    try {
      simulation.restore_observers();
    } catch (const std::exception& e) {
      std::cerr << "sedem: cannot resume: " << e.what() << '\n';
      return exit_code::invalid_scene;
    }
    try {
      replay(simulation, replay_folder(scene, out));
    } catch (const std::exception& e) {
      std::cerr << "sedem: cannot resume: the saved series is damaged: " << e.what() << '\n';
      return exit_code::invalid_scene;
    }
  }

  const auto leg_start = std::chrono::steady_clock::now();
  auto wall_so_far = [&] {
    return previous.wall_time +
           std::chrono::duration<double>(std::chrono::steady_clock::now() - leg_start).count();
  };
  auto checkpoint_record = [&] {
    CheckpointRecord c;
    c.identity = identity;
    c.time = simulation.time();
    c.wall_time = wall_so_far();
    c.legs = record.legs;
    c.scene_file = record.scene_file;
    return c;
  };

  Progress progress(scene.end_time, options.quiet);
  RunControl control;
  // Two snapshots waiting keep the engine busy while files are written; above a quarter of a
  // million particles (16 MB a snapshot) one. From a million none: the engine waits while the
  // files are written from its particles in place (at ten million, the two snapshots a run
  // held were 1.3 GB, a third of it; the engine's share of the time is small beside the files).
  control.capacity = particle_count >= 1000000 ? 0 : (particle_count > 250000 ? 1 : 2);
  control.stop_requested = stop;
  control.poll = std::chrono::milliseconds(100);
  control.progress = [&](double t, double steps) {
    progress.update(t, steps);
    if (hooks.progress) hooks.progress(t, steps);
  };
  // Periodic checkpoints, while the engine rests between two steps.
  control.checkpoint_every = scene.checkpoint_interval;
  control.checkpoint = [&](const auto& write_engine) {
    write_checkpoint(out, write_engine, checkpoint_record());
  };
  control.warning = [](const std::string& message) {
    std::cerr << "sedem: warning: " << message << '\n';
  };
  try {
    const RunEnd end = simulation.run(control);
    if (!end.engine_error.empty())
      fail(record, status, exit_code::engine_failure, engine_message(end.engine_error));
    else if (!end.completed)
      status = exit_code::interrupted;
  } catch (const std::bad_alloc& e) {
    fail(record, status, exit_code::engine_failure, engine_message(e.what()));
  } catch (const std::exception& e) {
    fail(record, status, exit_code::io_failure,
         std::string("writing the outputs failed: ") + e.what());
  }
  progress.done();

  // The engine thread has ended: the engine rests between two steps.
  if (status == exit_code::interrupted) {
    try {
      write_checkpoint(
          out, [&](const std::string& path) { simulation.save_checkpoint(path); },
          checkpoint_record());
    } catch (const std::exception& e) {
      fail(record, status, exit_code::io_failure,
           std::string("the checkpoint could not be written: ") + e.what());
    }
  }
  // A complete run's checkpoint (and, without the particle series, its replay/) goes only once
  // run.json says it is complete: a run killed while it writes its outputs still resumes. (Taken
  // here, before the outputs, a kill in between left neither a checkpoint nor a complete run.)
  const std::string replay = replay_folder(scene, out).lexically_relative(out).generic_string();
  auto listed = [&] {
    std::vector<std::string> files = run_files(out);
    if (status != exit_code::ok) return files;
    std::erase_if(files, [&](const std::string& f) {
      return f == kCheckpointFile || f == kCheckpointRecordFile ||
             (!scene.output.particles && f.rfind(replay + "/", 0) == 0);
    });
    return files;
  };
  try {
    simulation.observers().finish();
    record.results = write_test_outputs(scene, run_observers, out);
    if (run_observers.instruments && status != exit_code::interrupted)
      for (const auto& d :
           result_doubts(run_observers.instruments->granulometry(), doubts_setup, doubts_count)) {
        std::cerr << "sedem: warning: " << d.message << '\n';
        record.warnings.push_back({{"code", d.code}, {"message", d.message}});
      }
  } catch (const std::bad_alloc& e) {
    fail(record, status, exit_code::engine_failure, engine_message(e.what()));
  } catch (const std::exception& e) {
    fail(record, status, exit_code::io_failure,
         std::string("writing the test results failed: ") + e.what());
  }
  if (hooks.finished) hooks.finished(simulation, run_observers);
  if (status != exit_code::ok && status != exit_code::interrupted) remove_temporary_files(out);
  record.status = status == exit_code::ok            ? "complete"
                  : status == exit_code::interrupted ? "interrupted"
                                                     : "failed";
  record.steps = simulation.stats().steps;
  record.simulated_time = simulation.time();
  // Every leg of a resumed run: its wall time and its particle-steps (the engine's counts go
  // on from the checkpoint).
  record.wall_time = wall_so_far();
  record.particle_steps = simulation.stats().particle_steps;
  // The page that shows the run as a whole, from the record as it is written next.
  record.files = listed();
  try {
    write_run_report(run_record_json(record, scene), out);
  } catch (const std::exception& e) {
    fail(record, status, exit_code::io_failure,
         std::string("writing ") + kRunReport + " failed: " + e.what());
    record.status = "failed";
    remove_temporary_files(out);
  }
  record.files = listed();
  try {
    write_run_record(record, scene, out / "run.json");
  } catch (const std::exception& e) {
    fail(record, status, exit_code::io_failure, e.what());
    remove_temporary_files(out);
    // Never left "running": the short record in the place of the long one.
    write_failed_record_in_place(record, out / "run.json");
  }
  if (status == exit_code::ok) {
    remove_checkpoint(out);
    if (!scene.output.particles) {
      std::error_code ignored;  // a leftover replay/ costs disk only
      fs::remove_all(replay_folder(scene, out), ignored);
    }
  }
  if (status == exit_code::ok && !options.quiet)
    if (const auto& r = record.results;
        r.contains("hydrometer") && r["hydrometer"].value("off_scale_readings", 0) > 0)
      std::cerr << "sedem: warning: " << r["hydrometer"]["off_scale_readings"].get<int>()
                << " hydrometer reading(s) lie off the 152H scale (-5 to 60 g/L) or with the "
                   "bulb out of the liquid; see on_scale in readings_hydrometer.csv\n";
  if (status == exit_code::interrupted)
    std::cerr << "sedem: stopped at t = " << simulation.time() << " s; what was computed is in "
              << out.string() << "; go on with: sedem run --resume " << out.string() << '\n';
  else if (status != exit_code::ok)
    std::cerr << "sedem: " << record.message << '\n';
  else if (!options.quiet)
    std::fputs(run_summary(record.results, record.wall_time, out).c_str(), stdout);
  return status;
}

}  // namespace

int run(const RunOptions& options, const RunHooks& hooks) {
  RunContext ctx;
  try {
    return run_in(options, hooks, ctx);
  } catch (const std::bad_alloc& e) {
    // An allocation failure anywhere: a message and a final run.json, never an abort.
    const std::string message = engine_message(e.what());
    std::cerr << "sedem: " << message << '\n';
    if (ctx.record_started) {
      ctx.record.status = "failed";
      if (ctx.record.message.empty()) ctx.record.message = message;
      try {
        write_run_record(ctx.record, ctx.scene, ctx.out / "run.json");
      } catch (const std::exception&) {
        write_failed_record_in_place(ctx.record, ctx.out / "run.json");
      }
      remove_temporary_files(ctx.out);
    }
    return exit_code::engine_failure;
  }
}

}  // namespace sedem::app
