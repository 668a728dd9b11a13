#include "app/output_observers.h"

namespace sedem::app {

ParticleSeriesObserver::ParticleSeriesObserver(const Scene& scene,
                                               const std::filesystem::path& out_dir)
    : times_(every(scene.output.interval, scene.end_time)),
      writer_(out_dir, scene.sample.particle_density) {}

namespace {

render::ColumnAnimation::Options animation_options(const Scene& scene) {
  render::ColumnAnimation::Options o;
  o.label = scene.name;
  o.panel_width = int(scene.output.frame_width);
  o.panel_height = int(scene.output.frame_height);
  return o;
}

}  // namespace

ColumnFrameObserver::ColumnFrameObserver(const Scene& scene, const std::filesystem::path& out_dir)
    : times_(every(scene.output.interval, scene.end_time)),
      animation_(out_dir, scene.cylinder, animation_options(scene)) {}

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
