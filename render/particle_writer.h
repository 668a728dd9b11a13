#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/engine/engine.h"

namespace sedem::render {

// A ParaView time series: a .pvd collection listing one data file per time. The .pvd is
// rewritten (to a temporary file, then renamed) after every entry, so a run that stops at
// any moment leaves a valid series of what it wrote.
class PvdSeries {
 public:
  explicit PvdSeries(std::filesystem::path pvd_file);
  // Records `data_file` (relative to the .pvd's folder) at `time`.
  void add(double time, const std::string& data_file);
  const std::filesystem::path& path() const { return pvd_; }

 private:
  void write() const;
  std::filesystem::path pvd_;
  std::vector<std::pair<double, std::string>> entries_;
};

// Writes a snapshot as VTK XML PolyData (appended raw binary, zlib-compressed): one vertex per
// particle, point data diameter, radius (m), velocity (3 components, m/s, the active vectors), mass
// (kg), weight, size_class, id; field data TimeValue. z = 0: the section's plane.
void write_particles_vtp(const Snapshot& snapshot, double particle_density,
                         const std::filesystem::path& file);

// Writes particles/particles_NNNNNN.vtp under `out_dir` and adds it to particles.pvd.
class ParticleSeriesWriter {
 public:
  ParticleSeriesWriter(const std::filesystem::path& out_dir, double particle_density);
  void write(const Snapshot& snapshot);

 private:
  std::filesystem::path dir_;
  double particle_density_;
  PvdSeries series_;
  int count_ = 0;
};

}  // namespace sedem::render
