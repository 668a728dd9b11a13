#include "app/batch_outputs.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "app/batch_index.h"
#include "app/batch_summary.h"
#include "app/figure_inputs.h"
#include "app/run_record.h"
#include "app/seed_figure.h"
#include "render/plot.h"

namespace sedem::app {
namespace fs = std::filesystem;

namespace {

// Each test's error against the swept value, one series per test. Values that are not
// numbers are placed at 1, 2, 3...
void write_error_figure(const std::vector<BatchRun>& runs, const std::string& key,
                        const render::FigureOutput& figures, const fs::path& out_dir) {
  std::vector<double> xs;
  bool numeric = true;
  for (const auto& r : runs) {
    try {
      std::size_t used = 0;
      xs.push_back(std::stod(r.value, &used));
      numeric = numeric && used == r.value.size();
    } catch (const std::exception&) {
      xs.push_back(0);
      numeric = false;
    }
  }
  if (!numeric)
    for (std::size_t i = 0; i < xs.size(); ++i) xs[i] = double(i + 1);
  const bool log =
      numeric && !xs.empty() && *std::min_element(xs.begin(), xs.end()) > 0 &&
      *std::max_element(xs.begin(), xs.end()) >= 10 * *std::min_element(xs.begin(), xs.end());
  render::Plot plot;
  plot.title = "error against " + key;
  plot.x = render::axis(numeric ? key : key + " (run number)", "", log);
  plot.y = render::axis("error", "pp");
  std::set<std::string> scenes;
  for (const auto& r : runs) scenes.insert(fs::path(r.scene).stem().string());
  for (const auto& scene : scenes)
    for (const auto& test : batch_tests()) {
      render::PlotSeries series;
      series.name = scenes.size() > 1 ? scene + " " + test : test;
      series.style = render::SeriesStyle::line_and_points;
      for (std::size_t i = 0; i < runs.size(); ++i) {
        if (fs::path(runs[i].scene).stem().string() != scene) continue;
        const double error =
            run_figure(read_run_record(out_dir / runs[i].folder), test, "error_pp");
        if (std::isnan(error)) continue;
        series.x.push_back(xs[i]);
        series.y.push_back(error);
      }
      if (!series.x.empty()) plot.series.push_back(std::move(series));
    }
  if (plot.series.empty()) return;
  render::write_figure(render::single_plot(plot), out_dir / "summary_error", figures);
}

// The summary figures' formats and size: those the first run that has a record asked for.
render::FigureOutput summary_figure_output(const std::vector<BatchRun>& runs,
                                           const fs::path& out_dir) {
  for (const auto& r : runs) {
    try {
      const auto record = read_run_record(out_dir / r.folder);
      return figure_output(scene_from_json(record.at("scene"), r.folder).output);
    } catch (const std::exception&) {
      continue;  // a run that failed early has no record: the next one tells
    }
  }
  return {};
}

}  // namespace

std::string sweep_key(const BatchOptions& options) {
  return options.sweep.substr(0, options.sweep.find('='));
}

void write_batch_outputs(const std::vector<BatchRun>& runs, const BatchOptions& options) {
  const fs::path out_dir = options.out_dir;
  const std::string key = sweep_key(options);
  write_summary_csv(runs, key, out_dir);
  const auto figures = summary_figure_output(runs, out_dir);
  if (!key.empty()) write_error_figure(runs, key, figures, out_dir);
  const bool stats = options.seeds.value_or(0) >= 2;
  const auto groups = stats ? seed_groups(runs, out_dir) : std::vector<SeedGroup>();
  if (stats) {
    write_summary_stats_csv(groups, key, out_dir);
    write_seed_granulometry(groups, figures, out_dir);
  }
  // The page of the batch, with the summaries above.
  write_batch_index(runs, key, out_dir);
  if (!stats) return;
  if (!options.quiet) {
    const long long first = options.seed0.value_or(1);
    std::printf("sedem: seeds %lld to %lld; mean \u00b1 half-width of its 95 %% interval\n", first,
                first + *options.seeds - 1);
    print_summary_stats(groups, stdout);
  }
}

}  // namespace sedem::app
