#pragma once

#include <cstddef>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/lab/hydrometer_reduction.h"
#include "core/lab/lab_columns.h"
#include "core/lab/lab_table.h"

namespace sedem {

// Reads a CSV (or ';'- or tab-separated text, read_lab_text) of numbers with a header naming
// the columns (any order, extra columns ignored; lines starting with '#' above it are
// comments): per data row, the values of `required` then `optional` in that order, NaN for an
// optional column the header lacks; the columns found under the laboratory's names and units
// too (lab_columns). Every value must be a finite number; at least one data row and at most
// kMaxLabRows. Throws LabCsvError naming the line and the column. `lines`, if given, receives
// each row's line number.
std::vector<std::vector<double>> read_numeric_csv(std::istream& in,
                                                  const std::vector<std::string>& required,
                                                  const std::vector<std::string>& optional = {},
                                                  std::vector<std::size_t>* lines = nullptr);

// A reading time in minutes, from the file's `line`: in (0, kMaxLabTimeMin]. Throws
// LabCsvError naming the line and time_min.
void check_lab_time_min(std::size_t line, double time_min, const std::string& place = "line");

// Reads hydrometer readings in the laboratory's units, one per line, with a header naming
// the columns (any order): time_min, reading_g_per_l, temperature_c and, optionally,
// composite_correction_g_per_l and meniscus_correction_g_per_l (0 if the column is absent; a
// cell that is no finite number is refused, never taken as 0). Times checked by check_lab_time_min.
// Returns them in SI (time in s), each with its line. The columns may be named as the
// laboratory names them, in its units (lab_columns: "time (min)", "R (g/L)", "T (°C)").
std::vector<LabReading> read_lab_readings_csv(std::istream& in);
// The same from a table already read (a text file or a workbook's sheet).
std::vector<LabReading> read_lab_readings(const LabTable& table);

// time_s, diameter_m, percent_finer, corrected_reading_g_per_l, effective_depth_m,
// viscosity_pa_s, and the same in the units laboratories use: time_min, diameter_mm,
// diameter_um.
void write_lab_points_csv(std::ostream& out, const std::vector<LabPoint>& points);

}  // namespace sedem
