#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <vtkImageData.h>
#include <vtkSmartPointer.h>

#include "render/drawing/drawing.h"
#include "render/drawing/figure_files.h"

namespace sedem::render {

// A generic 2D plot described by plain data, laid out as a Drawing (so that PNG, SVG and PDF
// show the same picture) and written with the same numbers as CSV, so every picture can be
// replotted elsewhere.

// band: a filled area between `y_low` and `y` (a spread), translucent, not in the legend.
enum class SeriesStyle { line, dashed, points, line_and_points, band };

struct PlotAxis {
  std::string quantity;  // shown on the axis as "quantity (unit)"
  std::string unit;      // user-facing unit, e.g. "s", "µm", "%"
  std::string column;    // CSV column name; empty: derived, e.g. "time_s", "diameter_um"
  bool log = false;
  std::optional<std::pair<double, double>> range;  // fixed; otherwise fitted to the data

  std::string title() const;        // "diameter (µm)"
  std::string column_name() const;  // `column`, or quantity and unit as an identifier
};

PlotAxis axis(std::string quantity, std::string unit, bool log = false);
PlotAxis axis(std::string quantity, std::string unit, double min, double max, bool log = false);

struct PlotSeries {
  PlotSeries() = default;
  PlotSeries(std::string name, std::vector<double> x, std::vector<double> y,
             SeriesStyle style = SeriesStyle::line)
      : name(std::move(name)), x(std::move(x)), y(std::move(y)), style(style) {}

  std::string name;  // legend entry
  std::vector<double> x, y;
  std::vector<double> y_low;  // SeriesStyle::band only: the band's lower edge
  SeriesStyle style = SeriesStyle::line;
  // RGB; when unset the colour follows the series' name, so one name has one colour in
  // every panel of a figure.
  std::optional<std::array<unsigned char, 3>> color;
};

struct Plot {
  std::string title;
  PlotAxis x, y;
  std::vector<PlotSeries> series;
  bool legend = true;  // right of the plot area, outside the data, its top level with it
};

// An axis' range and ticks as drawn: linear axes end on whole steps of 1, 2 or 5 times a
// power of ten (unless the range is fixed) and label each tick with the decimals the step
// needs, so no two labels are alike; log axes label their decades (1, 2 and 5 within them
// when they span fewer than two), so labels never run together.
struct AxisTicks {
  std::pair<double, double> range;
  std::vector<double> at;
  std::vector<std::string> labels;
};
AxisTicks axis_ticks(const Plot& plot, bool x);

// Several plots in one image: a grid of `columns` panels per row, filled row by row, with
// the figure's title above. One panel is a single plot. Panels whose legends list the same
// entries share one legend, right of the grid.
struct Figure {
  std::string title;
  std::vector<Plot> panels;
  int columns = 1;
  int panel_width = 480;  // pixels; keep the whole image at most 1600 wide
  int panel_height = 360;
  // A line written as a comment ("# ...") above the CSV's header, e.g. that the figure is of a
  // partial run; empty: none.
  std::string csv_note;
};

// A figure holding one plot.
Figure single_plot(Plot plot, int width = 640, int height = 440);

// The figure laid out in logical pixels; with `layout`, where each panel put what.
struct PanelLayout;
Drawing figure_drawing(const Figure& figure, std::vector<PanelLayout>* layout = nullptr);

// The figure rasterised at its logical size (one pixel per logical pixel), as RGB.
vtkSmartPointer<vtkImageData> render_figure(const Figure& figure);

// Where a figure's panels put their data and legends (logical pixels, origin bottom left):
// the plot area between the axes, and the legend's anchor (its lower-left corner).
struct PanelLayout {
  std::array<float, 4> plot_area;  // x0, y0, x1, y1
  bool legend_shown = false;
  bool legend_inline = false;
  std::array<float, 2> legend_point{};
  std::string title;  // as drawn: shrunk to fit the panel, its middle cut when even that fails
  int title_font_size = 0;
  std::vector<std::string> legend_lines;  // as drawn: long entries wrapped onto several lines
};
std::vector<PanelLayout> figure_layout(const Figure& figure);

// CSV: two columns per series, "<series>:<x column>" and "<series>:<y column>", prefixed
// with "<panel title>/" when the figure has more than one panel; shorter series leave their
// cells empty. Numbers with 9 significant digits.
void write_figure_csv(const Figure& figure, const std::filesystem::path& file);

// Writes `<base>.<format>` for each of `output`'s formats and `<base>.csv`; returns the files.
std::vector<std::filesystem::path> write_figure(const Figure& figure,
                                                const std::filesystem::path& base,
                                                const FigureOutput& output = {});

// The colour given to the i-th distinct series name (a fixed, colour-blind friendly list).
std::array<unsigned char, 3> palette_color(std::size_t i);

}  // namespace sedem::render
