#include "core/lab/lab_csv.h"

#include <charconv>
#include <cmath>
#include <sstream>

namespace sedem {

std::vector<std::vector<double>> read_numeric_csv(std::istream& in,
                                                  const std::vector<std::string>& required,
                                                  const std::vector<std::string>& optional,
                                                  std::vector<std::size_t>* lines) {
  return lab_columns(read_lab_text(in), required, optional, lines);
}

void check_lab_time_min(std::size_t line, double time_min, const std::string& place) {
  if (!(time_min > 0 && time_min <= kMaxLabTimeMin)) {
    std::ostringstream why;
    why << time_min << " is out of range; allowed (0, " << kMaxLabTimeMin
        << "] min (a test's readings end within days)";
    throw LabCsvError(line, "time_min", why.str(), place);
  }
}

std::vector<LabReading> read_lab_readings(const LabTable& table) {
  std::vector<LabReading> readings;
  std::vector<std::size_t> lines;
  const auto rows =
      lab_columns(table, {"time_min", "reading_g_per_l", "temperature_c"},
                  {"composite_correction_g_per_l", "meniscus_correction_g_per_l"}, &lines);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& v = rows[i];
    check_lab_time_min(lines[i], v[0], table.place);
    // NaN here only for an optional column the header lacks: no correction.
    readings.push_back({v[0] * 60.0, v[1], v[2], std::isnan(v[3]) ? 0.0 : v[3],
                        std::isnan(v[4]) ? 0.0 : v[4], lines[i], table.place});
  }
  return readings;
}

std::vector<LabReading> read_lab_readings_csv(std::istream& in) {
  return read_lab_readings(read_lab_text(in));
}

void write_lab_points_csv(std::ostream& out, const std::vector<LabPoint>& points) {
  // The shortest text that reads back as the same double.
  auto num = [](double v) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
    return std::string(buffer, result.ptr);
  };
  out << "time_s,diameter_m,percent_finer,corrected_reading_g_per_l,effective_depth_m,"
         "viscosity_pa_s,time_min,diameter_mm,diameter_um\n";
  for (const auto& p : points)
    out << num(p.time) << ',' << num(p.diameter) << ',' << num(p.percent_finer) << ','
        << num(p.corrected_reading) << ',' << num(p.effective_depth) << ',' << num(p.viscosity)
        << ',' << num(p.time / 60.0) << ',' << num(p.diameter * 1e3) << ',' << num(p.diameter * 1e6)
        << '\n';
}

}  // namespace sedem
