#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace sedem::app {

struct BatchOptions {
  std::vector<std::string> scenes;
  std::string sweep;  // key=v1,v2,...: one run per value (of every scene)
  std::string out_dir = "out/batch";
  std::vector<std::string> overrides;
  int jobs = 1;            // runs at once, each with its share of the cores
  bool overwrite = false;  // passed on to every run
  bool quiet = false;
};

// One run per scene (and per sweep value), each in its own sub-folder of out_dir named after
// the scene file and the swept value (made unique and kept inside out_dir). Then
// out_dir/summary.csv, one row per run, and with a sweep out_dir/summary_error.png (+ .csv),
// each test's error against the swept value. Returns the worst exit status.
int batch(const BatchOptions& options);

// "key=v1,v2,v3" -> {"key=v1", "key=v2", "key=v3"}; throws std::invalid_argument if malformed.
std::vector<std::string> expand_sweep(const std::string& sweep);

// One planned run of a batch.
struct BatchRun {
  std::string scene;
  std::string folder;  // sub-folder of the batch's out_dir
  std::string value;   // the swept value, empty without a sweep
  std::vector<std::string> overrides;
};

// The runs of a batch, with their folders: the scene file's stem, "__key=value" with a sweep,
// "_2", "_3"... when two scenes share a stem; every folder name is one safe path component.
std::vector<BatchRun> plan_batch(const BatchOptions& options);

// summary.csv: run, scene, the swept key (when there is one), each test's error_pp and bias_pp,
// wall_time_s, particle_count, status; one row per run from its run.json (a missing or
// unreadable one gives status "missing").
void write_summary_csv(const std::vector<BatchRun>& runs, const std::string& sweep_key,
                       const std::filesystem::path& out_dir);

}  // namespace sedem::app
