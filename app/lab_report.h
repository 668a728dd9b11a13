#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace sedem::app {

// A table of the lab report: its heading, column heads and rows of cells (plain text,
// escaped on the page; a number's cell is right-aligned).
struct LabReportTable {
  std::string id, heading;
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;
  std::string note;  // a line under the table; empty: none
};

// A reduction's or an inversion's one-page report, in the run report's form (one page that
// opens from its folder with no server: report_page's style, figure_html's figure).
struct LabReport {
  std::string title;     // "sedem reduce: clay.xlsx"
  std::string standard;  // the standard followed: "ASTM D7928", "ASTM D7928 with ASTM D6913"
  std::vector<std::pair<std::string, std::string>> inputs;  // what went in: files, flags
  std::string figure_stem;  // the curve's figure relative to the page, without extension
  std::vector<std::string> figure_formats{"png", "csv"};
  std::vector<LabReportTable> tables;  // the readings and results, the whole curve
  std::vector<std::string> warnings;
  std::vector<std::string> files;  // links to the outputs beside the page
};

std::string lab_report_html(const LabReport& report);

// Writes the page to `file` atomically.
void write_lab_report(const LabReport& report, const std::filesystem::path& file);

// A number for a report's cell: `digits` significant digits; "" for NaN (no value).
std::string report_number(double value, int digits = 4);

}  // namespace sedem::app
