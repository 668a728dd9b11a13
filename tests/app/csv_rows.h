#pragma once

// A batch's CSVs (summary.csv, summary_stats.csv, ...) read back by column name, for tests.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace sedem::test {

using Row = std::map<std::string, std::string>;

// A CSV line's cells (no quoted cells: a batch's names hold no comma).
inline std::vector<std::string> split_cells(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream s(line);
  std::string cell;
  while (std::getline(s, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.push_back("");
  return cells;
}

// A CSV whose cells hold no comma, as rows by column name.
inline std::vector<Row> read_rows(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  const auto header = split_cells(line);
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    const auto cells = split_cells(line);
    EXPECT_EQ(cells.size(), header.size()) << line;
    Row row;
    for (std::size_t i = 0; i < header.size() && i < cells.size(); ++i) row[header[i]] = cells[i];
    rows.push_back(row);
  }
  return rows;
}

// A cell as a number; NaN when empty.
inline double cell(const Row& row, const std::string& column) {
  const auto it = row.find(column);
  EXPECT_NE(it, row.end()) << column;
  return it == row.end() || it->second.empty() ? NAN : std::stod(it->second);
}

}  // namespace sedem::test
