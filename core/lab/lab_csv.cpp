#include "core/lab/lab_csv.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

#include "core/model/shortened.h"

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

// One line, ended by LF, CRLF or a lone CR (as old Mac spreadsheets write): false at the end
// of the input. A line longer than kMaxLabLineBytes is refused rather than read on.
bool next_line(std::istream& in, std::string& line, std::size_t number) {
  line.clear();
  std::streambuf* buffer = in.rdbuf();
  if (!buffer) return false;
  using traits = std::char_traits<char>;
  for (;;) {
    const auto c = buffer->sbumpc();
    if (traits::eq_int_type(c, traits::eof())) {
      in.setstate(std::ios::eofbit);
      return !line.empty();
    }
    if (c == '\n') return true;
    if (c == '\r') {
      if (traits::eq_int_type(buffer->sgetc(), '\n')) buffer->sbumpc();
      return true;
    }
    if (line.size() >= kMaxLabLineBytes)
      throw LabCsvError(number, "",
                        "a line longer than " + std::to_string(kMaxLabLineBytes) +
                            " characters: not a readings file");
    line += traits::to_char_type(c);
  }
}

}  // namespace

LabCsvError::LabCsvError(std::size_t line, const std::string& column, const std::string& why)
    : std::invalid_argument("line " + std::to_string(line) +
                            (column.empty() ? "" : ", column " + column) + ": " + why),
      line_(line) {}

std::vector<std::vector<double>> read_numeric_csv(std::istream& in,
                                                  const std::vector<std::string>& required,
                                                  const std::vector<std::string>& optional,
                                                  std::vector<std::size_t>* lines) {
  if (lines) lines->clear();
  std::vector<std::string> names = required;
  names.insert(names.end(), optional.begin(), optional.end());
  std::string line;
  std::size_t number = 0;
  std::vector<std::string> header;
  while (header.empty() && next_line(in, line, number + 1)) {
    ++number;
    // A spreadsheet's "CSV UTF-8" starts with a byte order mark.
    if (number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    // A comment above the header ("# partial: ..." in the outputs of a partial run).
    if (line.rfind('#', 0) == 0) continue;
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
  while (next_line(in, line, number + 1)) {
    ++number;
    if (blank(line)) continue;
    if (rows.size() == kMaxLabRows)
      throw LabCsvError(number, "",
                        "more than " + std::to_string(kMaxLabRows) +
                            " readings; a laboratory test has a few dozen: is this the right "
                            "file?");
    const auto cells = split(line);
    std::vector<double> v(names.size(), std::numeric_limits<double>::quiet_NaN());
    for (std::size_t k = 0; k < names.size(); ++k) {
      if (!column[k]) continue;
      if (*column[k] >= cells.size()) throw LabCsvError(number, names[k], "missing value");
      const std::string& text = cells[*column[k]];
      const char* end = text.data() + text.size();
      auto [ptr, ec] = std::from_chars(text.data(), end, v[k]);
      if (ec != std::errc() || ptr != end || text.empty())
        throw LabCsvError(number, names[k], "'" + shortened(text) + "' is not a number");
      // "nan" or "inf" parse, but are no reading: refused here rather than taken for a
      // missing value (an absent optional column) or carried into the results.
      if (!std::isfinite(v[k]))
        throw LabCsvError(number, names[k], "'" + shortened(text) + "' is not a finite number");
    }
    rows.push_back(std::move(v));
    if (lines) lines->push_back(number);
  }
  if (rows.empty())
    throw LabCsvError(number, "", "no readings: the file holds a header and no data row");
  return rows;
}

void check_lab_time_min(std::size_t line, double time_min) {
  if (!(time_min > 0 && time_min <= kMaxLabTimeMin)) {
    std::ostringstream why;
    why << time_min << " is out of range; allowed (0, " << kMaxLabTimeMin
        << "] min (a test's readings end within days)";
    throw LabCsvError(line, "time_min", why.str());
  }
}

std::vector<LabReading> read_lab_readings_csv(std::istream& in) {
  std::vector<LabReading> readings;
  std::vector<std::size_t> lines;
  const auto rows =
      read_numeric_csv(in, {"time_min", "reading_g_per_l", "temperature_c"},
                       {"composite_correction_g_per_l", "meniscus_correction_g_per_l"}, &lines);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& v = rows[i];
    check_lab_time_min(lines[i], v[0]);
    // NaN here only for an optional column the header lacks: no correction.
    readings.push_back({v[0] * 60.0, v[1], v[2], std::isnan(v[3]) ? 0.0 : v[3],
                        std::isnan(v[4]) ? 0.0 : v[4], lines[i]});
  }
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
