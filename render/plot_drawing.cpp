#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "render/drawing/figure_files.h"
#include "render/plot.h"
#include "render/text_fit.h"

namespace sedem::render {
namespace {

// Logical pixels (a PNG is scaled to output.figure_width_px).
constexpr double kTitleHeight = 34;
constexpr double kLeftMargin = 74, kBottomMargin = 48, kTopMargin = 30;
constexpr int kLegendFont = 11;
constexpr int kTitleFont = 14;
constexpr double kTickFont = 12, kAxisTitleFont = 13;
constexpr double kTickLength = 5;
// The legend strip takes at most this share of a panel's width: longer entries (the names
// `sedem render` gives runs) wrap onto more lines rather than squeezing the plot area.
constexpr double kLegendShare = 0.45;
// A legend entry: the strip's left gap, the line sample, the gap before the text.
constexpr double kLegendGap = 10, kLegendSample = 28, kLegendTextGap = 8;
constexpr double kLegendPad = kLegendGap + kLegendSample + kLegendTextGap + 10;
constexpr double kLegendLine = 16;  // height of one line of a legend
constexpr double kMarkerRadius = 3.5;
constexpr double kLineWidth = 2;
const std::vector<double> kDashes = {7, 4};
constexpr Rgba kGrid{225, 225, 225, 255};
constexpr unsigned char kBandAlpha = 70;

Rgba rgba(std::array<unsigned char, 3> c, unsigned char a = 255) {
  return {c[0], c[1], c[2], a};
}

// Each distinct name of a series without a colour of its own, in order of first appearance
// across the panels, so that one name has one colour in every panel.
std::map<std::string, std::size_t> name_indices(const Figure& figure) {
  std::map<std::string, std::size_t> index;
  for (const auto& panel : figure.panels)
    for (const auto& s : panel.series)
      if (!s.color) index.emplace(s.name, index.size());
  return index;
}

Rgba series_colour(const PlotSeries& s, const std::map<std::string, std::size_t>& colours) {
  return rgba(s.color ? *s.color : palette_color(colours.at(s.name)));
}

bool in_legend(const PlotSeries& s) {
  return s.style != SeriesStyle::band;
}

double legend_text_width(const Figure& figure) {
  return kLegendShare * figure.panel_width - kLegendPad;
}

std::vector<std::string> legend_lines(const PlotSeries& s, double text_width) {
  return wrap_text(s.name, int(text_width), kLegendFont);
}

// A multi-panel figure whose panels all list the same entries (the samples of Fig. 15, the
// times of Fig. 13) shows that legend once, beside the figure, not once per panel.
bool shared_legend(const Figure& figure) {
  if (figure.panels.size() < 2) return false;
  auto entries = [](const Plot& p) {
    std::vector<std::pair<std::string, SeriesStyle>> e;
    if (p.legend)
      for (const auto& s : p.series)
        if (in_legend(s)) e.emplace_back(s.name, s.style);
    return e;
  };
  const auto first = entries(figure.panels.front());
  if (first.empty()) return false;
  return std::all_of(figure.panels.begin(), figure.panels.end(),
                     [&](const Plot& p) { return entries(p) == first; });
}

// The strip right of the plot areas that holds the widest legend of the figure (a narrow
// margin without legends): its longest line, the line sample before it and padding.
double legend_width(const Figure& figure) {
  const double text = legend_text_width(figure);
  double widest = -1;
  for (const auto& panel : figure.panels) {
    if (!panel.legend) continue;
    for (const auto& s : panel.series) {
      if (!in_legend(s)) continue;
      for (const auto& line : legend_lines(s, text))
        widest = std::max(widest, double(text_width(line, kLegendFont)));
    }
  }
  return widest < 0 ? 18 : widest + kLegendPad;
}

struct Geometry {
  int columns = 1, rows = 1;
  double title_h = 0;
  bool shared = false;
  double legend_w = 0;  // per panel, or the figure's strip when shared
  double width = 0, height = 0;
};

Geometry geometry(const Figure& figure) {
  Geometry g;
  g.columns = std::clamp(figure.columns, 1, int(figure.panels.size()));
  g.rows = (int(figure.panels.size()) + g.columns - 1) / g.columns;
  g.title_h = figure.title.empty() ? 0 : kTitleHeight;
  g.shared = shared_legend(figure);
  g.legend_w = legend_width(figure);
  g.width = g.columns * figure.panel_width + (g.shared ? g.legend_w : 0);
  g.height = g.rows * figure.panel_height + g.title_h;
  return g;
}

// Maps data to the plot area on one axis.
struct Scale {
  double lo, hi;  // the axis' range (log10 of it on a log axis)
  double p0, p1;  // pixels of lo and hi
  bool log;

