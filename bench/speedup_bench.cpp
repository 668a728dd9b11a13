// The fast integrator against the explicit integrator, side by side in one run, on the same
// sample: wall time, steps, each test's error against the continuum reference solution, and
// how far the fast integrator's readings are from the explicit integrator's (the error the
// fast integration itself adds, free of the sampling noise both share).
//
// The explicit integrator keeps the paper's step rule: its step stays below the
// drag response time of the smallest grain (and below a contact's period while grains touch),
// so it can only run short tests. The default case is the demo scene cut down to what it can
// finish in a few minutes: 50 grains of 10 and 60 um for 60 s, contacts off (a grain on the
// bottom would hold the explicit integrator at 1e-8 s steps) and Stokes drag (with so few heavily
// weighted grains each one packs its own voidage cell to the floor, and the explicit integrator's
// step shrinks with the drag it then feels).
//
//   sedem_bench_speedup [--scene FILE] [--set key=value ...] [--max-step s1 s2 ...] [--out DIR]
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "bench/bench_support.h"
#include "core/run/simulation.h"
#include "core/run/stage_setups.h"
#include "core/sample/sample_builder.h"
#include "core/scene/scene_loader.h"

namespace {

using namespace sedem;
namespace fs = std::filesystem;

struct Variant {
  std::string name;
  std::vector<std::string> sets;
};

// Largest |w_o| difference over the readings two runs share, per test, percentage points.
double readings_gap(const TestResults& a, const TestResults& b, const std::string& test) {
  double gap = 0;
  for (const auto& ta : a.granulometry.tests)
    for (const auto& tb : b.granulometry.tests)
      if (ta.test == test && tb.test == test) gap = std::max(gap, curve_error(ta.dem, tb.dem));
  return gap;
}

// Largest distance between the same particle in two runs, over the largest distance any
// particle fell in the first.
double position_gap(const Particles& a, const Particles& b, const Particles& start) {
  double gap = 0, fall = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    gap = std::max(gap, std::hypot(a.x[i] - b.x[i], a.y[i] - b.y[i]));
    fall = std::max(fall, start.y[i] - a.y[i]);
  }
  return fall > 0 ? gap / fall : gap;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli{"Fast against explicit integrator, side by side"};
  std::string scene_file = std::string(SEDEM_SOURCE_DIR) + "/scenes/demo.toml";
  std::vector<std::string> sets{"sample.simulated_count=50", "run.end_time_s=60",
                                "forces.contact=false", "forces.drag=stokes"};
  std::vector<double> max_steps{1.0, 0.1, 0.01, 0.001};
  std::string out = "bench-out";
  cli.add_option("--scene", scene_file, "Scene file")->capture_default_str();
  cli.add_option("--set", sets, "Keys set in every run (replace the defaults)")
      ->capture_default_str();
  cli.add_option("--max-step", max_steps, "integrator.max_step_s of the fast runs")
      ->capture_default_str();
  cli.add_option("--out", out, "Folder for the CSV")->capture_default_str();
  CLI11_PARSE(cli, argc, argv);
  sets.insert(sets.begin(), "integrator.threads=1");
  const auto quiet = bench::no_output_keys();
  sets.insert(sets.begin(), quiet.begin(), quiet.end());

  std::vector<Variant> variants{{"explicit", {"integrator.method=explicit"}}};
  for (double step : max_steps) {
    char name[64];
    std::snprintf(name, sizeof name, "exponential, step <= %g s", step);
    variants.push_back(
        {name, {"integrator.method=exponential", "integrator.max_step_s=" + std::to_string(step)}});
  }

  const char* tests[] = {"hydrometer", "buoyancy", "pipette"};
  fs::create_directories(out);
  std::ofstream csv(fs::path(out) / "bench_speedup.csv");
  csv << "variant,particles,steps,wall_s,speedup,position_gap_over_fall,test,error_pp,"
         "gap_to_explicit_pp\n";
  std::printf("%-30s %9s %10s %9s %9s %10s  %-10s %9s %10s\n", "integrator", "particles", "steps",
              "wall_s", "speedup", "pos_gap", "test", "error_pp", "gap_pp");
  SimulationRun slow;
  for (const auto& v : variants) {
    std::vector<std::string> overrides = sets;
    overrides.insert(overrides.end(), v.sets.begin(), v.sets.end());
    const Scene scene = load_scene(scene_file, overrides);
    const Sample sample = build_sample(sample_setup(scene));
    SimulationRun run = simulate(scene, sample, true);
    if (v.name == "explicit") slow = run;
    const double speedup = slow.wall_seconds / std::max(run.wall_seconds, 1e-9);
    const double moved = position_gap(run.last, slow.last, sample.particles);
    for (const char* test : tests) {
      const double error = bench::test_error(run.results, test);
      if (std::isnan(error)) continue;
      const double gap = readings_gap(run.results, slow.results, test);
      std::printf("%-30s %9zu %10lld %9.3f %9.1f %10.2e  %-10s %9.3f %10.2e\n", v.name.c_str(),
                  run.particles, static_cast<long long>(run.stats.steps), run.wall_seconds, speedup,
                  moved, test, error, gap);
      csv << v.name << ',' << run.particles << ',' << run.stats.steps << ',' << run.wall_seconds
          << ',' << speedup << ',' << moved << ',' << test << ',' << error << ',' << gap << '\n';
    }
    std::fflush(stdout);
  }
  std::printf("wrote %s/bench_speedup.csv\n", out.c_str());
  return 0;
}
