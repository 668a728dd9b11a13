#include "app/output_observers.h"

#include <cstdio>

#include "render/column_view.h"

namespace sedem::app {

ParticleSeriesObserver::ParticleSeriesObserver(const Scene& scene,
                                               const std::filesystem::path& out_dir)
    : times_(every(scene.output.interval, scene.end_time)),
      writer_(out_dir, scene.sample.particle_density) {}

ColumnFrameObserver::ColumnFrameObserver(const Scene& scene, const std::filesystem::path& out_dir)
    : scene_(scene),
      dir_(out_dir / "frames"),
      times_(every(scene.output.interval, scene.end_time)) {}

void ColumnFrameObserver::observe(const Snapshot& snapshot) {
  char name[64];
  std::snprintf(name, sizeof name, "column_%06d.png", count_++);
  render::render_column_png(snapshot, scene_.cylinder, scene_.name, int(scene_.output.frame_width),
                            int(scene_.output.frame_height), dir_ / name);
}

std::vector<std::unique_ptr<Observer>> make_observers(const Scene& scene,
                                                      const std::filesystem::path& out_dir) {
  std::vector<std::unique_ptr<Observer>> observers;
  if (scene.output.particles)
    observers.push_back(std::make_unique<ParticleSeriesObserver>(scene, out_dir));
  if (scene.output.frames)
    observers.push_back(std::make_unique<ColumnFrameObserver>(scene, out_dir));
  return observers;
}

}  // namespace sedem::app
