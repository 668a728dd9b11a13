#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "core/model/snapshot.h"
#include "render/xml_series.h"

namespace sedem::render {

// Writes a snapshot as VTK XML PolyData (appended raw binary, zlib-compressed): one vertex per
// particle, point data diameter, radius (m), velocity (3 components, m/s, the active vectors), mass
// (kg), weight, size_class, id; field data TimeValue. z = 0: the section's plane.
vtkSmartPointer<vtkPolyData> particles_polydata(double time, const Particles& particles,
                                                double particle_density);
void write_particles_vtp(const Snapshot& snapshot, double particle_density,
                         const std::filesystem::path& file);

// Writes particles/particles_NNNNNN.vtp under `out_dir` and adds it to particles.pvd.
class ParticleSeriesWriter {
 public:
  ParticleSeriesWriter(const std::filesystem::path& out_dir, double particle_density,
                       double keep_until = -std::numeric_limits<double>::infinity());
  // The particles where they are: a run of ten million holds no copy of them.
  void write(double time, const Particles& particles);

 private:
  double particle_density_;
  XmlSeriesWriter series_;
};

}  // namespace sedem::render
