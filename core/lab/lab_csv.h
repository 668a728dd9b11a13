#pragma once

#include <cstddef>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/lab/hydrometer_reduction.h"

namespace sedem {

// A laboratory CSV that cannot be parsed: names the line (1-based, the header is line 1)
// and the column.
class LabCsvError : public std::invalid_argument {
 public:
  LabCsvError(std::size_t line, const std::string& column, const std::string& why);
  std::size_t line() const { return line_; }

 private:
  std::size_t line_;
};

// Reads a CSV of numbers with a header naming the columns (any order, extra columns
// ignored): per data row, the values of `required` then `optional` in that order, NaN for an
// optional column the header lacks. Throws LabCsvError naming the line and the column.
std::vector<std::vector<double>> read_numeric_csv(std::istream& in,
                                                  const std::vector<std::string>& required,
                                                  const std::vector<std::string>& optional = {});

// Reads hydrometer readings in the laboratory's units, one per line, with a header naming
// the columns (any order): time_min, reading_g_per_l, temperature_c and, optionally,
// composite_correction_g_per_l (0 if absent). Returns them in SI (time in s).
std::vector<LabReading> read_lab_readings_csv(std::istream& in);

// time_s, diameter_m, percent_finer, corrected_reading_g_per_l, effective_depth_m,
// viscosity_pa_s.
void write_lab_points_csv(std::ostream& out, const std::vector<LabPoint>& points);

}  // namespace sedem
