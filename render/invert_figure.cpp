#include "render/invert_figure.h"

#include <algorithm>
#include <cmath>

namespace sedem::render {

namespace {

std::vector<double> micrometres(std::vector<double> v) {
  for (double& x : v) x *= 1e6;
  return v;
}

}  // namespace

Figure invert_figure(const InvertFigureInput& in) {
  Plot plot;
  plot.title = in.title;
  // The axis spans the curve's grid and the standard points, in whole decades.
  double lo = 1e9, hi = 0;
  for (const auto* v : {&in.diameter_m, &in.standard_diameter_m})
    for (double d : *v)
      if (d > 0) {
        lo = std::min(lo, d * 1e6);
        hi = std::max(hi, d * 1e6);
      }
  if (!(hi > lo)) lo = 1, hi = 100;
  plot.x = axis("diameter", "µm", std::pow(10.0, std::floor(std::log10(lo))),
                std::pow(10.0, std::ceil(std::log10(hi))), true);
  plot.y = axis("percent finer", "%", 0.0, 110.0);
  const std::array<unsigned char, 3> black{0, 0, 0};
  if (!in.bound_lower.empty()) {
    // Behind everything: where the readings leave the curve open, the prior chose it.
    PlotSeries allowed("readings allow", micrometres(in.bound_diameter_m), in.bound_upper,
                       SeriesStyle::band);
    allowed.y_low = in.bound_lower;
    allowed.color = std::array<unsigned char, 3>{200, 200, 200};
    plot.series.push_back(std::move(allowed));
  }
  if (!in.true_diameter_m.empty()) {
    PlotSeries truth("true", micrometres(in.true_diameter_m), in.true_percent_finer);
    truth.color = black;
    plot.series.push_back(std::move(truth));
  }
  const auto inverted_color = palette_color(0), standard_color = palette_color(1);
  PlotSeries inverted("inverted", micrometres(in.diameter_m), in.percent_finer,
                      SeriesStyle::line_and_points);
  inverted.color = inverted_color;
  plot.series.push_back(std::move(inverted));
  if (!in.lower.empty()) {
    PlotSeries low(in.band_name + " low", micrometres(in.diameter_m), in.lower,
                   SeriesStyle::dashed);
    PlotSeries high(in.band_name + " high", micrometres(in.diameter_m), in.upper,
                    SeriesStyle::dashed);
    low.color = high.color = inverted_color;
    plot.series.push_back(std::move(low));
    plot.series.push_back(std::move(high));
  }
  if (!in.open_diameter_m.empty()) {
    PlotSeries open("readings cannot tell", micrometres(in.open_diameter_m), in.open_percent_finer,
                    SeriesStyle::points);
    open.color = std::array<unsigned char, 3>{150, 150, 150};
    plot.series.push_back(std::move(open));
  }
  PlotSeries standard(in.standard_name, micrometres(in.standard_diameter_m),
                      in.standard_percent_finer, SeriesStyle::points);
  standard.color = standard_color;
  plot.series.push_back(std::move(standard));
  Figure figure = single_plot(std::move(plot), 720, 480);
  figure.csv_note = in.csv_note;
  return figure;
}

void write_invert_figure(const InvertFigureInput& input, const std::filesystem::path& base) {
  write_figure(invert_figure(input), base);
}

}  // namespace sedem::render
