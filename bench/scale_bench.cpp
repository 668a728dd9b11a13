// The whole test at scale: every sample scene's full test (86 400 s as the scenes say) at
// 3 000, 30 000 and 100 000 particles (and 1 000 000 with --full), no frames or particle
// files. Per run: wall time, steps, particle-steps, the engine's bytes and the process's peak
// resident memory, each test's error against the reference solution, and the figure of merit
// particles x simulated seconds per wall second. Prints a line per run as it ends, writes
// bench_scale.csv (rewritten after each run) and bench_scale_plot.png. --label fills the CSV's
// label column so that two builds' CSVs can be concatenated (scripts/compare_engines.sh).
//
//   sedem_bench_scale [--samples 1,5] [--counts 3000,30000] [--end-time-s S]
//                     [--set key=value ...] [--threads N] [--out DIR] [--label NAME] [--full]
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>

#include "bench/bench_support.h"
#include "bench/scale_run.h"

int main(int argc, char** argv) {
  using namespace sedem::bench;
  CLI::App cli{"sedem scale benchmark: the whole test of every sample against particle count"};
  std::vector<int> samples{1, 2, 3, 4, 5};
  std::vector<double> counts;
  double end_time_s = 0;
  std::string out = "bench-out";
  bool full = false;
  ScaleOptions options;
  cli.add_option("--samples", samples, "Sample scenes (scenes/sample<k>.toml), e.g. 1,5")
      ->delimiter(',')
      ->check(CLI::Range(1, 5))
      ->capture_default_str();
  cli.add_option("--counts", counts,
                 "Particle counts (sample.simulated_count), e.g. 3000,30000; default "
                 "3000,30000,100000 (and 1000000 with --full)")
      ->delimiter(',')
      ->check(CLI::PositiveNumber);
  cli.add_option("--end-time-s", end_time_s,
                 "Simulated time, s (default: the scene's, 86400); the run stops at the last "
                 "reading before it")
      ->check(CLI::PositiveNumber);
  cli.add_flag("--to-end-time", options.to_end_time,
               "Run to the end time even past the last reading (the first seconds at a large "
               "count, where no reading comes before the end)");
  cli.add_option("--set", options.sets, "A scene key set in every run, key=value (repeatable)");
  cli.add_option("--threads", options.threads, "integrator.threads (default: the scene's)")
      ->check(CLI::NonNegativeNumber);
  cli.add_option("--out", out, "Folder for bench_scale.csv and bench_scale_plot.png")
      ->capture_default_str();
  cli.add_option("--label", options.label, "Written in the CSV's label column (e.g. the build)");
  cli.add_flag("--full", full, "Add 1 000 000 particles to the counts (hours)");
  CLI11_PARSE(cli, argc, argv);

  if (counts.empty()) counts = {3000, 30000, 100000};
  if (full && std::find(counts.begin(), counts.end(), 1e6) == counts.end()) counts.push_back(1e6);
  options.scenes = sample_scenes(samples);
  options.counts = counts;
  if (end_time_s > 0) options.end_time_s = end_time_s;
  options.out = out;
  try {
    const auto rows = run_scale_bench(options, stdout);
    std::size_t failed = 0;
    for (const auto& r : rows) failed += r.status != "ok";
    std::printf("wrote %s/bench_scale.csv and bench_scale_plot.png%s\n", out.c_str(),
                failed ? " (some runs failed)" : "");
    return failed ? 1 : 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sedem_bench_scale: %s\n", e.what());
    return 2;
  }
}
