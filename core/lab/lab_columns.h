#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/lab/lab_table.h"

namespace sedem {

// The columns of a laboratory's table as sedem names them inside (time_min, reading_g_per_l,
// temperature_c, ...), found under the names and units the laboratory wrote: "time (min)",
// "elapsed time, s", "R (g/L)", "T (°C)", "Temperature [C]", "opening (µm)", ... and converted
// to the internal column's unit (s and h to min, µm to mm, mg to g, °F to °C, ...). The
// internal name itself is always accepted. docs/lab.md lists every name and unit.

// The internal columns known by their laboratory names: a column name not listed here is
// matched by its exact name only (the columns of a run's own CSVs: time_s, dry_mass_kg, ...).
// The quantity in words ("the reading time") and what the laboratory may write for it, for
// an error that says what was expected; empty for an unlisted name.
std::string lab_column_expected(const std::string& internal);

// Per data row of `table`, the values of `required` then `optional` (internal names) in the
// internal units, NaN for an optional column the table lacks. Every value must be a finite
// number (a decimal comma where table.decimal_comma); at least one data row. Throws
// LabCsvError naming the line and the column as the file names it: a required column missing
// (with the columns found and what was expected), two columns for one quantity, a column of
// the right name in a unit not known for it, a cell that is no number. `lines`, if given,
// receives each row's line.
std::vector<std::vector<double>> lab_columns(const LabTable& table,
                                             const std::vector<std::string>& required,
                                             const std::vector<std::string>& optional = {},
                                             std::vector<std::size_t>* lines = nullptr);

// The header cell that lab_columns takes for `internal`, if any (throws as it does for two).
std::optional<std::size_t> lab_column_index(const LabTable& table, const std::string& internal);

}  // namespace sedem
