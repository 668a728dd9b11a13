#include "core/lab/lab_columns.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <optional>

#include "core/model/shortened.h"

namespace sedem {

namespace {

// A unit as normalize_unit spells it, and its conversion to the internal column's unit:
// internal = scale * value + offset.
struct Unit {
  const char* spelled;
  double scale = 1;
  double offset = 0;
};

struct Column {
  const char* internal;
  const char* quantity;            // "the reading time"
  std::vector<const char*> names;  // as normalize_name spells them
  std::vector<Unit> units;         // the first is the internal unit
  bool unit_required;              // the name alone is ambiguous (min or s?): the header must say
  const char* examples;
};

const std::vector<Unit> kTime = {
    {"min"},          {"mins"},          {"minute"},          {"minutes"},          {"s", 1 / 60.},
    {"sec", 1 / 60.}, {"secs", 1 / 60.}, {"second", 1 / 60.}, {"seconds", 1 / 60.}, {"h", 60},
    {"hr", 60},       {"hrs", 60},       {"hour", 60},        {"hours", 60}};
const std::vector<Unit> kGramsPerLitre = {{"g/l"}, {"kg/m3"}, {"g/dm3"}, {"mg/ml"}};
const std::vector<Unit> kCelsius = {{"c"}, {"f", 5 / 9., -160 / 9.}, {"k", 1, -273.15}};
const std::vector<Unit> kGrams = {{"g"}, {"mg", 1e-3}, {"kg", 1e3}};
const std::vector<Unit> kMillimetres = {{"mm"}, {"um", 1e-3}, {"cm", 10}, {"m", 1e3}};

const std::vector<Column>& columns() {
  static const std::vector<Column> all = {
      {"time_min",
       "the reading time",
       {"time", "t", "elapsed time", "elapsed", "time elapsed", "reading time"},
       kTime,
       true,
       "time (min), time (s), time [h], elapsed time, s"},
      {"reading_g_per_l",
       "the 152H reading",
       {"r", "reading", "hydrometer reading", "actual reading", "raw reading", "152h reading"},
       kGramsPerLitre,
       false,
       "R (g/L), hydrometer reading [g/L]"},
      {"temperature_c",
       "the temperature",
       {"t", "temp", "temperature", "suspension temperature", "water temperature"},
       kCelsius,
       false,
       "T (°C), Temperature [C], temperature (°F)"},
      {"composite_correction_g_per_l",
       "the composite correction",
       {"composite correction", "c", "cc", "correction", "blank", "blank reading"},
       kGramsPerLitre,
       false,
       "composite correction (g/L), C (g/L)"},
      {"meniscus_correction_g_per_l",
       "the meniscus correction",
       {"meniscus correction", "cm", "meniscus"},
       kGramsPerLitre,
       false,
       "meniscus correction (g/L), Cm (g/L)"},
      {"apparent_mass_g",
       "the sphere's apparent mass",
       // Not "mass" alone: the sphere's own mass is another number.
       {"apparent mass", "sphere apparent mass", "sphere reading", "apparent weight"},
       kGrams,
       false,
       "apparent mass (g), apparent mass [mg]"},
      {"dry_mass_g",
       "the pipette sample's dry mass",
       // Not "mass" alone: a sample's wet mass is another number.
       {"dry mass", "dry weight", "sample dry mass", "residue", "dry residue"},
       kGrams,
       false,
       "dry mass (g), dry mass [mg]"},
      {"opening_mm",
       "the sieve opening",
       {"opening", "sieve opening", "sieve", "aperture", "sieve size", "size", "mesh opening",
        "sieve aperture"},
       kMillimetres,
       true,
       "opening (mm), sieve opening [µm]"},
      {"mass_retained_g",
       "the mass retained",
       {"mass retained", "retained", "retained mass", "weight retained", "mass retained on sieve"},
       kGrams,
       false,
       "mass retained (g), retained [kg]"},
  };
  return all;
}

const Column* find_column(const std::string& internal) {
  for (const auto& c : columns())
    if (internal == c.internal) return &c;
  return nullptr;
}

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  const auto last = s.find_last_not_of(" \t\r");
  return first == std::string::npos ? "" : s.substr(first, last - first + 1);
}

void replace_all(std::string& s, const std::string& from, const std::string& to) {
  for (auto at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
    s.replace(at, from.size(), to);
}

// Lower case, '_' and '-' as spaces, one space between words, no trailing ':' or '.'.
std::string normalize_name(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '_' || c == '-' || c == '\t') c = ' ';
    if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
    if (c == ' ' && (out.empty() || out.back() == ' ')) continue;
    out += c;
  }
  while (!out.empty() && (out.back() == ' ' || out.back() == ':' || out.back() == '.'))
    out.pop_back();
  return out;
}

