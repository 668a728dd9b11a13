#include "app/render_command.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "app/exit_codes.h"
#include "app/output_observers.h"
#include "app/run_record.h"
#include "app/test_outputs.h"
#include "core/sample/sample_builder.h"
#include "core/scene/scene_loader.h"
#include "render/series_reader.h"

namespace sedem::app {
namespace fs = std::filesystem;

namespace {

struct RenderFailure : std::runtime_error {
  RenderFailure(const std::string& what, int status) : std::runtime_error(what), status(status) {}
  int status;
};

LabelledResults render_one(const fs::path& dir, bool quiet) {
  std::ifstream in(dir / "run.json");
  if (!in)
    throw RenderFailure(dir.string() + ": no run.json (is this a sedem run folder?)",
                        exit_code::invalid_scene);
  Scene scene;
  try {
    scene = scene_from_json(nlohmann::json::parse(in).at("scene"), (dir / "run.json").string());
  } catch (const nlohmann::json::exception& e) {
    throw RenderFailure((dir / "run.json").string() + ": " + e.what(), exit_code::invalid_scene);
  } catch (const SceneError& e) {
    throw RenderFailure(e.what(), exit_code::invalid_scene);
  }
  const Sample sample = build_sample(scene);
  RunObservers observers = make_observers(scene, sample, dir, {.write_particles = false});
  const auto entries = render::read_pvd(dir / "particles.pvd");
  if (entries.empty())
    throw RenderFailure((dir / "particles.pvd").string() + ": no particle files to render from",
                        exit_code::invalid_scene);
  for (const auto& [time, file] : entries)
    dispatch(observers.all, render::read_particles_vtp(dir / file));
  for (auto& o : observers.all) o->finish();
  write_test_outputs(scene, observers, dir);
  if (!quiet) std::printf("sedem: redrew %s from %zu snapshots\n", dir.c_str(), entries.size());
  return labelled_results(scene, observers);
}

}  // namespace

int render_runs(const RenderOptions& options) {
  std::vector<LabelledResults> runs;
  for (const auto& dir : options.run_dirs) {
    try {
      runs.push_back(render_one(dir, options.quiet));
    } catch (const RenderFailure& e) {
      std::fprintf(stderr, "sedem: %s\n", e.what());
      return e.status;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "sedem: rendering %s failed: %s\n", dir.c_str(), e.what());
      return exit_code::io_failure;
    }
  }
  if (runs.size() > 1) {
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
