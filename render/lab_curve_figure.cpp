#include "render/lab_curve_figure.h"

#include <algorithm>
#include <cmath>

namespace sedem::render {

Figure lab_curve_figure(const std::string& title, const std::vector<CurvePoint>& curve) {
  Plot plot;
  plot.title = title;
  double lo = 1e9, hi = 0;
  std::vector<std::string> sources;
  for (const auto& p : curve) {
    if (p.diameter > 0) {
      lo = std::min(lo, p.diameter * 1e3);
      hi = std::max(hi, p.diameter * 1e3);
    }
    if (std::find(sources.begin(), sources.end(), p.source) == sources.end())
      sources.push_back(p.source);
  }
  if (!(hi > lo)) lo = 1e-3, hi = 1;
  // Whole decades, as grading charts are printed.
  plot.x = axis("diameter", "mm", std::pow(10.0, std::floor(std::log10(lo))),
                std::pow(10.0, std::ceil(std::log10(hi))), true);
  plot.y = axis("percent finer", "%", 0.0, 105.0);
  for (std::size_t s = 0; s < sources.size(); ++s) {
    PlotSeries series(sources[s], {}, {}, SeriesStyle::line_and_points);
    for (const auto& p : curve)
      if (p.source == sources[s] && p.diameter > 0) {
        series.x.push_back(p.diameter * 1e3);
        series.y.push_back(p.percent_finer);
      }
    series.color = palette_color(s);
    plot.series.push_back(std::move(series));
  }
  return single_plot(std::move(plot), 720, 480);
}

void write_lab_curve_figure(const std::string& title, const std::vector<CurvePoint>& curve,
                            const std::filesystem::path& base) {
  write_figure(lab_curve_figure(title, curve), base);
}

}  // namespace sedem::render
