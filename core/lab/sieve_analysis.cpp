#include "core/lab/sieve_analysis.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "core/lab/lab_columns.h"

namespace sedem {

namespace {

std::string lower_trimmed(const std::string& cell) {
  std::string s;
  for (char c : cell)
    if (c != ' ' && c != '\t' && c != '\r') s += (c >= 'A' && c <= 'Z') ? char(c - 'A' + 'a') : c;
  return s;
}

// What a row's label says it is: a sieve, the pan or the total.
enum class RowKind { sieve, pan, total };
RowKind row_kind(const std::vector<std::string>& cells) {
  for (const auto& cell : cells) {
    const std::string s = lower_trimmed(cell);
    if (s == "pan" || s == "bottompan") return RowKind::pan;
    if (s == "total" || s == "totaldrymass" || s == "totalmass") return RowKind::total;
  }
  return RowKind::sieve;
}

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

SieveAnalysis read_sieve_analysis(const LabTable& table) {
  // The pan's and the total's rows have a word for an opening: read them apart.
  LabTable sieves = table, totals = table;
  sieves.rows.clear();
  sieves.lines.clear();
  totals.rows.clear();
  totals.lines.clear();
  const auto opening = lab_column_index(table, "opening_mm");
  std::vector<bool> pan_rows;
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    auto row = table.rows[i];
    const RowKind kind = row_kind(row);
    if (opening && *opening < row.size() && kind != RowKind::sieve) row[*opening] = "0";
    (kind == RowKind::total ? totals : sieves).rows.push_back(row);
    (kind == RowKind::total ? totals : sieves).lines.push_back(table.lines[i]);
    if (kind != RowKind::total) pan_rows.push_back(kind == RowKind::pan);
  }
  SieveAnalysis out;
  out.place = table.place;
  std::vector<std::size_t> lines;
  const auto rows = lab_columns(sieves, {"opening_mm", "mass_retained_g"}, {}, &lines);
  auto check_mass = [&](std::size_t line, double g) {
    if (!(g >= 0 && g <= kMaxSieveMassG))
      throw LabCsvError(line, "mass_retained_g",
                        number(g) + " g is out of range; allowed 0 to " + number(kMaxSieveMassG),
                        table.place);
  };
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double d = rows[i][0], g = rows[i][1];
    check_mass(lines[i], g);
    if (pan_rows[i] || d == 0) {
      if (out.pan_g) throw LabCsvError(lines[i], "opening_mm", "a second pan", table.place);
      out.pan_g = g;
      continue;
    }
    if (!(d > 0 && d <= kMaxSieveOpeningMm))
      throw LabCsvError(lines[i], "opening_mm",
                        number(d) + " mm is out of range; allowed (0, " +
                            number(kMaxSieveOpeningMm) + "] mm (0 or \"pan\" for the pan)",
                        table.place);
    for (const auto& s : out.sieves)
      if (std::abs(s.opening_mm - d) <= 1e-9 * d)
        throw LabCsvError(
            lines[i], "opening_mm",
            number(d) + " mm twice (" + table.place + " " + std::to_string(s.line) + ")",
            table.place);
    out.sieves.push_back({d, g, lines[i]});
  }
  if (out.sieves.empty())
    throw LabCsvError(table.header_line, "opening_mm", "no sieve, only the pan", table.place);
  if (!totals.rows.empty()) {
    // The total's row: its mass in the mass column (its opening cell was made 0 above).
    const auto total_rows = lab_columns(totals, {"opening_mm", "mass_retained_g"}, {});
    if (total_rows.size() > 1)
      throw LabCsvError(totals.lines[1], "mass_retained_g", "a second total", table.place);
    check_mass(totals.lines[0], total_rows[0][1]);
    out.total_g = total_rows[0][1];
  }
  std::sort(out.sieves.begin(), out.sieves.end(),
            [](const Sieve& a, const Sieve& b) { return a.opening_mm > b.opening_mm; });
  return out;
}

double sieve_total_g(const SieveAnalysis& analysis, std::optional<double> total_g) {
  if (total_g) return *total_g;
  if (analysis.total_g) return *analysis.total_g;
  if (!analysis.pan_g)
    throw std::invalid_argument(
        "the sieve analysis has neither a total dry mass nor the pan's mass: add a \"total\" or "
        "a \"pan\" row, or give --sieve-total-g");
  double sum = *analysis.pan_g;
  for (const auto& s : analysis.sieves) sum += s.retained_g;
  return sum;
}

double sieve_mass_difference_percent(const SieveAnalysis& analysis, std::optional<double> total_g) {
  if (!analysis.pan_g) return std::numeric_limits<double>::quiet_NaN();
  double sum = *analysis.pan_g;
  for (const auto& s : analysis.sieves) sum += s.retained_g;
  const double total = sieve_total_g(analysis, total_g);
  return 100.0 * (sum - total) / total;
}

std::vector<SievePoint> sieve_percent_passing(const SieveAnalysis& analysis,
                                              std::optional<double> total_g) {
  const double total = sieve_total_g(analysis, total_g);
  if (!(total > 0 && total <= kMaxSieveMassG))
    throw std::invalid_argument("the sieve analysis' total dry mass " + number(total) +
                                " g is out of range; allowed (0, " + number(kMaxSieveMassG) +
                                "] g");
  std::vector<SievePoint> out;
  double cumulative = 0;
  for (const auto& s : analysis.sieves) {
    cumulative += s.retained_g;
    // Weighing scatter may take the last sieves a hair past the total; more is a wrong total.
    if (cumulative > total * 1.001)
      throw std::invalid_argument("the sieves down to " + number(s.opening_mm) + " mm retain " +
                                  number(cumulative) + " g, more than the total dry mass " +
                                  number(total) + " g (" + analysis.place + " " +
                                  std::to_string(s.line) + ")");
    out.push_back({s.opening_mm, s.retained_g, cumulative,
                   std::max(0.0, 100.0 * (total - cumulative) / total)});
  }
  return out;
}

}  // namespace sedem
