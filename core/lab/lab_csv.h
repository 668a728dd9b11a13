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

// The most data rows a laboratory CSV may hold (a test has a few dozen readings), the
// longest line read, and the latest reading time, min (about two years).
inline constexpr std::size_t kMaxLabRows = 10000;
inline constexpr std::size_t kMaxLabLineBytes = 65536;
inline constexpr double kMaxLabTimeMin = 1e6;

// Reads a CSV of numbers with a header naming the columns (any order, extra columns
// ignored; lines starting with '#' above it are comments): per data row, the values of
// `required` then `optional` in that order, NaN for an optional column the header lacks. Lines end
// in LF, CRLF or a lone CR. Every value must be a finite number; at least one data row and at most
// kMaxLabRows. Throws LabCsvError naming the line and the column. `lines`, if given, receives each
// row's line number.
std::vector<std::vector<double>> read_numeric_csv(std::istream& in,
                                                  const std::vector<std::string>& required,
                                                  const std::vector<std::string>& optional = {},
                                                  std::vector<std::size_t>* lines = nullptr);

// A reading time in minutes, from the file's `line`: in (0, kMaxLabTimeMin]. Throws
// LabCsvError naming the line and time_min.
void check_lab_time_min(std::size_t line, double time_min);

// Reads hydrometer readings in the laboratory's units, one per line, with a header naming
// the columns (any order): time_min, reading_g_per_l, temperature_c and, optionally,
// composite_correction_g_per_l and meniscus_correction_g_per_l (0 if the column is absent; a
// cell that is no finite number is refused, never taken as 0). Times checked by check_lab_time_min.
// Returns them in SI (time in s), each with its line.
std::vector<LabReading> read_lab_readings_csv(std::istream& in);

// time_s, diameter_m, percent_finer, corrected_reading_g_per_l, effective_depth_m,
// viscosity_pa_s.
void write_lab_points_csv(std::ostream& out, const std::vector<LabPoint>& points);

}  // namespace sedem
