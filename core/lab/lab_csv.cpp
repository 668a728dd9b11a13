#include "core/lab/lab_csv.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

namespace sedem {

namespace {

std::string trimmed(const std::string& cell) {
  const auto first = cell.find_first_not_of(" \t\r");
  const auto last = cell.find_last_not_of(" \t\r");
  return first == std::string::npos ? "" : cell.substr(first, last - first + 1);
}

// One CSV line into cells: a cell may be quoted ("time_min", as spreadsheets write headers),
// with "" for a quote inside; spaces around a cell are dropped.
std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  bool quoted = false, was_quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cell += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        cell += c;
      }
    } else if (c == '"' && trimmed(cell).empty()) {
      quoted = was_quoted = true;
      cell.clear();
    } else if (c == ',') {
      cells.push_back(was_quoted ? cell : trimmed(cell));
      cell.clear();
      was_quoted = false;
    } else if (!(was_quoted && (c == ' ' || c == '\t' || c == '\r'))) {
      cell += c;
    }
  }
  cells.push_back(was_quoted ? cell : trimmed(cell));
  return cells;
}

bool blank(const std::string& line) {
  return line.find_first_not_of(" \t\r") == std::string::npos;
}

}  // namespace

LabCsvError::LabCsvError(std::size_t line, const std::string& column, const std::string& why)
    : std::invalid_argument("line " + std::to_string(line) +
                            (column.empty() ? "" : ", column " + column) + ": " + why),
      line_(line) {}

std::vector<std::vector<double>> read_numeric_csv(std::istream& in,
                                                  const std::vector<std::string>& required,
                                                  const std::vector<std::string>& optional) {
  std::vector<std::string> names = required;
  names.insert(names.end(), optional.begin(), optional.end());
  std::string line;
  std::size_t number = 0;
  std::vector<std::string> header;
  while (header.empty() && std::getline(in, line)) {
    ++number;
    // A spreadsheet's "CSV UTF-8" starts with a byte order mark.
    if (number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    if (!blank(line)) header = split(line);
  }
  if (header.empty()) throw LabCsvError(number, "", "no header");
  std::vector<std::optional<std::size_t>> column(names.size());
  for (std::size_t k = 0; k < names.size(); ++k) {
    auto it = std::find(header.begin(), header.end(), names[k]);
    if (it != header.end())
      column[k] = std::size_t(it - header.begin());
    else if (k < required.size())
      throw LabCsvError(number, names[k], "missing from the header");
  }
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    ++number;
    if (blank(line)) continue;
    const auto cells = split(line);
    std::vector<double> v(names.size(), std::numeric_limits<double>::quiet_NaN());
    for (std::size_t k = 0; k < names.size(); ++k) {
      if (!column[k]) continue;
      if (*column[k] >= cells.size()) throw LabCsvError(number, names[k], "missing value");
      const std::string& text = cells[*column[k]];
      const char* end = text.data() + text.size();
      auto [ptr, ec] = std::from_chars(text.data(), end, v[k]);
      if (ec != std::errc() || ptr != end || text.empty())
        throw LabCsvError(number, names[k], "'" + text + "' is not a number");
    }
    rows.push_back(std::move(v));
  }
  return rows;
}

std::vector<LabReading> read_lab_readings_csv(std::istream& in) {
  std::vector<LabReading> readings;
  for (const auto& v : read_numeric_csv(in, {"time_min", "reading_g_per_l", "temperature_c"},
                                        {"composite_correction_g_per_l"}))
    readings.push_back({v[0] * 60.0, v[1], v[2], std::isnan(v[3]) ? 0.0 : v[3]});
  return readings;
}

void write_lab_points_csv(std::ostream& out, const std::vector<LabPoint>& points) {
  // The shortest text that reads back as the same double.
  auto num = [](double v) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
    return std::string(buffer, result.ptr);
  };
  out << "time_s,diameter_m,percent_finer,corrected_reading_g_per_l,effective_depth_m,"
         "viscosity_pa_s\n";
  for (const auto& p : points)
    out << num(p.time) << ',' << num(p.diameter) << ',' << num(p.percent_finer) << ','
        << num(p.corrected_reading) << ',' << num(p.effective_depth) << ',' << num(p.viscosity)
        << '\n';
}

}  // namespace sedem
