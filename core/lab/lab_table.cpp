#include "core/lab/lab_table.h"

namespace sedem {

namespace {

std::string trimmed(const std::string& cell) {
  const auto first = cell.find_first_not_of(" \t\r");
  const auto last = cell.find_last_not_of(" \t\r");
  return first == std::string::npos ? "" : cell.substr(first, last - first + 1);
}

// One line into cells at `separator`: a cell may be quoted ("time_min", as spreadsheets write
// headers), with "" for a quote inside; spaces around a cell are dropped (tabs too, unless
// they separate).
std::vector<std::string> split(const std::string& line, char separator) {
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
    } else if (c == separator) {
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

LabCsvError::LabCsvError(std::size_t line, const std::string& column, const std::string& why,
                         const std::string& place)
    : std::invalid_argument(place + " " + std::to_string(line) +
                            (column.empty() ? "" : ", column " + column) + ": " + why),
      line_(line) {}

char detect_separator(const std::string& header_line) {
  bool quoted = false, semicolon = false;
  for (const char c : header_line) {
    if (c == '"') quoted = !quoted;
    if (quoted) continue;
    if (c == '\t') return '\t';
    if (c == ';') semicolon = true;
  }
  return semicolon ? ';' : ',';
}

LabTable read_lab_text(std::istream& in) {
  LabTable table;
  std::string line;
  std::size_t number = 0;
  char separator = ',';
  while (table.header.empty() && next_line(in, line, number + 1)) {
    ++number;
    // A spreadsheet's "CSV UTF-8" starts with a byte order mark.
    if (number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    // A comment above the header ("# partial: ..." in the outputs of a partial run).
    if (line.rfind('#', 0) == 0) continue;
    if (blank(line)) continue;
    separator = detect_separator(line);
    table.header = split(line, separator);
    table.header_line = number;
  }
  if (table.header.empty()) throw LabCsvError(number, "", "no header");
  // With ',' separating cells a decimal comma would split the number in two.
  table.decimal_comma = separator != ',';
  while (next_line(in, line, number + 1)) {
    ++number;
    if (blank(line)) continue;
    if (table.rows.size() == kMaxLabRows)
      throw LabCsvError(number, "",
                        "more than " + std::to_string(kMaxLabRows) +
                            " readings; a laboratory test has a few dozen: is this the right "
                            "file?");
    table.rows.push_back(split(line, separator));
    table.lines.push_back(number);
  }
  return table;
}

}  // namespace sedem
