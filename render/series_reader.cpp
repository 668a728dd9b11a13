#include "render/series_reader.h"

#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>

namespace sedem::render {

std::vector<std::pair<double, std::string>> read_pvd(const std::filesystem::path& pvd) {
  std::ifstream in(pvd);
  if (!in) throw std::runtime_error("cannot read " + pvd.string());
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  std::vector<std::pair<double, std::string>> entries;
  const std::regex dataset(R"re(<DataSet\s+timestep="([^"]+)"[^>]*\sfile="([^"]+)"\s*/>)re");
  for (auto it = std::sregex_iterator(s.begin(), s.end(), dataset); it != std::sregex_iterator();
       ++it)
    entries.emplace_back(std::stod((*it)[1].str()), (*it)[2].str());
  return entries;
}

Snapshot read_particles_vtp(const std::filesystem::path& file) {
  if (!std::filesystem::exists(file)) throw std::runtime_error("no such file: " + file.string());
  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkPolyData* poly = reader->GetOutput();
  auto* pd = poly->GetPointData();
  auto array = [&](const char* name) {
    vtkDataArray* a = pd->GetArray(name);
    if (!a) throw std::runtime_error(file.string() + ": no point array '" + name + "'");
    return a;
  };
  vtkDataArray* diameter = array("diameter");
  vtkDataArray* velocity = array("velocity");
  vtkDataArray* weight = array("weight");
  vtkDataArray* size_class = array("size_class");
  vtkDataArray* id = array("id");
  vtkDataArray* time = poly->GetFieldData()->GetArray("TimeValue");
  if (!time) throw std::runtime_error(file.string() + ": no field data 'TimeValue'");

  Snapshot s;
  s.time = time->GetTuple1(0);
  const auto n = std::size_t(poly->GetNumberOfPoints());
  auto& p = s.particles;
  p.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto k = vtkIdType(i);
    double xyz[3];
    poly->GetPoint(k, xyz);
    p.x[i] = xyz[0];
    p.y[i] = xyz[1];
    p.vx[i] = velocity->GetComponent(k, 0);
    p.vy[i] = velocity->GetComponent(k, 1);
    p.diameter[i] = diameter->GetTuple1(k);
    p.weight[i] = weight->GetTuple1(k);
    p.size_class[i] = std::int32_t(size_class->GetTuple1(k));
    p.id[i] = std::uint32_t(id->GetTuple1(k));
  }
  return s;
}

}  // namespace sedem::render
