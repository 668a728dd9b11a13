#include "render/plot.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>

#include "render/atomic_write.h"
#include "render/drawing/figure_files.h"

namespace sedem::render {
namespace {

std::string identifier(const std::string& text) {
  std::string out;
  for (unsigned char c : text) {
    if (std::isalnum(c)) {
      out += char(std::tolower(c));
    } else if (c == '%') {
      out += "percent";
    } else if (c == 0xC2 || c == 0xCE) {
      continue;  // lead byte of µ (U+00B5) or μ (U+03BC) in UTF-8
    } else if (c == 0xB5 || c == 0xBC) {
      out += 'u';
    } else if (c == 0xB3) {
      out += '3';  // ³ (U+00B3), as in kg/m³
    } else if (!out.empty() && out.back() != '_') {
      out += '_';
    }
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out;
}

// A log axis without a fixed range spans the whole decades around its positive data.
std::optional<std::pair<double, double>> log_range(const Plot& plot, bool x) {
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (const auto& s : plot.series)
    for (double v : x ? s.x : s.y)
      if (std::isfinite(v) && v > 0) lo = std::min(lo, v), hi = std::max(hi, v);
  if (!(lo <= hi)) return std::pair{1.0, 10.0};
  lo = std::pow(10.0, std::floor(std::log10(lo) + 1e-9));
  hi = std::pow(10.0, std::ceil(std::log10(hi) - 1e-9));
  if (hi <= lo) hi = 10.0 * lo;
  return std::pair{lo, hi};
}

// The data range of one axis over every series (bands included); log axes only positive values.
std::pair<double, double> data_range(const Plot& plot, bool x, bool log) {
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (const auto& s : plot.series)
    for (const auto* values : {x ? &s.x : &s.y, x ? &s.x : &s.y_low})
      for (double v : *values)
        if (std::isfinite(v) && (!log || v > 0)) lo = std::min(lo, v), hi = std::max(hi, v);
  return {lo, hi};
}

// 1, 2 or 5 times a power of ten, nearest (in ratio) to a `target`-th of `span`.
double nice_step(double span, int target) {
  const double raw = span / target;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  double best = decade;
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (std::abs(std::log(m * decade / raw)) < std::abs(std::log(best / raw))) best = m * decade;
  return best;
}

std::string tick_label(double v, int decimals) {
  char buf[48];
  if (std::abs(v) >= 1e6 && decimals == 0) {
    std::snprintf(buf, sizeof buf, "%.3g", v);
  } else {
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  }
  std::string out = buf;
  if (out.starts_with("-") && out.find_first_not_of("-0.") == std::string::npos) out.erase(0, 1);
  return out;
}

}  // namespace

AxisTicks axis_ticks(const Plot& plot, bool x) {
  PlotAxis spec = x ? plot.x : plot.y;
  AxisTicks t;
  if (spec.log) {
    const auto range = spec.range ? *spec.range : *log_range(plot, x);
    t.range = range;
    const double a = std::log10(range.first), b = std::log10(range.second);
    const int first = int(std::ceil(a - 1e-9)), last = int(std::floor(b + 1e-9));
    // Few decades: 1, 2 and 5 in each, so that the axis has at least three labels.
    const bool fine = last - first < 2;
    for (int k = first - 1; k <= last; ++k) {
      for (double m : fine ? std::vector<double>{1, 2, 5} : std::vector<double>{1}) {
        const double v = m * std::pow(10.0, k);
        if (v < range.first * (1 - 1e-9) || v > range.second * (1 + 1e-9)) continue;
        t.at.push_back(v);
        // Arial has no superscript 4-9: 1e6 rather than 10 to the 6.
        char label[32];
        if (v >= 1e6) {
          std::snprintf(label, sizeof label, "%ge%d", m, k);
        } else {
          std::snprintf(label, sizeof label, "%s",
                        tick_label(v, std::max(0, -int(std::floor(std::log10(v) + 1e-9)))).c_str());
        }
        t.labels.push_back(label);
      }
    }
    return t;
  }
  std::pair<double, double> range;
  if (spec.range) {
    range = *spec.range;
  } else {
    auto [lo, hi] = data_range(plot, x, false);
    if (!(lo <= hi)) lo = 0, hi = 1;
    if (hi - lo <= 1e-12 * std::max(1.0, std::abs(hi))) {
      const double pad = std::max(0.5, 0.05 * std::abs(hi));
      lo -= pad, hi += pad;
    }
    // A margin, so that no point sits on the frame (but no negative values for data that
    // have none), then outward to whole steps.
    const double margin = 0.03 * (hi - lo);
    lo = lo >= 0 ? std::max(0.0, lo - margin) : lo - margin;
    hi += margin;
    const double step = nice_step(hi - lo, 6);
    range = {std::floor(lo / step + 1e-9) * step, std::ceil(hi / step - 1e-9) * step};
  }
  if (!(range.second > range.first)) range.second = range.first + 1;
  t.range = range;
  const double span = range.second - range.first;
  const double step = nice_step(span, 6);
  int decimals = 0;  // as many as the step needs: 0.5 one, 5 none
  while (decimals < 12 && std::abs(step * std::pow(10.0, decimals) -
                                   std::round(step * std::pow(10.0, decimals))) > 1e-6)
    ++decimals;
  for (double k = std::ceil(range.first / step - 1e-9); k * step <= range.second + 1e-9 * span;
       k += 1) {
    t.at.push_back(k * step);
    t.labels.push_back(tick_label(k * step, decimals));
  }
  return t;
}

namespace {

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

}  // namespace

PlotAxis axis(std::string quantity, std::string unit, bool log) {
  PlotAxis a;
  a.quantity = std::move(quantity);
  a.unit = std::move(unit);
  a.log = log;
  return a;
}

PlotAxis axis(std::string quantity, std::string unit, double min, double max, bool log) {
  PlotAxis a = axis(std::move(quantity), std::move(unit), log);
  a.range = std::pair{min, max};
  return a;
}

std::string PlotAxis::title() const {
  return unit.empty() ? quantity : quantity + " (" + unit + ")";
}

std::string PlotAxis::column_name() const {
  if (!column.empty()) return column;
  const std::string q = identifier(quantity), u = identifier(unit);
  if (u.empty()) return q;
  if (q.empty()) return u;
  if (u == "percent") return q.starts_with("percent") ? q : u + "_" + q;
  return q + "_" + u;
}

std::array<unsigned char, 3> palette_color(std::size_t i) {
  // Okabe-Ito, then a few darker tones.
  static const std::array<std::array<unsigned char, 3>, 10> colors = {{{0, 114, 178},
                                                                       {213, 94, 0},
                                                                       {0, 158, 115},
                                                                       {204, 121, 167},
                                                                       {230, 159, 0},
                                                                       {86, 180, 233},
                                                                       {0, 0, 0},
                                                                       {120, 80, 20},
                                                                       {100, 100, 100},
                                                                       {150, 20, 60}}};
  return colors[i % colors.size()];
}

Figure single_plot(Plot plot, int width, int height) {
  Figure f;
  f.panels.push_back(std::move(plot));
  f.panel_width = width;
  f.panel_height = height;
  return f;
}

void write_figure_csv(const Figure& figure, const std::filesystem::path& file) {
  std::vector<std::string> header;
  std::vector<const std::vector<double>*> columns;
  const bool prefix = figure.panels.size() > 1;
  for (const auto& panel : figure.panels) {
    const std::string pre = prefix ? panel.title + "/" : "";
    for (const auto& s : panel.series) {
      header.push_back(pre + s.name + ":" + panel.x.column_name());
      columns.push_back(&s.x);
      const bool band = s.style == SeriesStyle::band;
      if (band) {
        header.push_back(pre + s.name + ":" + panel.y.column_name() + "_low");
        columns.push_back(&s.y_low);
      }
      header.push_back(pre + s.name + ":" + panel.y.column_name() + (band ? "_high" : ""));
      columns.push_back(&s.y);
    }
  }
  std::size_t rows = 0;
  for (const auto* c : columns) rows = std::max(rows, c->size());
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  write_atomically(file, [&](std::ostream& out) {
    if (!figure.csv_note.empty()) out << "# " << figure.csv_note << "\n";
    for (std::size_t j = 0; j < header.size(); ++j) out << (j ? "," : "") << csv_field(header[j]);
    out << "\n";
    char number[32];
    for (std::size_t i = 0; i < rows; ++i) {
      for (std::size_t j = 0; j < columns.size(); ++j) {
        if (j) out << ",";
        if (i < columns[j]->size()) {
          std::snprintf(number, sizeof number, "%.9g", (*columns[j])[i]);
          out << number;
        }
      }
      out << "\n";
    }
  });
}

std::vector<std::filesystem::path> write_figure(const Figure& figure,
                                                const std::filesystem::path& base,
                                                const FigureOutput& output) {
  if (!output.partial_note.empty()) {
    Figure partial = figure;
    partial.title += partial.title.empty() ? "(partial)" : " (partial)";
    partial.csv_note = output.partial_note;
    FigureOutput once = output;
    once.partial_note.clear();
    return write_figure(partial, base, once);
  }
  auto files = write_drawing(figure_drawing(figure), base, output);
  auto csv = base;
  csv += ".csv";
  write_figure_csv(figure, csv);
  files.push_back(csv);
  return files;
}

}  // namespace sedem::render
