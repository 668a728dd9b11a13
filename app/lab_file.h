#pragma once

#include <string>

#include "core/lab/lab_table.h"

namespace sedem::app {

// A laboratory's file as a table, whatever form the laboratory keeps it in: an .xlsx
// workbook's sheet (`sheet`, or the first; app/xlsx_reader.h), or text: CSV with ',' or ';'
// and a decimal comma, or tab-separated (core/lab/lab_table.h). A folder, a device or a file
// over 16 MB is refused. Throws std::invalid_argument (LabCsvError for the table's own
// faults) with a message for "sedem: FILE: ...".
LabTable read_lab_file(const std::string& path, const std::string& sheet = "");

// True for a file name ending in .xlsx (any case).
bool is_xlsx(const std::string& path);

}  // namespace sedem::app
