#include "app/seed_figure.h"

#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/stats/seed_statistics.h"
#include "render/paper_figures.h"

namespace sedem::app {
namespace fs = std::filesystem;

namespace {

struct CurvePoint {
  double time_s = 0, diameter_m = 0, percent_finer = 0;
};

// A run's granulometry.csv (test,source,time_s,diameter_m,percent_finer): its curves by
// "<test>/<source>" ("true/true", "hydrometer/dem", "hydrometer/reference", ...).
std::map<std::string, std::vector<CurvePoint>> read_curves(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  std::map<std::string, std::vector<CurvePoint>> curves;
  std::string line;
  // The header, after any comment ("# partial: ...").
  while (std::getline(in, line) && line.rfind('#', 0) == 0) {
  }
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream s(line);
    for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
    // The error and bias rows have no diameter.
    if (cells.size() < 5 || cells[3].empty()) continue;
    CurvePoint p;
    p.time_s = cells[2].empty() ? 0 : std::stod(cells[2]);
    p.diameter_m = std::stod(cells[3]);
    p.percent_finer = std::stod(cells[4]);
    curves[cells[0] + "/" + cells[1]].push_back(p);
  }
  return curves;
}

render::GradingCurve grading_curve(const std::string& name, const std::vector<CurvePoint>& points) {
  render::GradingCurve c{name, {}, {}};
  for (const auto& p : points) {
    c.diameter_m.push_back(p.diameter_m);
    c.percent_finer.push_back(p.percent_finer);
  }
  return c;
}

// One test over the seeds: at each reading time the mean diameter, and the mean percent
// finer with its interval.
struct SeedCurve {
  render::GradingCurve mean;
  std::vector<double> low, high;
};

SeedCurve seed_curve(const std::string& test,
                     const std::vector<std::map<std::string, std::vector<CurvePoint>>>& runs) {
  std::map<double, std::pair<std::vector<double>, std::vector<double>>> by_time;
  for (const auto& curves : runs) {
    const auto it = curves.find(test + "/dem");
    if (it == curves.end()) continue;
    for (const auto& p : it->second) {
      by_time[p.time_s].first.push_back(p.diameter_m);
      by_time[p.time_s].second.push_back(p.percent_finer);
    }
  }
  SeedCurve c;
  c.mean.name = test + " (mean of " + std::to_string(runs.size()) + ")";
  for (const auto& [time, values] : by_time) {
    const Interval finer = mean_interval(values.second);
    c.mean.diameter_m.push_back(mean_interval(values.first).mean);
    c.mean.percent_finer.push_back(finer.mean);
    // One value has no interval: the band closes on it.
    c.low.push_back(finer.n > 1 ? finer.low : finer.mean);
    c.high.push_back(finer.n > 1 ? finer.high : finer.mean);
  }
  return c;
}

// One group's panel input, and each test's band (empty when no run has the test).
struct GroupCurves {
  render::SampleGrading grading;
  std::vector<render::PlotSeries> bands;
};

GroupCurves group_curves(const SeedGroup& group, const fs::path& out_dir) {
  std::vector<std::map<std::string, std::vector<CurvePoint>>> runs;
  for (const auto& folder : group.complete)
    runs.push_back(read_curves(out_dir / folder / "granulometry.csv"));
  GroupCurves g;
  g.grading.sample = group.label;
  g.grading.truth = grading_curve("true", runs.front()["true/true"]);
  for (const auto& test : batch_tests()) {
    SeedCurve c = seed_curve(test, runs);
    if (c.mean.diameter_m.empty()) continue;
    render::PlotSeries band(test + " 95 % band", c.mean.diameter_m, c.high,
                            render::SeriesStyle::band);
    band.y_low = c.low;
    for (double& d : band.x) d *= 1e6;  // Fig. 18's axis is in µm
    g.bands.push_back(std::move(band));
    g.grading.tests.push_back(std::move(c.mean));
    g.grading.references.push_back(
        grading_curve(test + " reference", runs.front()[test + "/reference"]));
  }
  return g;
}

// Each band under its test's mean curve, in the test's colour.
void add_bands(render::Plot& panel, const std::vector<render::PlotSeries>& bands,
               const std::vector<render::GradingCurve>& tests) {
  std::vector<render::PlotSeries> series;
  for (auto& s : panel.series) {
    for (std::size_t i = 0; i < tests.size(); ++i)
      if (s.name == tests[i].name) {
        series.push_back(bands[i]);
        series.back().color = s.color;
      }
    series.push_back(std::move(s));
  }
  panel.series = std::move(series);
}

}  // namespace

void write_seed_granulometry(const std::vector<SeedGroup>& groups,
                             const render::FigureOutput& figures, const fs::path& out_dir) {
  std::vector<GroupCurves> curves;
  std::vector<render::SampleGrading> gradings;
  for (const auto& group : groups) {
    if (group.complete.empty()) continue;
    curves.push_back(group_curves(group, out_dir));
    gradings.push_back(curves.back().grading);
  }
  if (curves.empty()) return;
  render::Figure figure = render::fig18_granulometry(gradings);
  figure.title = "Grading curves over the seeds: each test's mean and 95 % band, the true curve";
  for (std::size_t k = 0; k < curves.size(); ++k)
    add_bands(figure.panels[k], curves[k].bands, curves[k].grading.tests);
  render::write_figure(figure, out_dir / "summary_granulometry", figures);
}

}  // namespace sedem::app