// Lower case, no spaces, "µm" and "μm" as "um", no degree sign, "per" as '/', "³" as 3.
std::string normalize_unit(const std::string& text) {
  std::string s = normalize_name(text);
  replace_all(s, "\xC2\xB5", "u");  // micro sign
  replace_all(s, "\xCE\xBC", "u");  // Greek mu
  replace_all(s, "\xC2\xB0", "");   // degree sign
  replace_all(s, "\xC2\xBA", "");   // masculine ordinal, typed for a degree
  replace_all(s, "\xC2\xB3", "3");
  replace_all(s, " per ", "/");
  s.erase(std::remove(s.begin(), s.end(), ' '), s.end());
  for (const char* word :
       {"micrometres", "micrometers", "micrometre", "micrometer", "microns", "micron"})
    replace_all(s, word, "um");
  for (const char* word : {"litres", "liters", "litre", "liter"}) replace_all(s, word, "l");
  for (const char* word : {"degrees", "degree", "deg"})
    if (s.rfind(word, 0) == 0) s.erase(0, std::string(word).size());
  if (s == "celsius") s = "c";
  if (s == "fahrenheit") s = "f";
  if (s == "kelvin") s = "k";
  return s;
}

// A header cell's name and unit as written: "time (min)", "Temperature [C]" and
// "elapsed time, s" give the unit in brackets or after the last comma; "time min" (time_min)
// its last words when they are a unit of a column of that name.
struct Header {
  std::string name, unit;
};
Header parse_header(const std::string& raw) {
  std::string text = trimmed(raw);
  if (!text.empty() && (text.back() == ')' || text.back() == ']')) {
    const auto open = text.find_last_of(text.back() == ')' ? '(' : '[');
    if (open != std::string::npos)
      return {normalize_name(text.substr(0, open)),
              normalize_unit(text.substr(open + 1, text.size() - open - 2))};
  }
  if (const auto comma = text.rfind(','); comma != std::string::npos)
    return {normalize_name(text.substr(0, comma)), normalize_unit(text.substr(comma + 1))};
  return {normalize_name(text), ""};
}

const Unit* find_unit(const Column& c, const std::string& unit) {
  for (const auto& u : c.units)
    if (unit == u.spelled) return &u;
  return nullptr;
}

bool has_name(const Column& c, const std::string& name) {
  return std::any_of(c.names.begin(), c.names.end(), [&](const char* n) { return name == n; });
}

// What a header cell is for column `c`: its unit, or why not (empty unit and a reason).
struct Match {
  std::optional<Unit> unit;
  std::string why_not;  // the name is right but the unit is not known or missing
};
Match match(const Column& c, const std::string& raw) {
  Header h = parse_header(raw);
  if (h.unit.empty()) {
    // "time min", "temperature c", "reading g per l": the name's last words as the unit.
    const std::string full = h.name;
    std::size_t at = full.size();
    for (int words = 0; words < 3; ++words) {
      at = full.rfind(' ', at == 0 ? 0 : at - 1);
      if (at == std::string::npos || at == 0) break;
      const std::string name = full.substr(0, at), unit = normalize_unit(full.substr(at + 1));
      if (has_name(c, name) && find_unit(c, unit)) return {*find_unit(c, unit), ""};
    }
  }
  if (!has_name(c, h.name)) return {};
  if (h.unit.empty()) {
    if (!c.unit_required) return {c.units.front(), ""};
    std::string why = "'";
    why.append(shortened(raw)).append("' gives no unit for ").append(c.quantity);
    return {std::nullopt, why};
  }
  if (const Unit* u = find_unit(c, h.unit)) return {*u, ""};
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "..." + std::string&&.
  std::string why = "'";
  why.append(shortened(raw)).append("': '").append(shortened(h.unit));
  why.append("' is not a unit of ").append(c.quantity).append(" (");
  for (std::size_t i = 0; i < c.units.size(); ++i)
    why.append(i ? ", " : "").append(c.units[i].spelled);
  return {std::nullopt, why.append(")")};
}

// The column as the file names it, for a message: the internal name as it is, another
// quoted.
std::string label(const std::string& raw, const std::string& internal) {
  return raw == internal ? internal : "'" + shortened(raw) + "'";
}

std::string found_list(const std::vector<std::string>& header) {
  std::string found;
  for (std::size_t j = 0; j < header.size() && j < 12; ++j)
    found += (j ? ", '" : "'") + shortened(header[j]) + "'";
  if (header.size() > 12) found += ", ...";
  return found.empty() ? "none" : found;
}

