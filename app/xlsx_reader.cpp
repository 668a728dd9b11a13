#include "app/xlsx_reader.h"

#include <zip.h>

#include <QByteArray>
#include <QString>
#include <QXmlStreamReader>
#include <algorithm>
#include <map>
#include <memory>
#include <stdexcept>

namespace sedem::app {

namespace {

// A part unpacked larger than this is no laboratory's sheet (or a zip bomb).
constexpr zip_uint64_t kMaxPartBytes = 64u << 20;
// Cells right of this column are ignored: a readings sheet is a few columns wide.
constexpr int kMaxColumns = 256;

struct Archive {
  zip_t* zip = nullptr;
  ~Archive() {
    if (zip) zip_discard(zip);
  }
};

std::unique_ptr<Archive> open_archive(const std::filesystem::path& file) {
  int error = 0;
  auto archive = std::make_unique<Archive>();
  archive->zip = zip_open(file.c_str(), ZIP_RDONLY, &error);
  if (!archive->zip) {
    zip_error_t e;
    zip_error_init_with_code(&e, error);
    const std::string why = zip_error_strerror(&e);
    zip_error_fini(&e);
    throw std::invalid_argument("not an .xlsx workbook (" + why + ")");
  }
  return archive;
}

// The part `name` unpacked; empty with `found` false when the archive has none.
QByteArray read_part(const Archive& archive, const std::string& name, bool* found = nullptr) {
  zip_stat_t stat;
  zip_stat_init(&stat);
  if (zip_stat(archive.zip, name.c_str(), 0, &stat) != 0) {
    if (found) {
      *found = false;
      return {};
    }
    throw std::invalid_argument("not an .xlsx workbook: it has no " + name);
  }
  if (found) *found = true;
  if (!(stat.valid & ZIP_STAT_SIZE) || stat.size > kMaxPartBytes)
    throw std::invalid_argument(name + " unpacks to more than 64 MB: not a readings workbook");
  zip_file_t* f = zip_fopen(archive.zip, name.c_str(), 0);
  if (!f) throw std::invalid_argument("cannot unpack " + name + " of the workbook");
  QByteArray data(static_cast<qsizetype>(stat.size), '\0');
  const zip_int64_t n = zip_fread(f, data.data(), stat.size);
  zip_fclose(f);
  if (n < 0 || static_cast<zip_uint64_t>(n) != stat.size)
    throw std::invalid_argument("cannot unpack " + name + " of the workbook (damaged)");
  return data;
}

void check(const QXmlStreamReader& xml, const std::string& part) {
  if (xml.hasError())
    throw std::invalid_argument("the workbook's " + part +
                                " is not well-formed XML: " + xml.errorString().toStdString());
}

std::string attribute(const QXmlStreamReader& xml, const char* name) {
  for (const auto& a : xml.attributes())
    if (a.name() == QLatin1String(name)) return a.value().toString().toStdString();
  return "";
}

// The text of the current element's <t> descendants (a rich string's runs joined), not of
// its phonetic guides (<rPh>); the reader ends on the element's end.
std::string string_item(QXmlStreamReader& xml) {
  std::string text;
  int phonetic = 0;
  const QString end = xml.name().toString();
  while (!xml.atEnd()) {
    xml.readNext();
    if (xml.isStartElement() && xml.name() == QLatin1String("rPh")) ++phonetic;
    if (xml.isEndElement() && xml.name() == QLatin1String("rPh")) --phonetic;
    if (xml.isStartElement() && xml.name() == QLatin1String("t") && phonetic == 0)
      text += xml.readElementText(QXmlStreamReader::IncludeChildElements).toStdString();
    if (xml.isEndElement() && xml.name() == end) break;
  }
  return text;
}

std::vector<std::string> shared_strings(const Archive& archive) {
  bool found = false;
  const QByteArray data = read_part(archive, "xl/sharedStrings.xml", &found);
  std::vector<std::string> strings;
  if (!found) return strings;
  QXmlStreamReader xml(data);
  while (!xml.atEnd()) {
    xml.readNext();
    if (xml.isStartElement() && xml.name() == QLatin1String("si"))
      strings.push_back(string_item(xml));
  }
  check(xml, "xl/sharedStrings.xml");
  return strings;
}

struct SheetEntry {
  std::string name, target;
};

std::vector<SheetEntry> sheets(const Archive& archive) {
  std::map<std::string, std::string> targets;  // relationship id -> part
  {
    QXmlStreamReader xml(read_part(archive, "xl/_rels/workbook.xml.rels"));
    while (!xml.atEnd()) {
      xml.readNext();
      if (xml.isStartElement() && xml.name() == QLatin1String("Relationship")) {
        std::string target = attribute(xml, "Target");
        // Relative to xl/, or absolute from the package's root.
        target = target.rfind('/', 0) == 0 ? target.substr(1) : "xl/" + target;
        targets[attribute(xml, "Id")] = target;
      }
    }
    check(xml, "xl/_rels/workbook.xml.rels");
  }
  std::vector<SheetEntry> out;
  QXmlStreamReader xml(read_part(archive, "xl/workbook.xml"));
  while (!xml.atEnd()) {
    xml.readNext();
    if (xml.isStartElement() && xml.name() == QLatin1String("sheet")) {
      const auto it = targets.find(attribute(xml, "id"));  // r:id
      out.push_back({attribute(xml, "name"), it == targets.end() ? "" : it->second});
    }
  }
  check(xml, "xl/workbook.xml");
  return out;
}

// "B12" -> column 1 (0-based); -1 when it names none.
int column_of(const std::string& reference) {
  int column = 0;
  std::size_t i = 0;
  for (; i < reference.size() && reference[i] >= 'A' && reference[i] <= 'Z'; ++i)
    // Past the columns read it no longer matters how far: no overflow on "ZZZZZZZZZZ1".
    column = std::min(column * 26 + (reference[i] - 'A' + 1), kMaxColumns + 1);
  return i == 0 ? -1 : column - 1;
}

// A row's number from its r attribute; `next` when it has none or names none.
std::size_t row_of(const std::string& r, std::size_t next) {
  std::size_t n = 0;
  if (r.empty() || r.size() > 9 || r.find_first_not_of("0123456789") != std::string::npos)
    return next;
  for (char c : r) n = n * 10 + std::size_t(c - '0');
  return n == 0 ? next : n;
}

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  const auto last = s.find_last_not_of(" \t\r\n");
  return first == std::string::npos ? "" : s.substr(first, last - first + 1);
}

// One <c> element's text; the reader ends on its end.
std::string cell_text(QXmlStreamReader& xml, const std::string& type,
                      const std::vector<std::string>& strings) {
  std::string value;
  bool inline_text = false;
  while (!xml.atEnd()) {
    xml.readNext();
    if (xml.isEndElement() && xml.name() == QLatin1String("c")) break;
    if (!xml.isStartElement()) continue;
    if (xml.name() == QLatin1String("v")) {
      value = xml.readElementText().toStdString();
    } else if (xml.name() == QLatin1String("is")) {
      value = string_item(xml);
      inline_text = true;
    }
  }
  if (type == "s" && !inline_text) {
    std::size_t index = strings.size();
    if (!value.empty() && value.size() <= 9 &&
        value.find_first_not_of("0123456789") == std::string::npos)
      index = std::stoul(value);
    if (index >= strings.size())
      throw std::invalid_argument("a cell names shared string '" + value +
                                  "', which the workbook does not have (damaged)");
    return strings[index];
  }
  if (type == "b") return value == "1" ? "TRUE" : "FALSE";
  return value;  // a number as stored, a formula's string, an inline string, an error (#N/A)
}

}  // namespace

