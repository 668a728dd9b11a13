#include "core/instruments/readings_csv.h"

#include <charconv>
#include <cmath>
#include <string>

namespace sedem {

namespace {

// The shortest text that reads back as the same double.
// A value that is no finite number (a reading that cannot be computed) is left empty: no
// "nan" or "inf" reaches a file.
std::string num(double v) {
  if (!std::isfinite(v)) return {};
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, result.ptr);
}

void write_points(std::ostream& out, const TestReadings& t, const char* source) {
  for (const auto& r : t.rows)
    out << t.test << ',' << source << ',' << num(r.time) << ',' << num(r.diameter) << ','
        << num(r.percent_finer) << '\n';
}

}  // namespace

void write_readings_csv(std::ostream& out, const TestReadings& readings) {
  out << "time_s,diameter_m,percent_finer";
  for (const auto& c : readings.extra_columns) out << ',' << c;
  out << '\n';
  for (const auto& r : readings.rows) {
    out << num(r.time) << ',' << num(r.diameter) << ',' << num(r.percent_finer);
    for (double v : r.extra) out << ',' << num(v);
    out << '\n';
  }
}

void write_granulometry_csv(std::ostream& out, const Granulometry& g) {
  out << "test,source,time_s,diameter_m,percent_finer\n";
  for (const auto& p : g.true_curve)
    out << "true,true,," << num(p.diameter) << ',' << num(p.percent_finer) << '\n';
  for (const auto& t : g.tests) {
    write_points(out, t.dem, "dem");
    write_points(out, t.reference, "reference");
  }
  for (const auto& t : g.tests) {
    out << t.test << ",error_pp,,," << num(t.error) << '\n';
    out << t.test << ",bias_pp,,," << num(t.bias) << '\n';
  }
}

}  // namespace sedem
