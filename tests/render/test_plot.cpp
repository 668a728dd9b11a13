#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "render/image_compare.h"
#include "render/offscreen_view.h"
#include "render/plot.h"
#include "render/text_fit.h"
#include "render_test_support.h"

namespace sedem {
namespace {

render::Plot sample_plot() {
  render::Plot p;
  p.title = "Settling";
  p.x = render::axis("time", "s", 1.0, 1000.0, true);
  p.y = render::axis("percent finer", "%", 0.0, 100.0);
  render::PlotSeries decay("decay", {}, {});
  render::PlotSeries readings("readings", {}, {}, render::SeriesStyle::points);
  for (int i = 0; i <= 30; ++i) {
    const double t = std::pow(10.0, 0.1 * i);
    decay.x.push_back(t);
    decay.y.push_back(100.0 * std::exp(-t / 200.0));
  }
  for (double t : {2.0, 5.0, 15.0, 30.0, 60.0, 250.0}) {
    readings.x.push_back(t);
    readings.y.push_back(100.0 * std::exp(-t / 200.0) - 3.0);
  }
  p.series = {decay, readings};
  return p;
}

TEST(Plot, ColumnNamesCarryTheUnit) {
  EXPECT_EQ(render::axis("time", "s").column_name(), "time_s");
  EXPECT_EQ(render::axis("diameter", "µm").column_name(), "diameter_um");
  EXPECT_EQ(render::axis("finer", "%").column_name(), "percent_finer");
  EXPECT_EQ(render::axis("density", "kg/m3").column_name(), "density_kg_m3");
  EXPECT_EQ(render::axis("apparent mass", "g").column_name(), "apparent_mass_g");
  auto named = render::axis("density", "kg/m³");
  named.column = "density_kg_m3";
  EXPECT_EQ(named.column_name(), "density_kg_m3");
  EXPECT_EQ(render::axis("time", "s").title(), "time (s)");
}

TEST(Plot, SinglePlotMatchesBaseline) {
  auto image = render::render_figure(render::single_plot(sample_plot(), 560, 400));
  int dims[3];
  image->GetDimensions(dims);
  EXPECT_EQ(dims[0], 560);
  EXPECT_EQ(dims[1], 400);
  auto result =
      render::compare_with_baseline(image, test::baseline("plot_single.png"), test::output_dir());
  EXPECT_TRUE(result.passed) << result.message;
}

TEST(Plot, PanelsMatchBaseline) {
  render::Figure f;
  f.title = "Two samples";
  f.columns = 2;
  f.panel_width = 400;
  f.panel_height = 300;
  auto a = sample_plot();
  a.title = "sample 1";
  auto b = sample_plot();
  b.title = "sample 2";
  for (auto& y : b.series[0].y) y *= 0.5;
  b.series[1].style = render::SeriesStyle::dashed;
  f.panels = {a, b};
  auto image = render::render_figure(f);
  int dims[3];
  image->GetDimensions(dims);
  EXPECT_EQ(dims[0], 800);
  EXPECT_EQ(dims[1], 334);
  auto result =
      render::compare_with_baseline(image, test::baseline("plot_panels.png"), test::output_dir());
  EXPECT_TRUE(result.passed) << result.message;
}

TEST(Plot, CsvHoldsEverySeriesWithUnits) {
  render::Figure f;
  f.panels = {sample_plot(), sample_plot()};
  f.panels[0].title = "sample 1";
  f.panels[1].title = "sample 2";
  const auto base = test::output_dir() / "plot_csv" / "figure";
  std::filesystem::remove_all(base.parent_path());
  render::write_figure(f, base);
  EXPECT_TRUE(std::filesystem::exists(test::output_dir() / "plot_csv" / "figure.png"));
  std::ifstream in(test::output_dir() / "plot_csv" / "figure.csv");
  std::string header, first, line;
  std::getline(in, header);
  std::getline(in, first);
  EXPECT_EQ(header,
            "sample 1/decay:time_s,sample 1/decay:percent_finer,sample 1/readings:time_s,"
            "sample 1/readings:percent_finer,sample 2/decay:time_s,sample 2/decay:percent_finer,"
            "sample 2/readings:time_s,sample 2/readings:percent_finer");
  EXPECT_EQ(first, "1,99.5012479,2,96.0049834,1,99.5012479,2,96.0049834");
  int rows = 1;
  std::string last = first;
  while (std::getline(in, line)) ++rows, last = line;
  EXPECT_EQ(rows, 31);  // the longest series
  EXPECT_EQ(last, "1000,0.6737947,,,1000,0.6737947,,");
}

TEST(Plot, SvgHoldsTheFigureAsVectorGraphics) {
  render::Figure f = render::single_plot(sample_plot(), 560, 400);
  f.title = "Settling in kg/m³";
  const auto base = test::output_dir() / "plot_svg" / "figure";
  std::filesystem::remove_all(base.parent_path());
  render::write_figure(f, base, test::kEveryFormat);
  auto svg = base;
  svg += ".svg";
  ASSERT_TRUE(std::filesystem::exists(svg));
  const auto text = test::read_text(svg);
  EXPECT_NE(text.find("<svg"), std::string::npos);
  EXPECT_NE(text.find("Settling"), std::string::npos);       // the panel's title as text
  EXPECT_NE(text.find("percent finer"), std::string::npos);  // an axis title
  EXPECT_NE(text.find("<polyline"), std::string::npos);      // the curves as lines
  // The figure's title as text in the picture, not only as the document's <title>.
  const auto title = text.find("Settling in kg/m³");
  ASSERT_NE(title, std::string::npos);
  EXPECT_NE(text.find("Settling in kg/m³", title + 1), std::string::npos);
  auto png = base;
  png += ".png";
  EXPECT_TRUE(std::filesystem::exists(png));
}

TEST(Plot, LegendsSitOutsideThePlotArea) {
  render::Figure f;
  f.columns = 2;
  f.panels = {sample_plot(), sample_plot()};
  const auto layout = render::figure_layout(f);
  ASSERT_EQ(layout.size(), 2u);
  for (const auto& l : layout) {
    EXPECT_TRUE(l.legend_shown);
    EXPECT_FALSE(l.legend_inline);
    EXPECT_GT(l.legend_point[0], l.plot_area[2]);  // right of the x axis' end
  }
  // The right panel's legend stays inside its own panel.
  EXPECT_LT(layout[1].legend_point[0], 2.0f * float(f.panel_width));
}

// What `sedem render` names runs that differ in three scene keys.
const std::string kLongRun =
    "integrator.local_steps=false, sample.seed=8, sample.simulated_count=3000";

render::Figure long_names_figure() {
  render::Figure f;
  f.columns = 2;
  f.panel_width = 520;
  f.panel_height = 340;
  for (int k = 0; k < 2; ++k) {
    auto p = sample_plot();
    p.title = kLongRun;
    p.series[0].name = kLongRun;
    p.series[1].name = "integrator.local_steps=true, sample.seed=7, sample.simulated_count=1500";
    f.panels.push_back(p);
  }
  return f;
}

std::string without_spaces(std::string s) {
  std::erase(s, ' ');
  return s;
}

TEST(Plot, LongLegendEntriesWrapBesideTheData) {
  auto f = long_names_figure();
  // The second panel's curves differ, so each panel keeps a legend of its own.
  f.panels[1].series[1].style = render::SeriesStyle::dashed;
  const auto layout = render::figure_layout(f);
  ASSERT_EQ(layout.size(), 2u);
  for (std::size_t i = 0; i < layout.size(); ++i) {
    const auto& l = layout[i];
    // The plot area keeps most of its panel (one line per name left it none).
    EXPECT_GT(l.plot_area[2] - l.plot_area[0], 0.4f * float(f.panel_width)) << i;
    EXPECT_GT(l.legend_point[0], l.plot_area[2]) << i;
    // Every line ends inside the panel: the legend's padding and line sample, then its text.
    const float right = float((i + 1) * std::size_t(f.panel_width));
    for (const auto& line : l.legend_lines)
      EXPECT_LE(l.legend_point[0] + 35.0f + float(render::text_width(line, 11)), right) << line;
    // Nothing of the names is lost.
    std::string joined;
    for (const auto& line : l.legend_lines) joined += line;
    EXPECT_EQ(without_spaces(joined),
              without_spaces(f.panels[i].series[0].name + f.panels[i].series[1].name));
  }
}

TEST(Plot, PanelTitlesStayWithinTheirPanel) {
  auto f = long_names_figure();
  for (auto& p : f.panels) p.series = sample_plot().series;  // the titles alone are long
  const auto image = render::render_figure(f);
  int dims[3];
  image->GetDimensions(dims);
  // The panels' title band: below the figure's title (none here), above the plot areas.
  const int top = dims[1], bottom = dims[1] - 24;
  EXPECT_EQ(test::dark_pixels(image, 0, 3, bottom, top), 0);  // not cut at the image's edge
  EXPECT_EQ(test::dark_pixels(image, dims[0] - 3, dims[0], bottom, top), 0);
  // The two titles do not meet at the panels' boundary.
  EXPECT_EQ(test::dark_pixels(image, f.panel_width - 3, f.panel_width + 3, bottom, top), 0);
  EXPECT_GT(test::dark_pixels(image, 0, dims[0], bottom, top), 200);  // but they are drawn
  for (const auto& l : render::figure_layout(f)) {
    EXPECT_GE(l.title_font_size, 8);
    EXPECT_EQ(l.title, kLongRun);  // whole: a panel's width holds three keys
  }
  // Titles too wide for the plot area are drawn in the charts' scene: the SVG has them.
  const auto base = test::output_dir() / "plot_long_titles";
  render::write_figure(f, base, test::kEveryFormat);
  auto svg = base;
  svg += ".svg";
  EXPECT_NE(test::read_text(svg).find(kLongRun), std::string::npos);
}

std::vector<std::string> labels_of(double lo, double hi, bool log) {
  render::Plot p;
  p.x = render::axis("x", "", lo, hi, log);
  p.y = render::axis("y", "", 0.0, 1.0);
  return render::axis_ticks(p, true).labels;
}

TEST(Plot, TickLabelsNeitherRepeatNorRunTogether) {
  // A density axis 0.02 kg/m³ tall: VTK's own labels read 1012.41, 1012.41.
  const auto narrow = labels_of(1012.40, 1012.42, false);
  ASSERT_GE(narrow.size(), 3u);
  for (std::size_t i = 1; i < narrow.size(); ++i) EXPECT_NE(narrow[i], narrow[i - 1]);
  EXPECT_EQ(narrow.front(), "1012.400");
  // A log time axis: decades only, no 20000 and 50000 beside 100000.
  EXPECT_EQ(labels_of(10, 1e5, true),
            (std::vector<std::string>{"10", "100", "1000", "10000", "100000"}));
  EXPECT_EQ(labels_of(1, 10, true), (std::vector<std::string>{"1", "2", "5", "10"}));
  EXPECT_EQ(labels_of(0, 110, false),
            (std::vector<std::string>{"0", "20", "40", "60", "80", "100"}));
}

TEST(Plot, DrawsCurvesOnANarrowAxisFarFromZero) {
  // 1000.0 to 1000.3 kg/m³ (a coarse sample's bulb average): VTK 9.1's charts drew nothing.
  for (bool fixed : {false, true}) {
    render::Plot p;
    p.x = render::axis("time", "s", true);
    p.y = render::axis("density", "kg/m³");
    if (fixed) p.y.range = std::pair{999.5, 1000.8};
    render::PlotSeries s("bulb", {}, {}, render::SeriesStyle::line_and_points);
    for (double t : {120.0, 300.0, 900.0, 1800.0, 3600.0, 15000.0, 86400.0}) {
      s.x.push_back(t);
      s.y.push_back(1000 + 0.3 * std::exp(-t / 300));
    }
    s.color = std::array<unsigned char, 3>{255, 0, 0};
    p.series = {s};
    p.legend = false;
    const auto image = render::render_figure(render::single_plot(p));
    EXPECT_GT(test::pixels_of(image, {255, 0, 0}, 0, 640), 400) << fixed;
  }
}

}  // namespace
}  // namespace sedem
