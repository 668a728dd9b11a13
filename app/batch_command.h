#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/slurm_options.h"

namespace sedem::app {

struct BatchOptions {
  std::vector<std::string> scenes;
  std::string sweep;  // key=v1,v2,...: one run per value (of every scene)
  std::string out_dir = "out/batch";
  std::vector<std::string> overrides;
  int jobs = 1;            // runs at once, each with its share of the cores
  bool overwrite = false;  // passed on to every run
  bool quiet = false;
  // Runs per scene and swept value, with sample.seed = seed0, seed0 + 1, ...; unset: one run
  // with the scene's own seed.
  std::optional<int> seeds;
  std::optional<std::int64_t> seed0;  // default 1
  // "slurm" or "parallel": write the runs as tasks for that scheduler instead of running them
  // (app/batch_emit.h); "" runs them here.
  std::string scheduler;
  bool jobs_given = false;  // --jobs on the command line: with --emit parallel, parallel's -j
  SlurmOptions slurm;
};

// One run per scene (and per sweep value), each in its own sub-folder of out_dir named after
// the scene file and the swept value (made unique and kept inside out_dir). Then
// out_dir/summary.csv, one row per run, and with a sweep out_dir/summary_error.png (+ .csv),
// each test's error against the swept value. With seeds, one run per seed of each, and from two
// seeds on out_dir/summary_stats.csv and summary_granulometry.png: each scene and swept value's
// mean and confidence interval over the seeds. Returns the worst exit status.
int batch(const BatchOptions& options);

// "key=v1,v2,v3" -> {"key=v1", "key=v2", "key=v3"}; throws std::invalid_argument if malformed.
std::vector<std::string> expand_sweep(const std::string& sweep);

// One planned run of a batch.
struct BatchRun {
  std::string scene;
  std::string folder;  // sub-folder of the batch's out_dir
  std::string group;   // `folder` without the seed: the runs that differ only in their seed
  std::string value;   // the swept value, empty without a sweep
  std::optional<std::int64_t> seed;  // with --seeds only
  std::vector<std::string> overrides;
};

// The runs of a batch, with their folders: the scene file's stem, "__key=value" with a sweep,
// "__seed=K" with seeds, "_2", "_3"... when two scenes share a stem; every folder name is one
// safe path component, and none is kBatchTasksFolder.
std::vector<BatchRun> plan_batch(const BatchOptions& options);

// The folder of a batch's out_dir that --emit writes its tasks' scenes and logs into: no run
// takes its name (a scene tasks.toml runs into tasks_2/), emitted or not, so that a batch's
// run folders are the same whether it runs here or on a cluster.
inline constexpr const char* kBatchTasksFolder = "tasks";

// Why the options' seeds cannot be run (one line naming the option, the value and the allowed
// range), or "" when they can.
std::string seed_options_error(const BatchOptions& options);

}  // namespace sedem::app
