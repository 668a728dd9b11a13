#include "render/particle_writer.h"

#include <cstdio>
#include <fstream>
#include <numbers>
#include <stdexcept>

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTypeUInt32Array.h>

#include "render/vtk_xml.h"

namespace sedem::render {

namespace {

vtkSmartPointer<vtkDoubleArray> double_array(const char* name, int components, vtkIdType n) {
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(n);
  return a;
}

}  // namespace

vtkSmartPointer<vtkPolyData> particles_polydata(double time, const Particles& p,
                                                double particle_density) {
  const auto n = vtkIdType(p.size());
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  auto diameter = double_array("diameter", 1, n);
  auto radius = double_array("radius", 1, n);
  auto velocity = double_array("velocity", 3, n);
  auto mass = double_array("mass", 1, n);
  auto weight = double_array("weight", 1, n);
  auto size_class = vtkSmartPointer<vtkIntArray>::New();
  size_class->SetName("size_class");
  size_class->SetNumberOfTuples(n);
  auto id = vtkSmartPointer<vtkTypeUInt32Array>::New();
  id->SetName("id");
  id->SetNumberOfTuples(n);
  auto verts = vtkSmartPointer<vtkCellArray>::New();
  verts->AllocateExact(n, n);
  for (vtkIdType i = 0; i < n; ++i) {
    const double d = p.diameter[std::size_t(i)];
    points->SetPoint(i, p.x[std::size_t(i)], p.y[std::size_t(i)], 0.0);
    diameter->SetValue(i, d);
    radius->SetValue(i, 0.5 * d);
    velocity->SetTuple3(i, p.vx[std::size_t(i)], p.vy[std::size_t(i)], 0.0);
    mass->SetValue(i, particle_density * std::numbers::pi / 6.0 * d * d * d);
    weight->SetValue(i, p.weight[std::size_t(i)]);
    size_class->SetValue(i, p.size_class[std::size_t(i)]);
    id->SetValue(i, p.id[std::size_t(i)]);
    verts->InsertNextCell(1, &i);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetVerts(verts);
  auto* pd = poly->GetPointData();
  pd->AddArray(diameter);
  pd->AddArray(radius);
  pd->SetVectors(velocity);
  pd->AddArray(mass);
  pd->AddArray(weight);
  pd->AddArray(size_class);
  pd->AddArray(id);
  pd->SetActiveScalars("diameter");
  set_time_value(poly, time);
  return poly;
}

void write_particles_vtp(const Snapshot& snapshot, double particle_density,
                         const std::filesystem::path& file) {
  write_vtk_xml(particles_polydata(snapshot.time, snapshot.particles, particle_density), file);
}

ParticleSeriesWriter::ParticleSeriesWriter(const std::filesystem::path& out_dir,
                                           double particle_density, double keep_until)
    : particle_density_(particle_density), series_(out_dir, "particles", "vtp", keep_until) {}

void ParticleSeriesWriter::write(double time, const Particles& particles) {
  series_.write(particles_polydata(time, particles, particle_density_), time);
}

}  // namespace sedem::render
