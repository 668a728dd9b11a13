#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/lab/lab_table.h"

namespace sedem::app {

// The sheets of an .xlsx workbook, in the workbook's order.
std::vector<std::string> xlsx_sheet_names(const std::filesystem::path& file);

// One sheet of an .xlsx workbook (Office Open XML, as Excel and LibreOffice write it) as a
// laboratory table: the sheet `sheet` by name, or the first when empty. Its first non-empty
// row (a row whose first cell starts with '#' above it is a comment) is the header; empty
// rows are skipped; each row's number is the sheet's, errors name it as "sheet 'NAME', row N"
// (LabTable::place). Cells: shared strings, inline strings, numbers (as stored: full
// precision), formulas' cached results, booleans; an empty cell is "". A text cell may write
// its decimals after a comma.
// Throws std::invalid_argument for a file that is no workbook, a sheet not there (listing
// those there are), a part larger than 64 MB unpacked, more than kMaxLabRows rows.
LabTable read_xlsx_table(const std::filesystem::path& file, const std::string& sheet = "");

}  // namespace sedem::app
