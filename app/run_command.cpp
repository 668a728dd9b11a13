#include "app/run_command.h"

#include <QGuiApplication>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "core/engine/engine.h"
#include "core/sample/sample_builder.h"
#include "core/scene/scene_loader.h"
#include "render/column_view.h"
#include "render/particle_writer.h"

namespace sedem::app {
namespace fs = std::filesystem;

int run(const RunOptions& options, int argc, char** argv) {
  QGuiApplication qt(argc, argv);
  Scene scene;
  try {
    scene = load_scene(options.scene, options.overrides);
  } catch (const SceneError& e) {
    std::cerr << "sedem: invalid scene: " << e.what() << '\n';
    return 2;
  }
  const fs::path out = options.out_dir;
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) {
    std::cerr << "sedem: cannot create the output folder " << out << ": " << ec.message() << '\n';
    return 3;
  }

  const auto wall_start = std::chrono::steady_clock::now();
  Sample sample = build_sample(scene);
  const double rho_p = sample.particle_density;
  const std::size_t count = sample.particles.size();
  if (!options.quiet)
    std::printf("sedem: %s, %zu particles in %zu sizes, %.0f s simulated\n", scene.name.c_str(),
                count, sample.classes.size(), scene.end_time);
  Engine engine(scene, std::move(sample));
  render::ParticleSeriesWriter particles(out, rho_p);
  const int frames = int(std::ceil(scene.end_time / scene.output.interval - 1e-9));
  for (int k = 0; k <= frames; ++k) {
    engine.advance_to(std::min(scene.end_time, k * scene.output.interval));
    const Snapshot snap = engine.snapshot();
    if (scene.output.particles) particles.write(snap);
    if (scene.output.frames) {
      char name[64];
      std::snprintf(name, sizeof name, "frames/column_%06d.png", k);
      render::render_column_png(snap, scene.cylinder, scene.name, int(scene.output.frame_width),
                                int(scene.output.frame_height), out / name);
    }
    if (!options.quiet) std::printf("  t = %8.1f s of %.1f s\n", snap.time, scene.end_time);
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();

  nlohmann::json info;
  info["version"] = SEDEM_VERSION;
  info["scene_file"] = options.scene;
  info["scene"] = resolved_toml(scene);
  info["seed"] = scene.sample.seed;
  info["particle_count"] = count;
  info["steps"] = engine.stats().steps;
  info["wall_time_s"] = wall;
  info["particle_steps_per_s"] = wall > 0 ? engine.stats().particle_steps / wall : 0.0;
  std::ofstream(out / "run.json") << info.dump(2) << '\n';
  if (!options.quiet)
    std::printf("sedem: wrote %s (particles.pvd, frames/*.png, run.json)\n", out.c_str());
  return 0;
}

}  // namespace sedem::app
