#pragma once

// The scale benchmark's runs: each sample scene's whole test at several particle counts, with
// no files or pictures, measured for wall time, steps, memory and each test's error against
// the reference solution. sedem_bench_scale is its command line; the tests drive it directly.

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sedem::bench {

struct ScaleOptions {
  std::vector<std::string> scenes;   // scene files, one sample each
  std::vector<double> counts;        // sample.simulated_count of the runs
  std::optional<double> end_time_s;  // run.end_time_s; unset: the scene's
  bool to_end_time = false;          // run to the end time, not to the last reading before it
  std::vector<std::string> sets;     // key=value set in every run
  int threads = 0;                   // integrator.threads; 0: the scene's
  std::string label;                 // the CSV's label column (which build, which change)
  std::filesystem::path out = "bench-out";
  bool plot = true;  // bench_scale_plot.png (wall time and error against count)
};

// Where a run's time went up to one simulated time: the first minutes, while coarse grains
// fall through fine ones, cost most of a whole test with contacts everywhere.
struct ScaleSpan {
  double until_s = 0;      // simulated time the span ends at (the run's start is its start)
  bool reached = false;    // the run got that far (false: the values stop where the run did)
  double wall_s = 0;       // wall time to the engine's first step at or past until_s
  std::int64_t steps = 0;  // engine steps in the span
  // Means over those steps of the grains on the common step (frozen ones included) and of the
  // particles touching something, as the engine's stats give them after each step.
  double members = 0, contacts = 0;
  // What set the step (local steps): the mean of the members a coarser grain pushed, and the
  // steps the others alone would have needed (each step counted as its share of the longer step
  // they allowed; the steps themselves where that is not known).
  double pushed = 0, unpushed_steps = 0;
  // Carried sub-steps: the mean of the fast set's members over every step (0 where a step was
  // not split), and of the sub-steps they took over the steps that were split.
  double fast = 0, substeps = 0;
  // Local steps: the mean of EngineStats::own_step_share over the steps that looked (every
  // 64th), each weighed by its members, 0 where none did: what clusters of members on steps of
  // their own would leave of the members' particle-steps.
  double own_share = 0;
  // Likewise EngineStats::largest_cluster: the largest cluster's share of the moving members.
  double largest_cluster = 0;
};

// The spans the benchmark reports: to 60 s, to 600 s and to the end.
inline constexpr double kScaleSpanEnds[] = {60, 600};

struct ScaleRow {
  std::string label, sample, status = "ok", message;
  std::string sets;           // the options' keys, space-separated
  double requested = 0;       // sample.simulated_count
  std::size_t particles = 0;  // simulated particles
  int threads = 0;            // threads the engine ran with
  double end_time_s = 0;      // the scene's run.end_time_s
  double simulated_s = 0;     // the engine's time at the end (the last reading)
  double wall_s = 0;          // the engine advanced and the tests read (as sedem run's)
  double sample_build_s = 0;  // building the sample, before that
  double cpu_s = 0;           // the process's CPU time (user + system) over both, every thread
  std::int64_t steps = 0, list_builds = 0, widened_rows = 0;
  std::int64_t box_moves = 0;  // members' boxes moved on (local steps)
  double particle_steps = 0;
  std::size_t engine_peak_bytes = 0;  // largest Engine::bytes() seen at the readings
  std::size_t rss_start_bytes = 0;    // the process's resident memory before the run
  std::size_t rss_peak_bytes = 0;     // the process's peak resident memory (VmHWM)
  bool rss_peak_per_run = false;      // VmHWM reset before the run (else: since process start)
  double error_hydrometer = 0, error_buoyancy = 0, error_pipette = 0;  // pp; NaN: no reading
  // To 60 s, to 600 s, and to the end (the whole run).
  std::vector<ScaleSpan> spans;

  // Particles x simulated seconds per wall second.
  double merit() const;
};

// Every scene at every count, in that order (a sample's counts together). Prints a table line
// to `table` (if not null) as each run ends and rewrites out/bench_scale.csv after each, so
// that an interrupted benchmark keeps what it measured; then draws out/bench_scale_plot.png.
// A run that fails (e.g. the engine blew up) is a row with status "failed" and its message.
std::vector<ScaleRow> run_scale_bench(const ScaleOptions& options, std::FILE* table);

void write_scale_csv(const std::vector<ScaleRow>& rows, const std::filesystem::path& file);

// Wall time against count (every sample) and each sample's errors against count.
void plot_scale(const std::vector<ScaleRow>& rows, const std::filesystem::path& base);

}  // namespace sedem::bench