std::vector<std::string> xlsx_sheet_names(const std::filesystem::path& file) {
  const auto archive = open_archive(file);
  std::vector<std::string> names;
  for (const auto& s : sheets(*archive)) names.push_back(s.name);
  return names;
}

LabTable read_xlsx_table(const std::filesystem::path& file, const std::string& sheet) {
  const auto archive = open_archive(file);
  const auto entries = sheets(*archive);
  if (entries.empty()) throw std::invalid_argument("the workbook has no sheet");
  const SheetEntry* chosen = sheet.empty() ? &entries.front() : nullptr;
  for (const auto& e : entries)
    if (!chosen && e.name == sheet) chosen = &e;
  if (!chosen) {
    std::string there;
    for (const auto& e : entries) there += (there.empty() ? "'" : ", '") + e.name + "'";
    throw std::invalid_argument("the workbook has no sheet '" + sheet + "'; it has " + there);
  }
  if (chosen->target.empty())
    throw std::invalid_argument("the workbook's sheet '" + chosen->name +
                                "' has no part (damaged)");
  const auto strings = shared_strings(*archive);
  LabTable table;
  // A spreadsheet's user looks for a sheet and a row, not a line.
  table.place = "sheet '" + chosen->name + "', row";
  table.decimal_comma = true;
  QXmlStreamReader xml(read_part(*archive, chosen->target));
  std::size_t row_number = 0;
  std::vector<std::string> cells;
  auto end_row = [&]() {
    while (!cells.empty() && cells.back().empty()) cells.pop_back();
    if (cells.empty()) return;
    if (table.header.empty()) {
      // A comment above the header, as in a text file.
      if (cells.front().rfind('#', 0) == 0) return;
      table.header = cells;
      table.header_line = row_number;
      return;
    }
    if (table.rows.size() == kMaxLabRows)
      throw LabCsvError(row_number, "",
                        "more than " + std::to_string(kMaxLabRows) +
                            " readings; a laboratory test has a few dozen: is this the right "
                            "sheet?",
                        table.place);
    table.rows.push_back(cells);
    table.lines.push_back(row_number);
  };
  while (!xml.atEnd()) {
    xml.readNext();
    if (xml.isStartElement() && xml.name() == QLatin1String("row")) {
      row_number = row_of(attribute(xml, "r"), row_number + 1);
      cells.clear();
    } else if (xml.isEndElement() && xml.name() == QLatin1String("row")) {
      end_row();
    } else if (xml.isStartElement() && xml.name() == QLatin1String("c")) {
      int column = column_of(attribute(xml, "r"));
      if (column < 0) column = int(cells.size());
      const std::string type = attribute(xml, "t");
      const std::string text = trimmed(cell_text(xml, type, strings));
      if (column >= kMaxColumns) continue;
      if (cells.size() <= std::size_t(column)) cells.resize(column + 1);
      cells[column] = text;
    }
  }
  check(xml, chosen->target);
  if (table.header.empty())
    throw LabCsvError(row_number, "", "no header: the sheet is empty", table.place);
  return table;
}

}  // namespace sedem::app
