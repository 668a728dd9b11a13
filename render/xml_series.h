#pragma once

#include <filesystem>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <vtkDataObject.h>

namespace sedem::render {

// A ParaView time series: a .pvd collection listing one data file per time. The .pvd is
// rewritten (to a temporary file, then renamed) after every entry, so a run that stops at
// any moment leaves a valid series of what it wrote.
class PvdSeries {
 public:
  // A new series; or, with `keep_until`, the existing one's entries up to that time (a
  // resumed run continues the series it left).
  explicit PvdSeries(std::filesystem::path pvd_file,
                     double keep_until = -std::numeric_limits<double>::infinity());
  // Records `data_file` (relative to the .pvd's folder) at `time`.
  void add(double time, const std::string& data_file);
  const std::filesystem::path& path() const { return pvd_; }
  std::size_t size() const { return entries_.size(); }

 private:
  void write() const;
  std::filesystem::path pvd_;
  std::vector<std::pair<double, std::string>> entries_;
};

// A numbered file series under one folder with its .pvd next to it:
// DIR/<name>.pvd listing DIR/<name>/<name>_NNNNNN.<extension>. Files are VTK XML, appended
// raw binary, zlib-compressed.
class XmlSeriesWriter {
 public:
  XmlSeriesWriter(const std::filesystem::path& out_dir, std::string name, std::string extension,
                  double keep_until = -std::numeric_limits<double>::infinity());
  // Writes `data` (TimeValue is set to `time`) and adds it to the .pvd; returns the file.
  std::filesystem::path write(vtkDataObject* data, double time);
  const std::filesystem::path& pvd() const { return series_.path(); }

 private:
  std::filesystem::path dir_;
  std::string name_, extension_;
  PvdSeries series_;
};

}  // namespace sedem::render
