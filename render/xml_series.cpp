#include "render/xml_series.h"

#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "render/series_reader.h"
#include "render/vtk_xml.h"

namespace sedem::render {

PvdSeries::PvdSeries(std::filesystem::path pvd_file, double keep_until)
    : pvd_(std::move(pvd_file)) {
  if (keep_until > -std::numeric_limits<double>::infinity() && std::filesystem::exists(pvd_))
    for (const auto& entry : read_pvd(pvd_))
      if (entry.first <= keep_until) entries_.push_back(entry);
}

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

XmlSeriesWriter::XmlSeriesWriter(const std::filesystem::path& out_dir, std::string name,
                                 std::string extension, double keep_until)
    : dir_(out_dir),
      name_(std::move(name)),
      extension_(std::move(extension)),
      series_(out_dir / (name_ + ".pvd"), keep_until) {
  std::filesystem::create_directories(dir_ / name_);
}

std::filesystem::path XmlSeriesWriter::write(vtkDataObject* data, double time) {
  char number[16];
  std::snprintf(number, sizeof number, "%06zu", series_.size());
  const std::string relative = name_ + "/" + name_ + "_" + number + "." + extension_;
  set_time_value(data, time);
  write_vtk_xml(data, dir_ / relative);
  series_.add(time, relative);
  return dir_ / relative;
}

}  // namespace sedem::render
