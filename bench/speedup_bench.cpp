// The fast integrator against the reference integrator, side by side in one run, on the same
// sample: wall time, steps, each test's error against the continuum reference solution, and
// how far the fast integrator's readings are from the reference integrator's (the error the
// fast integration itself adds, free of the sampling noise both share).
//
// The reference integrator is explicit, with the paper's step rule: its step stays below the
// drag response time of the smallest grain (and below a contact's period while grains touch),
// so it can only run short tests. The default case is the demo scene cut down to what it can
// finish in about a minute: 100 grains of 10 and 60 um for 120 s, contacts off (a grain on
// the bottom would hold the reference at 1e-8 s steps).
//
//   sedem_bench_speedup [--scene FILE] [--set key=value ...] [--crossing f1 f2 ...] [--out DIR]
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/observe/simulate.h"
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

double error_of(const TestResults& r, const std::string& test) {
  for (const auto& t : r.granulometry.tests)
    if (t.test == test) return t.error;
  return NAN;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli{"Fast against reference integrator, side by side"};
  std::string scene_file = std::string(SEDEM_SOURCE_DIR) + "/scenes/demo.toml";
  std::vector<std::string> sets{"sample.simulated_count=100", "run.end_time_s=120",
                                "forces.contact=false"};
  std::vector<double> crossings{0.8, 0.4, 0.2, 0.1};
  std::string out = "bench-out";
  cli.add_option("--scene", scene_file, "Scene file")->capture_default_str();
  cli.add_option("--set", sets, "Keys set in every run (replace the defaults)")
      ->capture_default_str();
  cli.add_option("--crossing", crossings, "integrator.crossing_fraction of the fast runs")
      ->capture_default_str();
  cli.add_option("--out", out, "Folder for the CSV")->capture_default_str();
  CLI11_PARSE(cli, argc, argv);
  sets.insert(sets.begin(), {"output.frames=false", "output.particles=false", "output.fields=false",
                             "integrator.threads=1"});

  std::vector<Variant> variants{{"reference", {"integrator.method=reference"}}};
  for (double c : crossings)
    variants.push_back(
        {"exponential crossing " + std::to_string(c).substr(0, 5),
         {"integrator.method=exponential", "integrator.crossing_fraction=" + std::to_string(c)}});

  const char* tests[] = {"hydrometer", "buoyancy", "pipette"};
  fs::create_directories(out);
  std::ofstream csv(fs::path(out) / "bench_speedup.csv");
  csv << "variant,particles,steps,wall_s,speedup,test,error_pp,gap_to_reference_pp\n";
  std::printf("%-26s %9s %10s %9s %9s  %-10s %9s %10s\n", "integrator", "particles", "steps",
              "wall_s", "speedup", "test", "error_pp", "gap_pp");
  SimulationRun reference;
  for (const auto& v : variants) {
    std::vector<std::string> overrides = sets;
    overrides.insert(overrides.end(), v.sets.begin(), v.sets.end());
    const Scene scene = load_scene(scene_file, overrides);
    SimulationRun run = simulate(scene, build_sample(scene));
    if (v.name == "reference") reference = run;
    const double speedup = reference.wall_seconds / std::max(run.wall_seconds, 1e-9);
    for (const char* test : tests) {
      const double error = error_of(run.results, test);
      if (std::isnan(error)) continue;
      const double gap = readings_gap(run.results, reference.results, test);
      std::printf("%-26s %9zu %10lld %9.3f %9.1f  %-10s %9.3f %10.2e\n", v.name.c_str(),
                  run.particles, static_cast<long long>(run.stats.steps), run.wall_seconds, speedup,
                  test, error, gap);
      csv << v.name << ',' << run.particles << ',' << run.stats.steps << ',' << run.wall_seconds
          << ',' << speedup << ',' << test << ',' << error << ',' << gap << '\n';
    }
    std::fflush(stdout);
  }
  std::printf("wrote %s/bench_speedup.csv\n", out.c_str());
  return 0;
}
