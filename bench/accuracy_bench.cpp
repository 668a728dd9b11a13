// Run time against error: every sample scene, every test, over a sweep of scene keys
// (simulated count, weighting, integrator and its step, ...). Prints a table, writes
// bench_accuracy.csv and, per test, a plot of run time against error with the Pareto front.
//
//   sedem_bench_accuracy [--scenes scenes/sample1.toml ...] [--vary key=v1,v2 ...]
//                        [--set key=value ...] [--out DIR] [--full]
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "bench/bench_support.h"
#include "core/run/simulation.h"
#include "core/run/stage_setups.h"
#include "core/sample/sample_builder.h"
#include "core/scene/scene_loader.h"
#include "render/plot.h"

namespace {

using namespace sedem;
namespace fs = std::filesystem;

struct Row {
  std::string sample, test, variant;
  double wall = 0, rate = 0, error = 0, bias = 0;
  std::size_t particles = 0;
};

// "key=v1,v2" lists -> every combination, as lists of "key=value".
std::vector<std::vector<std::string>> combinations(const std::vector<std::string>& varies) {
  std::vector<std::vector<std::string>> out{{}};
  for (const auto& vary : varies) {
    const auto eq = vary.find('=');
    if (eq == std::string::npos) throw std::invalid_argument("--vary " + vary + ": key=v1,v2,...");
    std::vector<std::vector<std::string>> next;
    std::size_t start = eq + 1;
    while (start <= vary.size()) {
      auto comma = std::min(vary.find(',', start), vary.size());
      for (auto combo : out) {
        combo.push_back(vary.substr(0, eq) + "=" + vary.substr(start, comma - start));
        next.push_back(std::move(combo));
      }
      start = comma + 1;
    }
    out = std::move(next);
  }
  return out;
}

std::string join(const std::vector<std::string>& parts) {
  std::string s;
  for (const auto& p : parts) s += (s.empty() ? "" : " ") + p;
  return s;
}

// Rows not beaten on both run time and error by another row of the same sample and test.
std::vector<Row> pareto(std::vector<Row> rows) {
  std::sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.wall < b.wall; });
  std::vector<Row> front;
  double best = 1e300;
  for (const auto& r : rows)
    if (r.error < best) front.push_back(r), best = r.error;
  return front;
}

void plot(const std::vector<Row>& rows, const std::string& test, const fs::path& dir) {
  render::Figure fig;
  fig.title = test + ": run time against error (Pareto front joined)";
  std::map<std::string, std::vector<Row>> by_sample;
  for (const auto& r : rows)
    if (r.test == test) by_sample[r.sample].push_back(r);
  for (const auto& [sample, list] : by_sample) {
    render::Plot p;
    p.title = sample;
    p.x = render::axis("wall time", "s", true);
    p.y = render::axis("error", "pp", true);
    render::PlotSeries all{"runs", {}, {}, render::SeriesStyle::points};
    for (const auto& r : list) all.x.push_back(r.wall), all.y.push_back(std::max(r.error, 1e-3));
    render::PlotSeries front{"Pareto front", {}, {}, render::SeriesStyle::line_and_points};
    for (const auto& r : pareto(list))
      front.x.push_back(r.wall), front.y.push_back(std::max(r.error, 1e-3));
    p.series = {all, front};
    fig.panels.push_back(p);
  }
  fig.columns = std::min<int>(3, int(fig.panels.size()));
  if (!fig.panels.empty()) render::write_figure(fig, dir / ("bench_accuracy_" + test));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli{"sedem accuracy benchmark: run time against error for every sample and test"};
  std::vector<std::string> scenes = bench::sample_scenes();
  std::vector<std::string> varies;
  std::vector<std::string> sets;
  std::string out = "bench-out";
  bool full = false;
  cli.add_option("--scenes", scenes, "Scene files")->capture_default_str();
  cli.add_option("--vary", varies, "Swept key: key=v1,v2,... (repeatable; every combination)");
  cli.add_option("--set", sets, "A key set in every run");
  cli.add_option("--out", out, "Folder for the CSV and the plots")->capture_default_str();
  cli.add_flag("--full", full, "Large counts (hours); the default runs in minutes");
  CLI11_PARSE(cli, argc, argv);
  if (varies.empty()) {
    varies = {full ? "sample.simulated_count=10000,100000,1000000"
                   : "sample.simulated_count=2000,8000,32000",
              "sample.weighting=equal_mass,uniform_count"};
  }
  const auto quiet = bench::no_output_keys();
  sets.insert(sets.begin(), quiet.begin(), quiet.end());

  fs::create_directories(out);
  std::vector<Row> rows;
  std::printf("%-10s %-11s %-58s %9s %9s %12s %9s %9s\n", "sample", "test", "variant", "particles",
              "wall_s", "p-steps/s", "error_pp", "bias_pp");
  for (const auto& file : scenes) {
    for (const auto& combo : combinations(varies)) {
      std::vector<std::string> overrides = sets;
      overrides.insert(overrides.end(), combo.begin(), combo.end());
      Scene scene = load_scene(file, overrides);
      SimulationRun run = simulate(scene, build_sample(sample_setup(scene)));
      for (const auto& t : run.results.granulometry.tests) {
        Row r{scene.name,
              t.test,
              join(combo),
              run.wall_seconds,
              run.stats.particle_steps / std::max(run.wall_seconds, 1e-9),
              t.error,
              t.bias,
              run.particles};
        std::printf("%-10s %-11s %-58s %9zu %9.3f %12.4g %9.3f %9.3f\n", r.sample.c_str(),
                    r.test.c_str(), r.variant.c_str(), r.particles, r.wall, r.rate, r.error,
                    r.bias);
        rows.push_back(r);
      }
    }
  }
  std::ofstream csv(fs::path(out) / "bench_accuracy.csv");
  csv << "sample,test,variant,particles,wall_s,particle_steps_per_s,error_pp,bias_pp\n";
  for (const auto& r : rows)
    csv << r.sample << ',' << r.test << ",\"" << r.variant << "\"," << r.particles << ',' << r.wall
        << ',' << r.rate << ',' << r.error << ',' << r.bias << '\n';
  for (const char* test : {"hydrometer", "buoyancy", "pipette"}) plot(rows, test, out);
  std::printf("wrote %s/bench_accuracy.csv and bench_accuracy_<test>.png\n", out.c_str());
  return 0;
}
