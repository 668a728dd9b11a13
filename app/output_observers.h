#pragma once

#include <filesystem>
#include <limits>
#include <memory>
#include <vector>

#include "core/observe/instrument_observer.h"
#include "core/observe/observer.h"
#include "core/scene/scene.h"
#include "render/column_animation.h"
#include "render/field_writer.h"
#include "render/particle_writer.h"

namespace sedem::app {

// particles.pvd + particles/*.vtp at every output time and every instrument time, so that
// `sedem render` can take every reading again from the files.
class ParticleSeriesObserver : public Observer {
 public:
  ParticleSeriesObserver(std::vector<double> times, const Scene& scene,
                         const std::filesystem::path& out_dir, double resume_from);
  std::string name() const override { return "particles"; }
  std::vector<double> wanted_times() const override { return times_; }
  void observe(double time, const Particles& p) override { writer_.write(time, p); }

 private:
  std::vector<double> times_;
  render::ParticleSeriesWriter writer_;
};

// frames/column_NNNNNN.png at every output time: the column as Fig. 11 mass bands with
// zoom insets, on one grey scale for the whole sequence.
class ColumnFrameObserver : public Observer {
 public:
  ColumnFrameObserver(const Scene& scene, const std::filesystem::path& out_dir, double resume_from,
                      bool partial = false);
  std::string name() const override { return "frames"; }
  std::vector<double> wanted_times() const override { return times_; }
  void observe(double time, const Particles& p) override { animation_.add(time, p); }

 private:
  std::vector<double> times_;
  render::ColumnAnimation animation_;
};

// fields.pvd + fields/*.vtp at every output time: the layer density and concentration.
class FieldsObserver : public Observer {
 public:
  FieldsObserver(const Scene& scene, const std::filesystem::path& out_dir, double resume_from);
  std::string name() const override { return "fields"; }
  std::vector<double> wanted_times() const override { return times_; }
  void observe(double time, const Particles& particles) override;

 private:
  Scene scene_;
  std::vector<double> times_;
  render::FieldSeriesWriter writer_;
};

// Fig. 11: the column's mass bands and particles at output.fig11_times_min.
class ColumnFigureObserver : public Observer {
 public:
  explicit ColumnFigureObserver(const Scene& scene);
  std::string name() const override { return "fig11"; }
  std::vector<double> wanted_times() const override { return times_; }
  void observe(double time, const Particles& particles) override;
  bool accumulates() const override { return true; }
  const std::vector<render::ColumnState>& states() const { return states_; }

 private:
  double height_;
  std::vector<double> times_;
  std::vector<render::ColumnState> states_;
};

// Where a run keeps the particle snapshots it replays on resume: its particles.pvd series,
// or replay/ when particle files are off (then removed once the run completes).
std::filesystem::path replay_folder(const Scene& scene, const std::filesystem::path& out_dir);

// The observers a scene asks for: an output that nothing asks for costs nothing.
struct RunObservers {
  std::vector<std::unique_ptr<Observer>> all;
  InstrumentObserver* instruments = nullptr;  // in `all`; null when no test is enabled
  ColumnFigureObserver* columns = nullptr;    // in `all`; null when frames are off
};

// How the observers start.
struct ObserverStart {
  // false when the snapshots come from the particle files already (sedem render).
  bool write_particles = true;
  // A resumed run: the series in out_dir keep what they hold before this time and go on.
  double resume_from = -std::numeric_limits<double>::infinity();
  // Redrawn from a run that did not complete (sedem render --partial): each frame says so.
  bool partial = false;
};

RunObservers make_observers(const Scene& scene, const Sample& sample,
                            const std::filesystem::path& out_dir, ObserverStart start = {});

}  // namespace sedem::app
