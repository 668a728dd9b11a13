#pragma once

#include <filesystem>
#include <memory>
#include <vector>

#include "core/observe/observer.h"
#include "core/scene/scene.h"
#include "render/column_animation.h"
#include "render/particle_writer.h"

namespace sedem::app {

// particles.pvd + particles/*.vtp at every output time.
class ParticleSeriesObserver : public Observer {
 public:
  ParticleSeriesObserver(const Scene& scene, const std::filesystem::path& out_dir);
  std::string name() const override { return "particles"; }
  std::vector<double> wanted_times() const override { return times_; }
  void observe(const Snapshot& snapshot) override { writer_.write(snapshot); }

 private:
  std::vector<double> times_;
  render::ParticleSeriesWriter writer_;
};

// frames/column_NNNNNN.png at every output time: the column as Fig. 11 mass bands with
// zoom insets, on one grey scale for the whole sequence.
class ColumnFrameObserver : public Observer {
 public:
  ColumnFrameObserver(const Scene& scene, const std::filesystem::path& out_dir);
  std::string name() const override { return "frames"; }
  std::vector<double> wanted_times() const override { return times_; }
  void observe(const Snapshot& snapshot) override { animation_.add(snapshot); }

 private:
  std::vector<double> times_;
  render::ColumnAnimation animation_;
};

// The observers the scene asks for: an output that nothing asks for costs nothing.
std::vector<std::unique_ptr<Observer>> make_observers(const Scene& scene,
                                                      const std::filesystem::path& out_dir);

}  // namespace sedem::app
