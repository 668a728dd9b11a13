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
#include <vtkTable.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>

#include "render/offscreen_view.h"

namespace sedem::render {
namespace {

constexpr int kTitleHeight = 34;

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

// Each distinct series name, in order of first appearance across the panels.
std::map<std::string, std::size_t> name_indices(const Figure& figure) {
  std::map<std::string, std::size_t> index;
  for (const auto& panel : figure.panels)
    for (const auto& s : panel.series) index.emplace(s.name, index.size());
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

void style_axis(vtkAxis* axis, PlotAxis spec, const Plot& plot, bool is_x) {
  if (spec.log && !spec.range) spec.range = log_range(plot, is_x);
  axis->SetTitle(spec.title());
  axis->GetTitleProperties()->SetFontSize(13);
  axis->GetTitleProperties()->SetColor(0, 0, 0);
  axis->GetTitleProperties()->SetFontFamilyToArial();
  axis->GetLabelProperties()->SetFontSize(12);
  axis->GetLabelProperties()->SetColor(0, 0, 0);
  axis->GetLabelProperties()->SetFontFamilyToArial();
  axis->SetLogScale(spec.log);
  if (spec.range) {
    axis->SetBehavior(vtkAxis::FIXED);
    axis->SetUnscaledRange(spec.range->first, spec.range->second);
  } else {
    axis->SetBehavior(vtkAxis::AUTO);
  }
}

vtkSmartPointer<vtkTable> series_table(const PlotSeries& s, bool log_x, bool log_y) {
  auto x = vtkSmartPointer<vtkDoubleArray>::New();
  x->SetName("x");
  auto y = vtkSmartPointer<vtkDoubleArray>::New();
  y->SetName("y");
  const std::size_t n = std::min(s.x.size(), s.y.size());
  for (std::size_t i = 0; i < n; ++i) {
    // A log axis cannot show zero or negative values, and VTK would reject the whole series.
    if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
    if ((log_x && s.x[i] <= 0) || (log_y && s.y[i] <= 0)) continue;
    x->InsertNextValue(s.x[i]);
    y->InsertNextValue(s.y[i]);
  }
  auto table = vtkSmartPointer<vtkTable>::New();
  table->AddColumn(x);
  table->AddColumn(y);
  return table;
}

// A band's table: x, its lower and upper edges.
vtkSmartPointer<vtkTable> band_table(const PlotSeries& s) {
  auto table = vtkSmartPointer<vtkTable>::New();
  const char* names[] = {"x", "low", "high"};
  const std::vector<double>* values[] = {&s.x, &s.y_low, &s.y};
  const std::size_t n = std::min({s.x.size(), s.y.size(), s.y_low.size()});
  for (int c = 0; c < 3; ++c) {
    auto a = vtkSmartPointer<vtkDoubleArray>::New();
    a->SetName(names[c]);
    for (std::size_t i = 0; i < n; ++i) a->InsertNextValue((*values[c])[i]);
    table->AddColumn(a);
  }
  return table;
}

vtkSmartPointer<vtkChartXY> make_chart(const Plot& plot,
                                       const std::map<std::string, std::size_t>& colors) {
  auto chart = vtkSmartPointer<vtkChartXY>::New();
  chart->SetTitle(plot.title);
  chart->GetTitleProperties()->SetFontSize(14);
  chart->GetTitleProperties()->SetBold(true);
  chart->GetTitleProperties()->SetColor(0, 0, 0);
  chart->GetTitleProperties()->SetFontFamilyToArial();
  style_axis(chart->GetAxis(vtkAxis::BOTTOM), plot.x, plot, true);
  style_axis(chart->GetAxis(vtkAxis::LEFT), plot.y, plot, false);
  for (const auto& s : plot.series) {
    if (s.style == SeriesStyle::band) {
      vtkPlot* area = chart->AddPlot(vtkChart::AREA);
      area->SetInputData(band_table(s));
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
    p->SetInputData(series_table(s, plot.x.log, plot.y.log), 0, 1);
    p->SetLabel(s.name);
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
  }
  chart->SetShowLegend(plot.legend && !plot.series.empty());
  chart->GetLegend()->GetLabelProperties()->SetFontSize(11);
  chart->GetLegend()->GetLabelProperties()->SetFontFamilyToArial();
  chart->GetLegend()->GetLabelProperties()->SetColor(0, 0, 0);
  const bool right = plot.legend_corner == LegendCorner::top_right ||
                     plot.legend_corner == LegendCorner::bottom_right;
  const bool top =
      plot.legend_corner == LegendCorner::top_right || plot.legend_corner == LegendCorner::top_left;
  chart->GetLegend()->SetHorizontalAlignment(right ? vtkChartLegend::RIGHT : vtkChartLegend::LEFT);
  chart->GetLegend()->SetVerticalAlignment(top ? vtkChartLegend::TOP : vtkChartLegend::BOTTOM);
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

// Draws `figure` into `view` (created by the caller at figure_size(figure)).
void draw_figure(const Figure& figure, OffscreenView& view);

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
  draw_figure(figure, view);
  return view.capture();
}

void write_figure_svg(const Figure& figure, const std::filesystem::path& file) {
  if (figure.panels.empty()) throw std::invalid_argument("a figure needs at least one panel");
  const auto [width, height] = figure_size(figure);
  OffscreenView view(width, height);
  draw_figure(figure, view);
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

void draw_figure(const Figure& figure, OffscreenView& view) {
  const int columns = std::clamp(figure.columns, 1, int(figure.panels.size()));
  const int rows = (int(figure.panels.size()) + columns - 1) / columns;
  const int title_h = figure.title.empty() ? 0 : kTitleHeight;
  const auto [width, height] = figure_size(figure);
  auto actor = vtkSmartPointer<vtkContextActor>::New();
  const auto colors = name_indices(figure);
  for (std::size_t i = 0; i < figure.panels.size(); ++i) {
    const int r = int(i) / columns, c = int(i) % columns;
    auto chart = make_chart(figure.panels[i], colors);
    chart->SetAutoSize(false);
    chart->SetSize(vtkRectf(float(c * figure.panel_width),
                            float((rows - 1 - r) * figure.panel_height), float(figure.panel_width),
                            float(figure.panel_height)));
    actor->GetScene()->AddItem(chart);
  }
  view.renderer()->AddActor(actor);
  if (title_h > 0) {
    auto text = vtkSmartPointer<vtkTextActor>::New();
    text->SetInput(figure.title.c_str());
    auto* prop = text->GetTextProperty();
    prop->SetFontFamilyToArial();
    prop->SetBold(true);
    prop->SetColor(0, 0, 0);
    prop->SetJustificationToCentered();
    prop->SetVerticalJustificationToCentered();
    prop->SetFontSize(fitting_font_size(figure.title, prop, width - 16, 18));
    text->SetDisplayPosition(width / 2, height - title_h / 2);
    view.renderer()->AddActor2D(text);
  }
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
  std::ofstream out(file);
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
  if (!out) throw std::runtime_error("cannot write " + file.string());
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
