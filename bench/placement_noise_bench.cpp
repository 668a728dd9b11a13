// Sampling noise of the instruments against the placement, in free settling: every particle
// falls at its terminal velocity from where the placement put it (the dilute limit the
// continuum reference describes; no engine), and the hydrometer, buoyancy sphere and pipette
// read it at their times. The error against the reference is then the placement's sampling
// noise alone, over many seeds in seconds, at every reading time of the full test.
//
//   sedem_bench_placement_noise [--scenes ...] [--counts 1000,4000] [--seeds 10]
//                               [--methods stratified,low_discrepancy] [--set key=value ...]
//                               [--speed 1]
//
// Prints, per scene, method, count and test, the mean and largest error over the seeds (pp)
// and the mean signed difference DEM - reference over seeds and readings (a bias would not
// average out); writes placement_noise.csv (one row per reading) into --out.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "core/instruments/instrument_panel.h"
#include "core/reference/reference_field.h"
#include "core/reference/reference_readings.h"
#include "core/run/stage_setups.h"
#include "core/sample/sample_builder.h"
#include "core/scene/scene_loader.h"

namespace {

using namespace sedem;
namespace fs = std::filesystem;

// The particles at `time` had each fallen freely at its class's terminal velocity, resting
// on the bottom once there (the bed's overlaps do not reach the instruments).
Particles settled(const Particles& start, const std::vector<double>& velocity, double time) {
  Particles p = start;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double r = 0.5 * p.diameter[i];
    p.y[i] = std::max(r, p.y[i] - velocity[std::size_t(p.size_class[i])] * time);
  }
  return p;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli{"sedem placement noise: instrument error in free settling against placement"};
  const std::string root = SEDEM_SOURCE_DIR;
  std::vector<std::string> scenes;
  for (int k = 1; k <= 5; ++k)
    scenes.push_back(root + "/scenes/sample" + std::to_string(k) + ".toml");
  std::vector<long> counts{1000, 2000, 4000, 8000, 16000, 32000};
  std::vector<std::string> methods{"stratified", "low_discrepancy"};
  std::vector<std::string> sets;
  int seeds = 10;
  double speed = 1;
  std::string out = "bench-out";
  cli.add_option("--scenes", scenes, "Scene files")->capture_default_str();
  cli.add_option("--counts", counts, "Simulated particle counts")->delimiter(',');
  cli.add_option("--seeds", seeds, "Seeds per configuration (1..N)")->capture_default_str();
  cli.add_option("--methods", methods, "sample.placement.method values")->delimiter(',');
  cli.add_option("--set", sets, "A key set in every run");
  cli.add_option("--speed", speed,
                 "Factor on every terminal velocity (a hindered settling the reference ignores)")
      ->capture_default_str();
  cli.add_option("--out", out, "Folder for the CSV")->capture_default_str();
  CLI11_PARSE(cli, argc, argv);

  fs::create_directories(out);
  std::ofstream csv(fs::path(out) / "placement_noise.csv");
  csv << "sample,method,particles,seed,test,time_s,diameter_m,dem_percent_finer,"
         "reference_percent_finer\n";
  std::printf("%-9s %-16s %9s %-11s %10s %10s %12s %9s\n", "sample", "method", "particles", "test",
              "mean_pp", "max_pp", "mean_diff_pp", "build_s");
  for (const auto& file : scenes) {
    for (const auto& method : methods) {
      for (long count : counts) {
        struct Stats {
          double sum = 0, max = 0, diff = 0;
          long readings = 0;
        };
        std::map<std::string, Stats> by_test;
        double build_seconds = 0;
        std::string name;
        for (int seed = 1; seed <= seeds; ++seed) {
          std::vector<std::string> overrides = sets;
          overrides.push_back("sample.simulated_count=" + std::to_string(count));
          overrides.push_back("sample.placement.method=" + method);
          overrides.push_back("sample.seed=" + std::to_string(seed));
          const Scene scene = load_scene(file, overrides);
          name = scene.name;
          const auto start = std::chrono::steady_clock::now();
          const Sample sample = build_sample(sample_setup(scene));
          build_seconds +=
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          std::vector<double> velocity;
          for (const auto& c : sample.classes)
            velocity.push_back(speed * reference_terminal_velocity(scene.forces.drag, c.diameter,
                                                                   sample.particle_density,
                                                                   scene.fluid));
          const TestSetup setup = test_setup(scene);
          InstrumentPanel panel(setup, sample);
          for (double t : panel.reading_times())
            panel.observe(t, settled(sample.particles, velocity, t));
          const Granulometry g =
              compare(panel.readings(), reference_readings(setup, sample), sample.classes);
          for (const auto& t : g.tests) {
            Stats& s = by_test[t.test];
            s.sum += t.error;
            s.max = std::max(s.max, t.error);
            for (std::size_t k = 0; k < t.dem.rows.size(); ++k) {
              const auto& d = t.dem.rows[k];
              const auto& r = t.reference.rows[k];
              s.diff += d.percent_finer - r.percent_finer;
              s.readings += 1;
              csv << scene.name << ',' << method << ',' << sample.particles.size() << ',' << seed
                  << ',' << t.test << ',' << d.time << ',' << r.diameter << ',' << d.percent_finer
                  << ',' << r.percent_finer << '\n';
            }
          }
        }
        for (const auto& [test, s] : by_test)
          std::printf("%-9s %-16s %9ld %-11s %10.3f %10.3f %12.3f %9.4f\n", name.c_str(),
                      method.c_str(), count, test.c_str(), s.sum / seeds, s.max,
                      s.diff / double(std::max(s.readings, 1L)), build_seconds / seeds);
        std::fflush(stdout);
      }
    }
  }
  std::printf("wrote %s/placement_noise.csv\n", out.c_str());
  return 0;
}
