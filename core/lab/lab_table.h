#pragma once

#include <cstddef>
#include <istream>
#include <stdexcept>
#include <string>
#include <vector>

namespace sedem {

// A laboratory file that cannot be read: names the line (1-based, the header is line 1, or a
// sheet's row) and the column.
class LabCsvError : public std::invalid_argument {
 public:
  // `place`: how the message names where, before the number: "line" (a text file) or
  // LabTable::place of a sheet ("sheet 'Readings', row"), so a spreadsheet's user finds it.
  LabCsvError(std::size_t line, const std::string& column, const std::string& why,
              const std::string& place = "line");
  std::size_t line() const { return line_; }

 private:
  std::size_t line_;
};

// The most data rows a laboratory file may hold (a test has a few dozen readings), the
// longest line read, and the latest reading time, min (about two years).
inline constexpr std::size_t kMaxLabRows = 10000;
inline constexpr std::size_t kMaxLabLineBytes = 65536;
inline constexpr double kMaxLabTimeMin = 1e6;

// A laboratory's table as its file holds it, before its columns are known: the header's
// cells and each data row's cells as text. Read from a CSV or tab-separated text here, or
// from a workbook's sheet (app/xlsx_reader.h); core/lab/lab_columns.h takes the columns out.
struct LabTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::vector<std::size_t> lines;  // each row's line in the file (or the sheet's row)
  std::size_t header_line = 0;
  // A cell may write its decimals after a comma ("12,5"): the file is separated by ';' or
  // tabs (as spreadsheets in comma locales write), or is a sheet.
  bool decimal_comma = false;
  // How messages name a row's number: "line" (text), or "sheet 'NAME', row" for a workbook's
  // sheet (a spreadsheet program numbers rows, not lines, and a workbook has several sheets).
  std::string place = "line";
};

// The cell separator of a header line: a tab if it holds one outside quotes, else ';' if it
// holds one, else ','.
char detect_separator(const std::string& header_line);

// Reads a laboratory text file: lines starting with '#' above the header are comments, blank
// lines are skipped; the separator is detect_separator's of the header, the decimal comma is
// allowed with ';' and tabs. A cell may be quoted ("time, min"), with "" for a quote inside.
// Lines end in LF, CRLF or a lone CR; a UTF-8 byte order mark is dropped. At most kMaxLabRows
// data rows and kMaxLabLineBytes a line. Throws LabCsvError for no header or a line too long.
LabTable read_lab_text(std::istream& in);

}  // namespace sedem
