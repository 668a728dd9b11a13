#include "render/plot.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>

#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextActor.h>
#include <vtkContextScene.h>
#include <vtkDoubleArray.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotArea.h>
#include <vtkPlotPoints.h>
#include <vtkSVGExporter.h>
#include <vtkStringArray.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>

#include "render/atomic_write.h"
#include "render/context_text.h"
#include "render/offscreen_view.h"
#include "render/text_fit.h"

namespace sedem::render {
namespace {

constexpr int kTitleHeight = 34;
constexpr int kLeftMargin = 72, kBottomMargin = 46, kTopMargin = 28;
constexpr int kLegendFont = 11;
constexpr int kTitleFont = 14;
// The legend strip takes at most this share of a panel's width: longer entries (the names
// `sedem render` gives runs) wrap onto more lines rather than squeezing the plot area.
constexpr double kLegendShare = 0.45;
// Beside a legend entry's text: the strip's left gap, the legend's padding and line sample.
constexpr int kLegendPad = 64;

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

// Each distinct name of a series without a colour of its own, in order of first appearance
// across the panels.
std::map<std::string, std::size_t> name_indices(const Figure& figure) {
  std::map<std::string, std::size_t> index;
  for (const auto& panel : figure.panels)
    for (const auto& s : panel.series)
      if (!s.color) index.emplace(s.name, index.size());
  return index;
}

// VTK 9.1 draws nothing on a log axis left to find its own range, so a log axis without a
// fixed range gets the whole decades around its positive data.
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
  // VTK 9.1's charts draw no curve at all on an axis whose span is below about 1 % of its
  // values (1000 to 1008 kg/m³): the data are drawn relative to the axis' start instead,
  // with the labels of the true values.
  if (span < 0.05 * std::max(std::abs(range.first), std::abs(range.second))) t.offset = range.first;
  return t;
}

namespace {

void style_axis(vtkAxis* axis, const PlotAxis& spec, const AxisTicks& ticks) {
  axis->SetTitle(spec.title());
  axis->GetTitleProperties()->SetFontSize(13);
  axis->GetTitleProperties()->SetColor(0, 0, 0);
  axis->GetTitleProperties()->SetFontFamilyToArial();
  axis->GetLabelProperties()->SetFontSize(12);
  axis->GetLabelProperties()->SetColor(0, 0, 0);
  axis->GetLabelProperties()->SetFontFamilyToArial();
  axis->SetLogScale(spec.log);
  axis->SetBehavior(vtkAxis::FIXED);
  axis->SetUnscaledRange(ticks.range.first - ticks.offset, ticks.range.second - ticks.offset);
  // Our own ticks: labels that never repeat (their decimals follow the step) nor run
  // together (decades only on a log axis of several decades).
  auto positions = vtkSmartPointer<vtkDoubleArray>::New();
  auto labels = vtkSmartPointer<vtkStringArray>::New();
  for (std::size_t i = 0; i < ticks.at.size(); ++i) {
    positions->InsertNextValue(spec.log ? std::log10(ticks.at[i]) : ticks.at[i] - ticks.offset);
    labels->InsertNextValue(ticks.labels[i]);
  }
  axis->SetCustomTickPositions(positions, labels);
}

vtkSmartPointer<vtkTable> series_table(const PlotSeries& s, bool log_x, bool log_y, double x0,
                                       double y0) {
  auto x = vtkSmartPointer<vtkDoubleArray>::New();
  x->SetName("x");
  auto y = vtkSmartPointer<vtkDoubleArray>::New();
  y->SetName("y");
  const std::size_t n = std::min(s.x.size(), s.y.size());
  for (std::size_t i = 0; i < n; ++i) {
    // A log axis cannot show zero or negative values, and VTK would reject the whole series.
    if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
    if ((log_x && s.x[i] <= 0) || (log_y && s.y[i] <= 0)) continue;
    x->InsertNextValue(s.x[i] - x0);
    y->InsertNextValue(s.y[i] - y0);
  }
  auto table = vtkSmartPointer<vtkTable>::New();
  table->AddColumn(x);
  table->AddColumn(y);
  return table;
}

// A band's table: x, its lower and upper edges.
vtkSmartPointer<vtkTable> band_table(const PlotSeries& s, double x0, double y0) {
  auto table = vtkSmartPointer<vtkTable>::New();
  const char* names[] = {"x", "low", "high"};
  const std::vector<double>* values[] = {&s.x, &s.y_low, &s.y};
  const double offsets[] = {x0, y0, y0};
  const std::size_t n = std::min({s.x.size(), s.y.size(), s.y_low.size()});
  for (int c = 0; c < 3; ++c) {
    auto a = vtkSmartPointer<vtkDoubleArray>::New();
    a->SetName(names[c]);
    for (std::size_t i = 0; i < n; ++i) a->InsertNextValue((*values[c])[i] - offsets[c]);
    table->AddColumn(a);
  }
  return table;
}

// The widest a legend entry's text may be in `figure`'s panels before it wraps.
int legend_text_width(const Figure& figure) {
  return int(kLegendShare * figure.panel_width) - kLegendPad;
}

// A series' legend entry as drawn: its name, wrapped to the legend strip.
std::vector<std::string> legend_lines(const PlotSeries& s, int text_width) {
  return wrap_text(s.name, text_width, kLegendFont);
}

// A line of a legend entry after its first: a plot with no data that draws no line sample,
// right after its series' plot, so that it sits under the entry's first line.
void add_legend_continuation(vtkChartXY* chart, const std::string& line) {
  auto table = vtkSmartPointer<vtkTable>::New();
  for (const char* name : {"x", "y"}) {
    auto a = vtkSmartPointer<vtkDoubleArray>::New();
    a->SetName(name);
    table->AddColumn(a);
  }
  vtkPlot* p = chart->AddPlot(vtkChart::LINE);
  p->SetInputData(table, 0, 1);
  p->SetLabel("   " + line);
  p->SetColor(255, 255, 255, 0);
  p->GetPen()->SetLineType(vtkPen::NO_PEN);
  if (auto* marker = vtkPlotPoints::SafeDownCast(p)) marker->SetMarkerStyle(vtkPlotPoints::NONE);
}

vtkSmartPointer<vtkChartXY> make_chart(const Plot& plot,
                                       const std::map<std::string, std::size_t>& colors,
                                       int legend_text) {
  auto chart = vtkSmartPointer<vtkChartXY>::New();
  chart->SetTitle(plot.title);
  chart->GetTitleProperties()->SetFontSize(kTitleFont);
  chart->GetTitleProperties()->SetBold(true);
  chart->GetTitleProperties()->SetColor(0, 0, 0);
  chart->GetTitleProperties()->SetFontFamilyToArial();
  const auto xt = axis_ticks(plot, true), yt = axis_ticks(plot, false);
  style_axis(chart->GetAxis(vtkAxis::BOTTOM), plot.x, xt);
  style_axis(chart->GetAxis(vtkAxis::LEFT), plot.y, yt);
  for (const auto& s : plot.series) {
    if (s.style == SeriesStyle::band) {
      vtkPlot* area = chart->AddPlot(vtkChart::AREA);
      area->SetInputData(band_table(s, xt.offset, yt.offset));
      area->SetInputArray(0, "x");
      area->SetInputArray(1, "low");
      area->SetInputArray(2, "high");
      const auto rgb = s.color ? *s.color : palette_color(colors.at(s.name));
      area->SetColor(rgb[0], rgb[1], rgb[2], 70);
      area->SetLegendVisibility(false);
      continue;
    }
    // A line needs two points; a series of one is drawn as a marker.
    const bool points = s.style == SeriesStyle::points || s.x.size() < 2;
    vtkPlot* p = chart->AddPlot(points ? vtkChart::POINTS : vtkChart::LINE);
    p->SetInputData(series_table(s, plot.x.log, plot.y.log, xt.offset, yt.offset), 0, 1);
    const auto lines = legend_lines(s, legend_text);
    p->SetLabel(lines.front());
    const auto rgb = s.color ? *s.color : palette_color(colors.at(s.name));
    p->SetColor(rgb[0], rgb[1], rgb[2], 255);
    p->SetWidth(2.0);
    auto* marker = vtkPlotPoints::SafeDownCast(p);
    if (s.style == SeriesStyle::dashed) p->GetPen()->SetLineType(vtkPen::DASH_LINE);
    if (marker) {
      if (points || s.style == SeriesStyle::line_and_points) {
        marker->SetMarkerStyle(vtkPlotPoints::CIRCLE);
        marker->SetMarkerSize(6);
      } else {
        marker->SetMarkerStyle(vtkPlotPoints::NONE);
      }
    }
    if (plot.legend)
      for (std::size_t k = 1; k < lines.size(); ++k) add_legend_continuation(chart, lines[k]);
  }
  chart->SetShowLegend(plot.legend && !plot.series.empty());
  auto* legend = chart->GetLegend();
  legend->GetLabelProperties()->SetFontSize(kLegendFont);
  legend->GetLabelProperties()->SetFontFamilyToArial();
  legend->GetLabelProperties()->SetColor(0, 0, 0);
  // Outside the data, in the strip right of the plot area (placed by draw_figure).
  legend->SetInline(false);
  legend->SetHorizontalAlignment(vtkChartLegend::CUSTOM);
  legend->SetVerticalAlignment(vtkChartLegend::CUSTOM);
  return chart;
}

}  // namespace

int fitting_font_size(const std::string& text, vtkTextProperty* prop, int width, int largest) {
  auto* renderer = vtkTextRenderer::GetInstance();
  int size = largest;
  for (; size > 8; --size) {
    prop->SetFontSize(size);
    int bbox[4];
    if (!renderer || !renderer->GetBoundingBox(prop, text, bbox, 72)) break;
    if (bbox[1] - bbox[0] <= width) break;
  }
  return size;
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

namespace {

// Draws `figure` into `view` (created by the caller at figure_size(figure)); returns its
// charts, one per panel, and their titles as drawn.
std::vector<vtkSmartPointer<vtkChartXY>> draw_figure(const Figure& figure, OffscreenView& view,
                                                     std::vector<FittedText>& titles);

// The strip right of the plot areas that holds the widest legend of the figure (none without
// legends): its longest line, the line sample before it and padding.
int legend_width(const Figure& figure) {
  const int text = legend_text_width(figure);
  int widest = -1;
  for (const auto& panel : figure.panels) {
    if (!panel.legend) continue;
    for (const auto& s : panel.series) {
      if (s.style == SeriesStyle::band) continue;
      for (const auto& line : legend_lines(s, text))
        widest = std::max(widest, text_width(line, kLegendFont));
    }
  }
  return widest < 0 ? 16 : widest + kLegendPad;
}

// A legend's height as vtkChartLegend lays it out: per line a line of text and its padding
// (5 pixels), and the padding once more.
int legend_height(const Plot& plot, int legend_text) {
  auto prop = vtkSmartPointer<vtkTextProperty>::New();
  prop->SetFontFamilyToArial();
  prop->SetFontSize(kLegendFont);
  int bbox[4] = {0, 0, 0, 12};
  if (auto* renderer = vtkTextRenderer::GetInstance())
    renderer->GetBoundingBox(prop, "Tg", bbox, 72);
  std::size_t lines = 0;
  for (const auto& s : plot.series)
    if (s.style != SeriesStyle::band) lines += legend_lines(s, legend_text).size();
  return int(lines) * (bbox[3] - bbox[2] + 5) + 5;
}

std::pair<int, int> figure_size(const Figure& figure) {
  const int columns = std::clamp(figure.columns, 1, int(figure.panels.size()));
  const int rows = (int(figure.panels.size()) + columns - 1) / columns;
  const int title_h = figure.title.empty() ? 0 : kTitleHeight;
  return {columns * figure.panel_width, rows * figure.panel_height + title_h};
}

}  // namespace

vtkSmartPointer<vtkImageData> render_figure(const Figure& figure) {
  if (figure.panels.empty()) throw std::invalid_argument("a figure needs at least one panel");
  const auto [width, height] = figure_size(figure);
  OffscreenView view(width, height);
  std::vector<FittedText> titles;
  draw_figure(figure, view, titles);
  return view.capture();
}

std::vector<PanelLayout> figure_layout(const Figure& figure) {
  if (figure.panels.empty()) throw std::invalid_argument("a figure needs at least one panel");
  const auto [width, height] = figure_size(figure);
  OffscreenView view(width, height);
  std::vector<FittedText> titles;
  const auto charts = draw_figure(figure, view, titles);
  view.capture();
  std::vector<PanelLayout> out;
  for (std::size_t i = 0; i < charts.size(); ++i) {
    const auto& chart = charts[i];
    PanelLayout l;
    const float* x0 = chart->GetAxis(vtkAxis::BOTTOM)->GetPoint1();
    const float* x1 = chart->GetAxis(vtkAxis::BOTTOM)->GetPoint2();
    const float* y1 = chart->GetAxis(vtkAxis::LEFT)->GetPoint2();
    l.plot_area = {x0[0], x0[1], x1[0], y1[1]};
    const auto& point = chart->GetLegend()->GetPointVector();
    l.legend_shown = chart->GetShowLegend();
    l.legend_inline = chart->GetLegend()->GetInline();
    l.legend_point = {point.GetX(), point.GetY()};
    l.title = titles[i].text;
    l.title_font_size = titles[i].size;
    for (vtkIdType k = 0; k < chart->GetNumberOfPlots(); ++k) {
      auto* labels = chart->GetPlot(k)->GetLabels();
      if (chart->GetPlot(k)->GetLegendVisibility() && labels && labels->GetNumberOfValues() > 0)
        l.legend_lines.push_back(labels->GetValue(0));
    }
    out.push_back(l);
  }
  return out;
}

void write_figure_svg(const Figure& figure, const std::filesystem::path& file) {
  if (figure.panels.empty()) throw std::invalid_argument("a figure needs at least one panel");
  const auto [width, height] = figure_size(figure);
  OffscreenView view(width, height);
  std::vector<FittedText> titles;
  draw_figure(figure, view, titles);
  view.capture();  // lays the charts out
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  auto exporter = vtkSmartPointer<vtkSVGExporter>::New();
  exporter->SetRenderWindow(view.window());
  exporter->SetFileName(file.c_str());
  exporter->SetTitle(figure.title.c_str());
  exporter->SetTextAsPath(false);
  exporter->Write();
  if (!std::filesystem::exists(file)) throw std::runtime_error("cannot write " + file.string());
}

namespace {

std::vector<vtkSmartPointer<vtkChartXY>> draw_figure(const Figure& figure, OffscreenView& view,
                                                     std::vector<FittedText>& titles) {
  std::vector<vtkSmartPointer<vtkChartXY>> charts;
  titles.clear();
  const int columns = std::clamp(figure.columns, 1, int(figure.panels.size()));
  const int rows = (int(figure.panels.size()) + columns - 1) / columns;
  const int title_h = figure.title.empty() ? 0 : kTitleHeight;
  const auto [width, height] = figure_size(figure);
  auto actor = vtkSmartPointer<vtkContextActor>::New();
  const auto colors = name_indices(figure);
  const int legend_w = legend_width(figure), legend_text = legend_text_width(figure);
  for (std::size_t i = 0; i < figure.panels.size(); ++i) {
    const int r = int(i) / columns, c = int(i) % columns;
    auto chart = make_chart(figure.panels[i], colors, legend_text);
    // Every panel's plot area at the same place in its panel, so that stacked panels share
    // their axes' ends: room on the left for tick labels and the axis title, below for the
    // same, above for the panel's title, and on the right for the widest legend.
    chart->SetLayoutStrategy(vtkChart::AXES_TO_RECT);
    const float x0 = float(c * figure.panel_width),
                y0 = float((rows - 1 - r) * figure.panel_height);
    chart->SetSize(vtkRectf(x0 + kLeftMargin, y0 + kBottomMargin,
                            float(figure.panel_width - kLeftMargin - legend_w),
                            float(figure.panel_height - kBottomMargin - kTopMargin)));
    // The legend's point is its lower-left corner: its top level with the plot area's.
    chart->GetLegend()->SetPoint(
        vtkVector2f(x0 + float(figure.panel_width - legend_w + 8),
                    y0 + float(figure.panel_height - kTopMargin -
                               legend_height(figure.panels[i], legend_text))));
    // vtkChartXY centres the title over the plot area. One too wide for that (a run named
    // by several scene keys) goes higher, above the top tick label and the legend, across
    // the whole panel and no further, or it would run into the next panel.
    const int plot_w = figure.panel_width - kLeftMargin - legend_w;
    const auto& title = figure.panels[i].title;
    auto fitted = fit_text(title, plot_w + 8, kTitleFont, 10, true);
    if (fitted.text == title) {
      chart->SetTitle(fitted.text);
      chart->GetTitleProperties()->SetFontSize(fitted.size);
    } else {
      fitted = fit_text(title, figure.panel_width - 8, kTitleFont, 8, true);
      chart->SetTitle("");
      auto text = vtkSmartPointer<ContextText>::New();
      text->Set(fitted.text, x0 + 0.5f * float(figure.panel_width),
                y0 + float(figure.panel_height - 10), fitted.size, true);
      actor->GetScene()->AddItem(text);
    }
    titles.push_back(fitted);
    actor->GetScene()->AddItem(chart);
    charts.push_back(chart);
  }
  if (title_h > 0) {
    // In the charts' scene, so that the SVG has it as text too.
    const auto fitted = fit_text(figure.title, width - 16, 18, 8, true);
    auto text = vtkSmartPointer<ContextText>::New();
    text->Set(fitted.text, 0.5f * float(width), float(height - title_h / 2), fitted.size, true);
    actor->GetScene()->AddItem(text);
  }
  view.renderer()->AddActor(actor);
  return charts;
}

}  // namespace

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

void write_figure(const Figure& figure, const std::filesystem::path& base, bool svg) {
  auto png = base, csv = base, vector = base;
  png += ".png";
  csv += ".csv";
  vector += ".svg";
  write_png(render_figure(figure), png);
  write_figure_csv(figure, csv);
  if (svg) write_figure_svg(figure, vector);
}

}  // namespace sedem::render
