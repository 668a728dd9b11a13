#include "render/paper_figures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/physics/stokes.h"

namespace sedem::render {
namespace {

constexpr std::array<unsigned char, 3> kBlack = {0, 0, 0};

std::vector<double> scaled(const std::vector<double>& v, double factor) {
  std::vector<double> out(v.size());
  std::transform(v.begin(), v.end(), out.begin(), [factor](double x) { return x * factor; });
  return out;
}

std::string time_title(double t) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "t = %g s", t);
  return buf;
}

// Per-sample panels side by side, at most three per row.
Figure sample_grid(std::string title, std::vector<Plot> panels) {
  Figure f;
  f.title = std::move(title);
  f.columns = std::min<int>(3, std::max<int>(1, int(panels.size())));
  f.panel_width = 460;
  f.panel_height = 320;
  f.panels = std::move(panels);
  return f;
}

// Quantities against time stacked one above the other, sharing the time axis.
Figure time_stack(std::string title, std::vector<Plot> panels) {
  Figure f;
  f.title = std::move(title);
  f.columns = 1;
  f.panel_width = 760;
  f.panel_height = 280;
  f.panels = std::move(panels);
  return f;
}

PlotAxis time_axis() {
  return axis("time", "s", true);
}
PlotAxis diameter_axis(bool log = false) {
  return axis("diameter", "µm", log);
}
PlotAxis percent_finer_axis() {
  return axis("percent finer", "%");
}

template <class Series, class Member>
Plot against_time(const std::vector<Series>& samples, std::string title, PlotAxis y, Member member,
                  double factor, LegendCorner legend = LegendCorner::top_right) {
  Plot p;
  p.legend_corner = legend;
  p.title = std::move(title);
  p.x = time_axis();
  p.y = std::move(y);
  for (const auto& s : samples)
    p.series.emplace_back(s.sample, s.time_s, scaled(s.*member, factor),
                          SeriesStyle::line_and_points);
  return p;
}

}  // namespace

Figure fig12_largest_diameter(const LargestDiameterInput& in) {
  std::vector<double> times;
  for (const auto& s : in.samples)
    for (const auto& p : s.profiles)
      if (std::none_of(times.begin(), times.end(),
                       [&](double t) { return std::abs(t - p.time_s) <= 1e-9 * (1 + t); }))
        times.push_back(p.time_s);
  std::sort(times.begin(), times.end());

  std::vector<Plot> panels;
  for (double t : times) {
    Plot plot;
    plot.title = time_title(t);
    plot.x = axis("depth", "m", 0.0, in.column_height_m);
    plot.legend_corner = LegendCorner::bottom_right;
    plot.y = diameter_axis();
    for (const auto& s : in.samples)
      for (const auto& p : s.profiles)
        if (std::abs(p.time_s - t) <= 1e-9 * (1 + t))
          plot.series.emplace_back(s.sample, p.depth_m, scaled(p.largest_diameter_m, 1e6),
                                   SeriesStyle::dashed);
    PlotSeries eq16("Eq. 16", {}, {});
    eq16.color = kBlack;
    constexpr int n = 100;
    for (int i = 1; i <= n; ++i) {
      const double depth = in.column_height_m * i / n;
      eq16.x.push_back(depth);
      eq16.y.push_back(
          1e6 * stokes::limiting_diameter(depth, std::max(t, 1e-9), in.particle_density, in.fluid));
    }
    plot.series.push_back(std::move(eq16));
    panels.push_back(std::move(plot));
  }
  Figure f = sample_grid("Largest diameter above each depth, and Eq. 16", std::move(panels));
  f.columns = std::min<int>(2, std::max<int>(1, int(f.panels.size())));
  return f;
}

Figure fig13_bulb_density(const std::vector<SampleBulbDensity>& samples) {
  std::vector<Plot> panels;
  for (const auto& s : samples) {
    Plot plot;
    plot.title = s.sample;
    plot.x = axis("position along the bulb from its top", "cm");
    plot.y = axis("suspension density", "kg/m3");
    for (const auto& p : s.profiles)
      plot.series.emplace_back(time_title(p.time_s), scaled(p.position_m, 100.0), p.density_kg_m3,
                               SeriesStyle::line);
    panels.push_back(std::move(plot));
  }
  return sample_grid("Suspension density along the hydrometer bulb", std::move(panels));
}

Figure fig14_bulb_average(const std::vector<BulbAverageSeries>& samples) {
  std::vector<Plot> panels;
  for (const auto& s : samples) {
    Plot plot;
    plot.title = s.sample;
    plot.x = time_axis();
    plot.y = axis("average density along the bulb", "kg/m3");
    PlotSeries eq19("Eq. 19", s.time_s, s.eq19_kg_m3, SeriesStyle::line);
    eq19.color = kBlack;
    plot.series.push_back(std::move(eq19));
    plot.series.emplace_back("simulation", s.time_s, s.simulated_kg_m3, SeriesStyle::points);
    panels.push_back(std::move(plot));
  }
  return sample_grid("Bulb average density: simulation and Eq. 19", std::move(panels));
}

