#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "render/image_compare.h"
#include "render/offscreen_view.h"
#include "render/plot.h"
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
  render::write_figure(f, base, true);
  auto svg = base;
  svg += ".svg";
  ASSERT_TRUE(std::filesystem::exists(svg));
  const auto text = test::read_text(svg);
  EXPECT_NE(text.find("<svg"), std::string::npos);
  EXPECT_NE(text.find("Settling"), std::string::npos);       // the panel's title as text
  EXPECT_NE(text.find("percent finer"), std::string::npos);  // an axis title
  EXPECT_NE(text.find("<path"), std::string::npos);          // the curves as paths
  auto png = base;
  png += ".png";
  EXPECT_TRUE(std::filesystem::exists(png));
}

}  // namespace
}  // namespace sedem