  Scale(const AxisTicks& t, bool log, double p0, double p1)
      : lo(log ? std::log10(t.range.first) : t.range.first),
        hi(log ? std::log10(t.range.second) : t.range.second),
        p0(p0),
        p1(p1),
        log(log) {}
  bool shows(double v) const { return std::isfinite(v) && (!log || v > 0); }
  double operator()(double v) const {
    const double u = log ? std::log10(v) : v;
    return p0 + (u - lo) / (hi - lo) * (p1 - p0);
  }
};

void draw_marker(Drawing& d, Point at, Rgba colour) {
  d.add(Circle{at, kMarkerRadius, colour, true, Stroke{kWhite, 0.8, {}}});
}

Stroke line_stroke(const PlotSeries& s, Rgba colour) {
  return Stroke{colour, kLineWidth,
                s.style == SeriesStyle::dashed ? kDashes : std::vector<double>{}};
}

bool has_line(const PlotSeries& s) {
  return s.style != SeriesStyle::points && s.x.size() >= 2;
}
bool has_markers(const PlotSeries& s) {
  return s.style == SeriesStyle::points || s.style == SeriesStyle::line_and_points ||
         s.x.size() < 2;
}

void draw_series(Drawing& d, const PlotSeries& s, const Scale& sx, const Scale& sy, Rgba colour) {
  const std::size_t n = std::min(s.x.size(), s.y.size());
  if (s.style == SeriesStyle::band) {
    std::vector<Point> upper, lower;
    for (std::size_t i = 0; i < std::min(n, s.y_low.size()); ++i) {
      if (!sx.shows(s.x[i]) || !sy.shows(s.y[i]) || !sy.shows(s.y_low[i])) continue;
      upper.push_back({sx(s.x[i]), sy(s.y[i])});
      lower.push_back({sx(s.x[i]), sy(s.y_low[i])});
    }
    upper.insert(upper.end(), lower.rbegin(), lower.rend());
    colour.a = kBandAlpha;
    d.add(Polygon{std::move(upper), colour, false, {}});
    return;
  }
  if (has_line(s)) {
    // A value the axis cannot show (NaN, or not positive on a log axis) breaks the line.
    std::vector<Point> run;
    auto flush = [&] {
      if (run.size() >= 2) d.add(Polyline{run, line_stroke(s, colour)});
      run.clear();
    };
    for (std::size_t i = 0; i < n; ++i) {
      if (sx.shows(s.x[i]) && sy.shows(s.y[i]))
        run.push_back({sx(s.x[i]), sy(s.y[i])});
      else
        flush();
    }
    flush();
  }
  if (has_markers(s))
    for (std::size_t i = 0; i < n; ++i)
      if (sx.shows(s.x[i]) && sy.shows(s.y[i])) draw_marker(d, {sx(s.x[i]), sy(s.y[i])}, colour);
}

struct Area {
  double x0, y0, x1, y1;  // top left to bottom right
};

void draw_axes(Drawing& d, const Plot& plot, const Area& a, const AxisTicks& xt,
               const AxisTicks& yt, const Scale& sx, const Scale& sy, double panel_x0) {
  for (std::size_t i = 0; i < xt.at.size(); ++i) {
    const double x = sx(xt.at[i]);
    d.line({x, a.y0}, {x, a.y1}, Stroke{kGrid, 1, {}});
  }
  for (std::size_t i = 0; i < yt.at.size(); ++i) {
    const double y = sy(yt.at[i]);
    d.line({a.x0, y}, {a.x1, y}, Stroke{kGrid, 1, {}});
  }
  d.frame(a.x0, a.y0, a.x1, a.y1, Stroke{kBlack, 1, {}});
  for (std::size_t i = 0; i < xt.at.size(); ++i) {
    const double x = sx(xt.at[i]);
    d.line({x, a.y1}, {x, a.y1 + kTickLength});
    d.add(Text{
        xt.labels[i], {x, a.y1 + kTickLength + 3 + kTickFont}, kTickFont, false, Anchor::middle});
  }
  for (std::size_t i = 0; i < yt.at.size(); ++i) {
    const double y = sy(yt.at[i]);
    d.line({a.x0 - kTickLength, y}, {a.x0, y});
    Text label{yt.labels[i], {a.x0 - kTickLength - 3, y}, kTickFont, false, Anchor::end};
    label.centred_vertically = true;
    d.add(label);
  }
  d.add(Text{plot.x.title(),
             {0.5 * (a.x0 + a.x1), a.y1 + kBottomMargin - 8},
             kAxisTitleFont,
             false,
             Anchor::middle});
  Text y_title{
      plot.y.title(), {panel_x0 + 14, 0.5 * (a.y0 + a.y1)}, kAxisTitleFont, false, Anchor::middle};
  y_title.centred_vertically = true;
  y_title.angle = 90;
  d.add(y_title);
}

// A legend whose first line's top is at `top`; returns the lines as drawn.
std::vector<std::string> draw_legend(Drawing& d, const Plot& plot, double left, double top,
                                     double text_width,
                                     const std::map<std::string, std::size_t>& colours) {
  std::vector<std::string> drawn;
  double y = top + 0.5 * kLegendLine;
  for (const auto& s : plot.series) {
    if (!in_legend(s)) continue;
    const Rgba colour = series_colour(s, colours);
    const double x = left + kLegendGap;
    if (has_line(s)) d.line({x, y}, {x + kLegendSample, y}, line_stroke(s, colour));
    if (has_markers(s)) draw_marker(d, {x + 0.5 * kLegendSample, y}, colour);
    for (const auto& line : legend_lines(s, text_width)) {
      Text t{line, {x + kLegendSample + kLegendTextGap, y}, double(kLegendFont)};
      t.centred_vertically = true;
      d.add(t);
      drawn.push_back(line);
      y += kLegendLine;
    }
  }
  return drawn;
}

double legend_height(const Plot& plot, double text_width) {
  std::size_t lines = 0;
  for (const auto& s : plot.series)
    if (in_legend(s)) lines += legend_lines(s, text_width).size();
  return double(lines) * kLegendLine;
}

}  // namespace

Drawing figure_drawing(const Figure& figure, std::vector<PanelLayout>* layout) {
  if (figure.panels.empty()) throw std::invalid_argument("a figure needs at least one panel");
  const Geometry g = geometry(figure);
  Drawing d;
  d.width = g.width;
  d.height = g.height;
  d.title = figure.title.empty() ? figure.panels.front().title : figure.title;
  const auto colours = name_indices(figure);
  const double text_w = legend_text_width(figure);
  const double panel_legend_w = g.shared ? 12 : g.legend_w;
  if (layout) layout->clear();
  for (std::size_t i = 0; i < figure.panels.size(); ++i) {
    const Plot& plot = figure.panels[i];
    const int r = int(i) / g.columns, c = int(i) % g.columns;
    const double px = c * figure.panel_width, py = g.title_h + r * figure.panel_height;
    // Every panel's plot area at the same place in its panel, so that stacked panels share
    // their axes' ends.
    const Area a{px + kLeftMargin, py + kTopMargin, px + figure.panel_width - panel_legend_w,
                 py + figure.panel_height - kBottomMargin};
    const auto xt = axis_ticks(plot, true), yt = axis_ticks(plot, false);
    const Scale sx(xt, plot.x.log, a.x0, a.x1), sy(yt, plot.y.log, a.y1, a.y0);
    draw_axes(d, plot, a, xt, yt, sx, sy, px);
    d.add(ClipBegin{a.x0, a.y0, a.x1, a.y1});
    for (const auto& s : plot.series) draw_series(d, s, sx, sy, series_colour(s, colours));
    d.add(ClipEnd{});

    PanelLayout l;
    l.plot_area = {float(a.x0), float(g.height - a.y1), float(a.x1), float(g.height - a.y0)};
    l.legend_inline = false;
    const bool own_legend =
        !g.shared && plot.legend && std::any_of(plot.series.begin(), plot.series.end(), in_legend);
    if (own_legend) {
      const double left = a.x1;
      l.legend_lines = draw_legend(d, plot, left, a.y0, text_w, colours);
      l.legend_shown = true;
      l.legend_point = {float(left + kLegendGap),
                        float(g.height - a.y0 - legend_height(plot, text_w))};
    }
    // The title centred over the plot area; one too wide for that (a run named by several
    // scene keys) goes across the whole panel, higher, and no further.
    const double plot_w = a.x1 - a.x0;
    auto fitted = fit_text(plot.title, int(plot_w + 8), kTitleFont, 10, true);
    double centre = 0.5 * (a.x0 + a.x1), baseline = py + kTopMargin - 9;
    if (fitted.text != plot.title) {
      fitted = fit_text(plot.title, figure.panel_width - 8, kTitleFont, 8, true);
      centre = px + 0.5 * figure.panel_width;
      baseline = py + fitted.size + 2;
    }
    d.add(Text{fitted.text, {centre, baseline}, double(fitted.size), true, Anchor::middle});
    l.title = fitted.text;
    l.title_font_size = fitted.size;
    if (layout) layout->push_back(l);
  }
  if (g.shared) {
    const double left = g.columns * figure.panel_width - 12;
    const auto lines =
        draw_legend(d, figure.panels.front(), left, g.title_h + kTopMargin, text_w, colours);
    if (layout)
      for (auto& l : *layout) {
        l.legend_shown = true;
        l.legend_lines = lines;
        l.legend_point = {float(left + kLegendGap),
                          float(g.height - g.title_h - kTopMargin -
                                legend_height(figure.panels.front(), text_w))};
      }
  }
  if (g.title_h > 0) {
    const auto fitted = fit_text(figure.title, int(g.width) - 16, 18, 8, true);
    Text t{
        fitted.text, {0.5 * g.width, 0.5 * g.title_h}, double(fitted.size), true, Anchor::middle};
    t.centred_vertically = true;
    d.add(t);
  }
  return d;
}

vtkSmartPointer<vtkImageData> render_figure(const Figure& figure) {
  return rasterize(figure_drawing(figure));
}

std::vector<PanelLayout> figure_layout(const Figure& figure) {
  std::vector<PanelLayout> layout;
  figure_drawing(figure, &layout);
  return layout;
}

}  // namespace sedem::render