Figure fig15_hydrometer(const std::vector<HydrometerSeries>& samples) {
  return time_stack(
      "Hydrometer test (ASTM D422)",
      {against_time(samples, "Depth of the bulb's centre", axis("depth", "cm"),
                    &HydrometerSeries::centre_depth_m, 100.0, LegendCorner::bottom_right),
       against_time(samples, "Limiting diameter (Eq. 16)", diameter_axis(),
                    &HydrometerSeries::diameter_m, 1e6),
       against_time(samples, "Accumulated weight (Eq. 18)", percent_finer_axis(),
                    &HydrometerSeries::percent_finer, 1.0)});
}

Figure fig16_buoyancy(const std::vector<BuoyancySeries>& samples) {
  return time_stack(
      "Buoyancy test",
      {against_time(samples, "Apparent mass of the sphere", axis("apparent mass", "g"),
                    &BuoyancySeries::apparent_mass_kg, 1e3, LegendCorner::bottom_right),
       against_time(samples, "Limiting diameter (Eq. 16)", diameter_axis(),
                    &BuoyancySeries::diameter_m, 1e6),
       against_time(samples, "Accumulated weight (Eq. 22)", percent_finer_axis(),
                    &BuoyancySeries::percent_finer, 1.0)});
}

Figure fig17_pipette(const std::vector<PipetteSeries>& samples) {
  return time_stack("Pipette test",
                    {against_time(samples, "Limiting diameter (Eq. 16)", diameter_axis(),
                                  &PipetteSeries::diameter_m, 1e6),
                     against_time(samples, "Accumulated weight (Eq. 17)", percent_finer_axis(),
                                  &PipetteSeries::percent_finer, 1.0)});
}

Figure fig18_granulometry(const std::vector<SampleGrading>& samples) {
  std::vector<Plot> panels;
  for (const auto& s : samples) {
    Plot plot;
    plot.title = s.sample;
    plot.x = axis("diameter", "µm", 1.0, 100.0, true);
    plot.y = axis("percent finer", "%", 0.0, 110.0);
    plot.legend_corner = LegendCorner::top_left;
    PlotSeries truth(s.truth.name.empty() ? "true" : s.truth.name, s.truth.diameter_m,
                     s.truth.percent_finer, SeriesStyle::line);
    truth.x = scaled(truth.x, 1e6);
    truth.color = kBlack;
    plot.series.push_back(std::move(truth));
    for (std::size_t i = 0; i < s.tests.size(); ++i) {
      const auto color = palette_color(i);
      PlotSeries test(s.tests[i].name, scaled(s.tests[i].diameter_m, 1e6), s.tests[i].percent_finer,
                      SeriesStyle::line_and_points);
      test.color = color;
      plot.series.push_back(std::move(test));
      if (i < s.references.size()) {
        PlotSeries ref(s.references[i].name, scaled(s.references[i].diameter_m, 1e6),
                       s.references[i].percent_finer, SeriesStyle::dashed);
        ref.color = color;
        plot.series.push_back(std::move(ref));
      }
    }
    panels.push_back(std::move(plot));
  }
  return sample_grid("Grading curves: tests against the true distribution", std::move(panels));
}

void write_fig12(const LargestDiameterInput& input, const std::filesystem::path& dir) {
  write_figure(fig12_largest_diameter(input), dir / kFig12Name);
}
void write_fig13(const std::vector<SampleBulbDensity>& input, const std::filesystem::path& dir) {
  write_figure(fig13_bulb_density(input), dir / kFig13Name);
}
void write_fig14(const std::vector<BulbAverageSeries>& input, const std::filesystem::path& dir) {
  write_figure(fig14_bulb_average(input), dir / kFig14Name);
}
void write_fig15(const std::vector<HydrometerSeries>& input, const std::filesystem::path& dir) {
  write_figure(fig15_hydrometer(input), dir / kFig15Name);
}
void write_fig16(const std::vector<BuoyancySeries>& input, const std::filesystem::path& dir) {
  write_figure(fig16_buoyancy(input), dir / kFig16Name);
}
void write_fig17(const std::vector<PipetteSeries>& input, const std::filesystem::path& dir) {
  write_figure(fig17_pipette(input), dir / kFig17Name);
}
void write_fig18(const std::vector<SampleGrading>& input, const std::filesystem::path& dir) {
  write_figure(fig18_granulometry(input), dir / kFig18Name);
}

}  // namespace sedem::render
