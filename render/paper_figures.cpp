#include "render/paper_figures.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "core/model/spread.h"
#include "core/physics/stokes.h"

namespace sedem::render {
namespace {

constexpr std::array<unsigned char, 3> kBlackRgb = {0, 0, 0};

std::vector<double> scaled(const std::vector<double>& v, double factor) {
  std::vector<double> out(v.size());
  std::transform(v.begin(), v.end(), out.begin(), [factor](double x) { return x * factor; });
  return out;
}

// Halfway to white.
std::array<unsigned char, 3> lighter(std::array<unsigned char, 3> c) {
  for (auto& v : c) v = static_cast<unsigned char>((int(v) + 255) / 2);
  return c;
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
  f.panels = std::move(panels);
  // The legend beside the plot area; a lone panel (one run) wider, so that its plot keeps
  // most of the picture.
  f.panel_width = f.panels.size() == 1 ? 700 : 520;
  f.panel_height = 320;
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
// Percent finer from 0 to 110 %: the whole curve with a margin above 100 %, never below 0.
PlotAxis percent_finer_axis() {
  return axis("percent finer", "%", 0.0, 110.0);
}

// A grading curve of a few discrete sizes is a staircase: the percent finer jumps at each
// size and stays flat between two sizes (0 below the smallest).
constexpr std::size_t kStepCurveBelow = 30;
void as_steps(PlotSeries& s) {
  if (s.x.size() >= kStepCurveBelow || s.x.empty()) return;
  std::vector<double> x, y;
  double previous = 0;
  for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
    x.push_back(s.x[i]);
    y.push_back(previous);
    x.push_back(s.x[i]);
    y.push_back(s.y[i]);
    previous = s.y[i];
  }
  s.x = std::move(x);
  s.y = std::move(y);
}

// Every curve (and band) inside the y axis with a margin, none on its limits; at least
// 1 kg/m^3 (or unit) tall, so that tick labels never repeat.
void fit_y_range(Plot& plot) {
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (const auto& series : plot.series)
    for (const auto* v : {&series.y, &series.y_low})
      for (double y : *v)
        if (std::isfinite(y)) lo = std::min(lo, y), hi = std::max(hi, y);
  if (lo <= hi) {
    const double pad = std::max(0.08 * (hi - lo), 0.5);
    plot.y.range = std::pair{lo - pad, hi + pad};
  }
}

// True when every series has the same times and values as the first, within `tolerance` of
// the values' spread: then one curve stands for all of them.
bool all_coincide(const std::vector<PlotSeries>& series) {
  if (series.size() < 2) return false;
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (const auto& s : series)
    for (double y : s.y) lo = std::min(lo, y), hi = std::max(hi, y);
  const double tolerance = 1e-3 * std::max(hi - lo, 1e-12 * std::max(std::abs(hi), 1.0));
  const auto& first = series.front();
  for (const auto& s : series) {
    if (s.x.size() != first.x.size() || s.y.size() != first.y.size()) return false;
    for (std::size_t i = 0; i < s.x.size(); ++i)
      if (std::abs(s.x[i] - first.x[i]) > 1e-9 * std::max(1.0, std::abs(first.x[i]))) return false;
    for (std::size_t i = 0; i < s.y.size(); ++i)
      if (!(std::abs(s.y[i] - first.y[i]) <= tolerance)) return false;
  }
  return true;
}

template <class Series, class Member>
Plot against_time(const std::vector<Series>& samples, std::string title, PlotAxis y, Member member,
                  double factor) {
  Plot p;
  p.title = std::move(title);
  p.x = time_axis();
  p.y = std::move(y);
  for (const auto& s : samples)
    p.series.emplace_back(s.sample, s.time_s, scaled(s.*member, factor),
                          SeriesStyle::line_and_points);
  // The samples' curves on top of one another (the limiting diameter at a fixed depth
  // depends on time alone) show as one, in black, named for what it stands for.
  if (all_coincide(p.series)) {
    PlotSeries all(kAllSamples, p.series.front().x, p.series.front().y,
                   SeriesStyle::line_and_points);
    all.color = kBlackRgb;
    p.series = {std::move(all)};
    p.title += ", " + std::string(kAllSamples);
  }
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
  // A panel per time makes an image of thousands of panels of thousands of times, which no
  // one reads and no image format holds: that many spread over them.
  if (times.size() > kFig12MaxPanels) {
    std::vector<double> shown;
    for (std::size_t i : spread_indices(times.size(), kFig12MaxPanels)) shown.push_back(times[i]);
    times = std::move(shown);
  }

  std::vector<Plot> panels;
  for (double t : times) {
    Plot plot;
    plot.title = time_title(t);
    // Depth in cm, as in Figs. 11 and 15.
    plot.x = axis("depth", "cm", 0.0, 100.0 * in.column_height_m);
    plot.y = diameter_axis();
    for (const auto& s : in.samples)
      for (const auto& p : s.profiles)
        if (std::abs(p.time_s - t) <= 1e-9 * (1 + t))
          plot.series.emplace_back(s.sample, scaled(p.depth_m, 100.0),
                                   scaled(p.largest_diameter_m, 1e6), SeriesStyle::dashed);
    PlotSeries eq16("Eq. 16", {}, {});
    eq16.color = kBlackRgb;
    constexpr int n = 100;
    for (int i = 1; i <= n; ++i) {
      const double depth = in.column_height_m * i / n;
      eq16.x.push_back(100.0 * depth);
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

int fig13_band_count(const SampleBulbDensity& s) {
  double length = 0;
  for (const auto& p : s.profiles)
    for (double x : p.position_m) length = std::max(length, x);
  if (s.simulated_count <= 0 || s.column_height_m <= 0) return 40;
  const double along = s.simulated_count * length / s.column_height_m;
  return std::clamp(int(along / kFig13GrainsPerBand), 2, 40);
}

namespace {

// The i-th of n times on a perceptually uniform sequential map (viridis, from dark purple to
// yellow-green, its lightest tenth left out so that the last curve still shows on white):
// neighbouring times differ as much in lightness as in hue, seven of them stay apart.
std::array<unsigned char, 3> ramp_color(std::size_t i, std::size_t n) {
  static constexpr std::array<std::array<double, 3>, 9> kViridis = {{{68, 1, 84},
                                                                     {71, 44, 122},
                                                                     {59, 81, 139},
                                                                     {44, 113, 142},
                                                                     {33, 144, 141},
                                                                     {39, 173, 129},
                                                                     {92, 200, 99},
                                                                     {170, 220, 50},
                                                                     {253, 231, 37}}};
  const double f = 0.9 * (n > 1 ? double(i) / double(n - 1) : 0.0) * (kViridis.size() - 1);
  const std::size_t k = std::min(std::size_t(f), kViridis.size() - 2);
  const double u = f - double(k);
  std::array<unsigned char, 3> out;
  for (int c = 0; c < 3; ++c)
    out[c] = static_cast<unsigned char>(
        std::lround(kViridis[k][c] + u * (kViridis[k + 1][c] - kViridis[k][c])));
  return out;
}

// The band means of one profile and their standard errors, bands of equal length over
// [0, length].
struct BandProfile {
  std::vector<double> centre, mean, low, high;
};
BandProfile band_means(const BulbDensityProfile& p, int bands, double length) {
  std::vector<double> sum(std::size_t(bands), 0.0), sq(sum), count(sum);
  const std::size_t n = std::min(p.position_m.size(), p.density_kg_m3.size());
  for (std::size_t i = 0; i < n; ++i) {
    const int k = std::clamp(int(p.position_m[i] / length * bands), 0, bands - 1);
    sum[std::size_t(k)] += p.density_kg_m3[i];
    sq[std::size_t(k)] += p.density_kg_m3[i] * p.density_kg_m3[i];
    count[std::size_t(k)] += 1;
  }
  BandProfile out;
  for (std::size_t k = 0; k < sum.size(); ++k) {
    if (count[k] == 0) continue;
    const double mean = sum[k] / count[k];
    const double var =
        count[k] > 1 ? std::max(0.0, (sq[k] - count[k] * mean * mean) / (count[k] - 1)) : 0.0;
    const double se = std::sqrt(var / count[k]);
    out.centre.push_back(100.0 * length * (double(k) + 0.5) / bands);  // cm
    out.mean.push_back(mean);
    out.low.push_back(mean - se);
    out.high.push_back(mean + se);
  }
  return out;
}

}  // namespace

Figure fig13_bulb_density(const std::vector<SampleBulbDensity>& samples) {
  std::vector<Plot> panels;
  for (const auto& s : samples) {
    double length = 0;
    for (const auto& p : s.profiles)
      for (double x : p.position_m) length = std::max(length, x);
    const int bands = fig13_band_count(s);
    char unit[64];
    std::snprintf(unit, sizeof unit, "cm; bands of %.2g cm", 100.0 * length / bands);
    Plot plot;
    plot.title = s.sample;
    // To the bulb's tip at the nearest millimetre: the last layer's centre falls a hair short
    // of it (13.998 cm), which dropped the axis' end label (14).
    plot.x = axis("distance below the bulb's top", unit, 0.0, std::round(1000.0 * length) / 10.0);
    plot.x.column = "position_along_the_bulb_cm";
    plot.y = axis("suspension density", "kg/m³");
    if (s.homogeneous_kg_m3 > 0) {
      char name[64];
      std::snprintf(name, sizeof name, "homogeneous suspension");
      PlotSeries t0(name, {0.0, 100.0 * length}, {s.homogeneous_kg_m3, s.homogeneous_kg_m3},
                    SeriesStyle::dashed);
      t0.color = kBlackRgb;
      plot.series.push_back(std::move(t0));
    }
    for (std::size_t i = 0; i < s.profiles.size(); ++i) {
      const auto& p = s.profiles[i];
      const auto b = band_means(p, bands, length > 0 ? length : 1.0);
      const auto color = ramp_color(i, s.profiles.size());
      PlotSeries spread(time_title(p.time_s) + " spread", b.centre, b.high, SeriesStyle::band);
      spread.y_low = b.low;
      spread.color = color;
      plot.series.push_back(std::move(spread));
      PlotSeries mean(time_title(p.time_s), b.centre, b.mean, SeriesStyle::line_and_points);
      mean.color = color;
      plot.series.push_back(std::move(mean));
    }
    fit_y_range(plot);
    panels.push_back(std::move(plot));
  }
  return sample_grid("Density along the bulb: band means, shaded \u00b1 one standard error",
                     std::move(panels));
}

Figure fig14_bulb_average(const std::vector<BulbAverageSeries>& samples) {
  std::vector<Plot> panels;
  for (const auto& s : samples) {
    Plot plot;
    plot.title = s.sample;
    plot.x = time_axis();
    plot.y = axis("average density along the bulb", "kg/m³");
    PlotSeries eq19("Eq. 19", s.time_s, s.eq19_kg_m3, SeriesStyle::line);
    eq19.color = kBlackRgb;
    plot.series.push_back(std::move(eq19));
    plot.series.emplace_back("simulation", s.time_s, s.simulated_kg_m3, SeriesStyle::points);
    fit_y_range(plot);
    panels.push_back(std::move(plot));
  }
  return sample_grid("Bulb average density: simulation and Eq. 19", std::move(panels));
}

Figure fig15_hydrometer(const std::vector<HydrometerSeries>& samples) {
  return time_stack("Hydrometer test (ASTM D422)",
                    {against_time(samples, "Depth of the bulb's centre", axis("depth", "cm"),
                                  &HydrometerSeries::centre_depth_m, 100.0),
                     against_time(samples, "Limiting diameter (Eq. 16)", diameter_axis(),
                                  &HydrometerSeries::diameter_m, 1e6),
                     against_time(samples, "Accumulated weight (Eq. 18)", percent_finer_axis(),
                                  &HydrometerSeries::percent_finer, 1.0)});
}

Figure fig16_buoyancy(const std::vector<BuoyancySeries>& samples) {
  return time_stack(
      "Buoyancy test",
      {against_time(samples, "Apparent mass of the sphere", axis("apparent mass", "g"),
                    &BuoyancySeries::apparent_mass_kg, 1e3),
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
    plot.y = percent_finer_axis();
    PlotSeries truth(s.truth.name.empty() ? "true" : s.truth.name, s.truth.diameter_m,
                     s.truth.percent_finer, SeriesStyle::line);
    truth.x = scaled(truth.x, 1e6);
    truth.color = kBlackRgb;
    as_steps(truth);
    plot.series.push_back(std::move(truth));
    for (std::size_t i = 0; i < s.tests.size(); ++i) {
      const auto color = palette_color(i);
      PlotSeries test(s.tests[i].name, scaled(s.tests[i].diameter_m, 1e6), s.tests[i].percent_finer,
                      SeriesStyle::line_and_points);
      test.color = color;
      plot.series.push_back(std::move(test));
      if (i < s.references.size()) {
        // Told apart from the test by style and by tone: dashed, in a lighter tint.
        PlotSeries ref(s.references[i].name, scaled(s.references[i].diameter_m, 1e6),
                       s.references[i].percent_finer, SeriesStyle::dashed);
        ref.color = lighter(color);
        plot.series.push_back(std::move(ref));
      }
    }
    panels.push_back(std::move(plot));
  }
  return sample_grid("Grading curves: tests against the true distribution", std::move(panels));
}

void write_fig12(const LargestDiameterInput& input, const std::filesystem::path& dir,
                 const FigureOutput& output) {
  write_figure(fig12_largest_diameter(input), dir / kFig12Name, output);
}
void write_fig13(const std::vector<SampleBulbDensity>& input, const std::filesystem::path& dir,
                 const FigureOutput& output) {
  write_figure(fig13_bulb_density(input), dir / kFig13Name, output);
}
void write_fig14(const std::vector<BulbAverageSeries>& input, const std::filesystem::path& dir,
                 const FigureOutput& output) {
  write_figure(fig14_bulb_average(input), dir / kFig14Name, output);
}
void write_fig15(const std::vector<HydrometerSeries>& input, const std::filesystem::path& dir,
                 const FigureOutput& output) {
  write_figure(fig15_hydrometer(input), dir / kFig15Name, output);
}
void write_fig16(const std::vector<BuoyancySeries>& input, const std::filesystem::path& dir,
                 const FigureOutput& output) {
  write_figure(fig16_buoyancy(input), dir / kFig16Name, output);
}
void write_fig17(const std::vector<PipetteSeries>& input, const std::filesystem::path& dir,
                 const FigureOutput& output) {
  write_figure(fig17_pipette(input), dir / kFig17Name, output);
}
void write_fig18(const std::vector<SampleGrading>& input, const std::filesystem::path& dir,
                 const FigureOutput& output) {
  write_figure(fig18_granulometry(input), dir / kFig18Name, output);
}

}  // namespace sedem::render
