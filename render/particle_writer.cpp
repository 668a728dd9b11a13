#include "render/particle_writer.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <new>
#include <numbers>
#include <stdexcept>
#include <type_traits>

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSOADataArrayTemplate.h>
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

// The arrays the particles hold already are wrapped, not copied (VTK only reads them to write
// the file): at ten million particles a copy of every array was a gigabyte at each write.
vtkSmartPointer<vtkPolyData> particles_polydata(double time, const Particles& p,
                                                double particle_density) {
  const auto n = vtkIdType(p.size());
  auto wrap = [n](auto array, const auto& values) {
    using T = std::decay_t<decltype(values[0])>;
    array->SetArray(const_cast<T*>(values.data()), n, 1);  // 1: not VTK's to free
    return array;
  };
  // Points and velocities: the particles' own x and y, and the plane's zeros as the third
  // component (calloc'd and VTK's to free: untouched zero pages take no memory).
  auto three = [&](const char* name, const std::vector<double>& a, const std::vector<double>& b) {
    auto v = vtkSmartPointer<vtkSOADataArrayTemplate<double>>::New();
    v->SetName(name);
    v->SetNumberOfComponents(3);
    v->SetArray(0, const_cast<double*>(a.data()), n, true, true);
    v->SetArray(1, const_cast<double*>(b.data()), n, true, true);
    auto* zeros = static_cast<double*>(std::calloc(std::size_t(std::max<vtkIdType>(n, 1)), 8));
    if (!zeros) throw std::bad_alloc();
    v->SetArray(2, zeros, n, true, false, vtkAbstractArray::VTK_DATA_ARRAY_FREE);
    return v;
  };
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetData(three("Points", p.x, p.y));
  auto diameter = wrap(vtkSmartPointer<vtkDoubleArray>::New(), p.diameter);
  diameter->SetName("diameter");
  auto radius = double_array("radius", 1, n);
  auto velocity = three("velocity", p.vx, p.vy);
  auto mass = double_array("mass", 1, n);
  auto weight = wrap(vtkSmartPointer<vtkDoubleArray>::New(), p.weight);
  weight->SetName("weight");
  auto size_class = wrap(vtkSmartPointer<vtkIntArray>::New(), p.size_class);
  size_class->SetName("size_class");
  auto id = wrap(vtkSmartPointer<vtkTypeUInt32Array>::New(), p.id);
  id->SetName("id");
  auto verts = vtkSmartPointer<vtkCellArray>::New();
  verts->Use32BitStorage();
  verts->AllocateExact(n, n);
  for (vtkIdType i = 0; i < n; ++i) {
    const double d = p.diameter[std::size_t(i)];
    radius->SetValue(i, 0.5 * d);
    mass->SetValue(i, particle_density * std::numbers::pi / 6.0 * d * d * d);
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