double parse_number(const LabTable& table, std::size_t line, const std::string& column,
                    std::string text) {
  // "12,5" in a file separated by ';' or tabs, or a sheet's text cell.
  if (table.decimal_comma && std::count(text.begin(), text.end(), ',') == 1 &&
      text.find('.') == std::string::npos)
    text[text.find(',')] = '.';
  double v = 0;
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (ec != std::errc() || ptr != end || text.empty())
    throw LabCsvError(line, column, "'" + shortened(text) + "' is not a number", table.place);
  // "nan" or "inf" parse, but are no reading: refused here rather than taken for a missing
  // value (an absent optional column) or carried into the results.
  if (!std::isfinite(v))
    throw LabCsvError(line, column, "'" + shortened(text) + "' is not a finite number",
                      table.place);
  return v;
}

// The header cell for `internal` and its unit; throws for two. `why_not`: why a cell of the
// right name was not taken (its unit), for the message when none is.
struct Found {
  std::size_t index;
  Unit unit;
};
std::optional<Found> find_header(const LabTable& table, const std::string& internal,
                                 std::string& why_not, const std::vector<std::size_t>& taken = {}) {
  const Column* c = find_column(internal);
  // The internal name itself wins over the laboratory's names: sedem's own outputs hold
  // time_s beside time_min, diameter_um beside diameter_m.
  for (std::size_t j = 0; j < table.header.size(); ++j)
    if (trimmed(table.header[j]) == internal) return Found{j, c ? c->units.front() : Unit{""}};
  std::optional<Found> found;
  for (std::size_t j = 0; j < table.header.size(); ++j) {
    const std::string& raw = table.header[j];
    std::optional<Unit> unit;
    if (trimmed(raw) == internal) {
      unit = c ? c->units.front() : Unit{""};
    } else if (c) {
      Match m = match(*c, raw);
      unit = m.unit;
      // A cell another column took ("T (°C)" is no time) says nothing about this one.
      const bool other = std::find(taken.begin(), taken.end(), j) != taken.end();
      if (!m.why_not.empty() && why_not.empty() && !other) why_not = m.why_not;
    }
    if (!unit) continue;
    if (found)
      throw LabCsvError(table.header_line, internal,
                        "two columns for it: '" + shortened(table.header[found->index]) +
                            "' and '" + shortened(raw) + "'",
                        table.place);
    found = Found{j, *unit};
  }
  return found;
}

}  // namespace

std::optional<std::size_t> lab_column_index(const LabTable& table, const std::string& internal) {
  std::string why_not;
  const auto found = find_header(table, internal, why_not);
  return found ? std::optional<std::size_t>(found->index) : std::nullopt;
}

std::string lab_column_expected(const std::string& internal) {
  const Column* c = find_column(internal);
  if (!c) return "";
  return std::string(c->quantity) + ", as " + internal + " or e.g. " + c->examples;
}

std::vector<std::vector<double>> lab_columns(const LabTable& table,
                                             const std::vector<std::string>& required,
                                             const std::vector<std::string>& optional,
                                             std::vector<std::size_t>* lines) {
  if (lines) lines->clear();
  std::vector<std::string> names = required;
  names.insert(names.end(), optional.begin(), optional.end());
  std::vector<std::optional<Found>> found(names.size());
  std::vector<std::size_t> taken;
  std::string ignored;
  for (std::size_t k = 0; k < names.size(); ++k) {
    found[k] = find_header(table, names[k], ignored);
    if (found[k]) taken.push_back(found[k]->index);
  }
  for (std::size_t k = 0; k < required.size(); ++k) {
    if (found[k]) continue;
    std::string why_not;
    find_header(table, names[k], why_not, taken);
    std::string why = "missing from the header (found " + found_list(table.header) + ")";
    if (!why_not.empty()) why += "; " + why_not;
    if (find_column(names[k])) why += "; expected " + lab_column_expected(names[k]);
    throw LabCsvError(table.header_line, names[k], why, table.place);
  }
  std::vector<std::vector<double>> rows;
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    const auto& cells = table.rows[i];
    const std::size_t line = table.lines[i];
    std::vector<double> v(names.size(), std::numeric_limits<double>::quiet_NaN());
    for (std::size_t k = 0; k < names.size(); ++k) {
      if (!found[k]) continue;
      const std::string column = label(table.header[found[k]->index], names[k]);
      if (found[k]->index >= cells.size())
        throw LabCsvError(line, column, "missing value", table.place);
      v[k] = found[k]->unit.scale * parse_number(table, line, column, cells[found[k]->index]) +
             found[k]->unit.offset;
    }
    rows.push_back(std::move(v));
    if (lines) lines->push_back(line);
  }
  if (rows.empty())
    throw LabCsvError(table.header_line, "", "no readings: the file holds a header and no data row",
                      table.place);
  return rows;
}

}  // namespace sedem
