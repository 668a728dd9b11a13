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

PvdSeries::PvdSeries(std::filesystem::path pvd_file) : pvd_(std::move(pvd_file)) {}

void PvdSeries::add(double time, const std::string& data_file) {
  entries_.emplace_back(time, data_file);
  write();
}

void PvdSeries::write() const {
  auto tmp = pvd_;
  tmp += ".tmp";
  {
    std::ofstream out(tmp);
    out.precision(17);
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
           "  <Collection>\n";
    for (const auto& [time, file] : entries_)
      out << "    <DataSet timestep=\"" << time << "\" group=\"\" part=\"0\" file=\"" << file
          << "\"/>\n";
    out << "  </Collection>\n</VTKFile>\n";
    if (!out) throw std::runtime_error("cannot write " + tmp.string());
  }
  std::filesystem::rename(tmp, pvd_);
}

namespace {

vtkSmartPointer<vtkDoubleArray> double_array(const char* name, int components, vtkIdType n) {
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(n);
  return a;
}

}  // namespace

void write_particles_vtp(const Snapshot& snapshot, double particle_density,
                         const std::filesystem::path& file) {
  const auto& p = snapshot.particles;
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
  set_time_value(poly, snapshot.time);
  write_vtk_xml(poly, file);
}

ParticleSeriesWriter::ParticleSeriesWriter(const std::filesystem::path& out_dir,
                                           double particle_density)
    : dir_(out_dir), particle_density_(particle_density), series_(out_dir / "particles.pvd") {
  std::filesystem::create_directories(dir_ / "particles");
}

void ParticleSeriesWriter::write(const Snapshot& snapshot) {
  char name[64];
  std::snprintf(name, sizeof name, "particles/particles_%06d.vtp", count_++);
  write_particles_vtp(snapshot, particle_density_, dir_ / name);
  series_.add(snapshot.time, name);
}

}  // namespace sedem::render
