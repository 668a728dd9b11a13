#include "app/render_command.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "app/exit_codes.h"
#include "app/output_observers.h"
#include "app/run_folder.h"
#include "app/run_record.h"
#include "app/run_report.h"
#include "app/test_outputs.h"
#include "core/observe/observer_set.h"
#include "core/run/stage_setups.h"
#include "core/sample/sample_builder.h"
#include "core/scene/scene_loader.h"
#include "render/atomic_write.h"
#include "render/series_reader.h"

namespace sedem::app {
namespace fs = std::filesystem;

namespace {

struct RenderFailure : std::runtime_error {
  RenderFailure(const std::string& what, int status) : std::runtime_error(what), status(status) {}
  int status;
};

// What every output of `render --partial` says of a run that did not complete.
const char* kPartialNote =
    "partial: redrawn from a run that did not complete; its readings stop where it did";

// report.html again, from the record and what the folder now holds; run.json lists the files
// anew when they changed (a folder written before the report was), and says when its outputs
// were redrawn as partial.
void update_report(nlohmann::json record, const fs::path& dir, bool partial) {
  const nlohmann::json listed = record.value("files", nlohmann::json());
  record["files"] = run_files(dir);
  write_run_report(record, dir);
  record["files"] = run_files(dir);
  if (partial) {
    record["partial"] = true;
    record["partial_note"] = kPartialNote;
  }
  if (record["files"] == listed && !partial) return;
  write_atomically(dir / "run.json", [&](std::ostream& out) { out << record.dump(2) << '\n'; });
}

// Redraws one run; `scene_json` receives its resolved scene as run.json holds it.
LabelledResults render_one(const fs::path& dir, bool quiet, bool partial,
                           nlohmann::json& scene_json) {
  std::ifstream in(dir / "run.json");
  if (!in)
    throw RenderFailure(dir.string() + ": no run.json (is this a sedem run folder?)",
                        exit_code::invalid_scene);
  Scene scene;
  nlohmann::json record;
  bool incomplete_run_taken = false;
  try {
    record = nlohmann::json::parse(in);
    if (!record.at("scene").is_object())
      throw RenderFailure((dir / "run.json").string() + ": not a sedem run record",
                          exit_code::invalid_scene);
    scene = scene_from_json(record.at("scene"), (dir / "run.json").string());
    scene_json = record.at("scene");
    // A run that did not complete is no whole test: redrawn only when asked, and said so.
    if (const std::string incomplete = incomplete_run(record, dir); !incomplete.empty()) {
      if (!partial) throw RenderFailure(incomplete, exit_code::invalid_scene);
      std::fprintf(stderr, "sedem: warning: partial: %s\n", incomplete.c_str());
      incomplete_run_taken = true;
    }
  } catch (const nlohmann::json::exception& e) {
    throw RenderFailure((dir / "run.json").string() + ": " + e.what(), exit_code::invalid_scene);
  } catch (const SceneError& e) {
    throw RenderFailure(e.what(), exit_code::invalid_scene);
  }
  Sample sample;
  try {
    sample = build_sample(sample_setup(scene));
  } catch (const SceneError& e) {
    throw RenderFailure(e.what(), exit_code::invalid_scene);
  }
  // Every saved file is read and checked before anything is rewritten: a damaged series is
  // refused (exit 2, naming the file), never rendered as far as it goes.
  std::vector<std::pair<double, std::string>> entries;
  auto read = [&](const std::string& file, double time) {
    Snapshot snap = render::read_particles_vtp(dir / file);
    if (snap.particles.size() != sample.particles.size() || snap.time != time)
      throw RenderFailure(
          (dir / file).string() + ": holds " + std::to_string(snap.particles.size()) +
              " particles at t = " + std::to_string(snap.time) +
              " s; particles.pvd and run.json say " + std::to_string(sample.particles.size()) +
              " at t = " + std::to_string(time) + " s",
          exit_code::invalid_scene);
    return snap;
  };
  try {
    entries = render::read_pvd(dir / "particles.pvd");
    if (entries.empty())
      throw RenderFailure((dir / "particles.pvd").string() + ": no particle files to render from",
                          exit_code::invalid_scene);
    for (const auto& [time, file] : entries) read(file, time);
  } catch (const render::SeriesError& e) {
    throw RenderFailure(e.what(), exit_code::invalid_scene);
  }
  RunObservers observers = make_observers(
      scene, sample, dir, {.write_particles = false, .partial = incomplete_run_taken});
  // The run's pipeline with the saved series in the engine's place.
  ObserverSet replayed;
  for (auto& o : observers.all) replayed.add(*o);
  for (const auto& [time, file] : entries) replayed.show(read(file, time));
  replayed.finish();
  write_test_outputs(scene, observers, dir, incomplete_run_taken ? kPartialNote : "");
  update_report(record, dir, incomplete_run_taken);
  if (!quiet) std::printf("sedem: redrew %s from %zu snapshots\n", dir.c_str(), entries.size());
  LabelledResults results = labelled_results(scene, observers);
  if (incomplete_run_taken) results.figures.partial_note = kPartialNote;
  return results;
}

}  // namespace

int render_runs(const RenderOptions& options) {
  std::vector<LabelledResults> runs;
  std::vector<nlohmann::json> scenes;
  for (const auto& dir : options.run_dirs) {
    try {
      runs.push_back(render_one(dir, options.quiet, options.partial, scenes.emplace_back()));
    } catch (const RenderFailure& e) {
      std::fprintf(stderr, "sedem: %s\n", e.what());
      return e.status;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "sedem: rendering %s failed: %s\n", dir.c_str(), e.what());
      return exit_code::io_failure;
    }
  }
  if (runs.size() > 1) {
    // Each panel and legend entry named by what differs between the runs.
    const auto labels = run_labels(scenes);
    for (std::size_t i = 0; i < runs.size(); ++i) runs[i].label = labels[i];
    try {
      write_figures(runs, options.out_dir);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "sedem: writing the figures into %s failed: %s\n",
                   options.out_dir.c_str(), e.what());
      return exit_code::io_failure;
    }
    if (!options.quiet)
      std::printf("sedem: figures of %zu runs side by side in %s\n", runs.size(),
                  options.out_dir.c_str());
  }
  return exit_code::ok;
}

}  // namespace sedem::app
