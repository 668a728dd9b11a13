#pragma once

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/batch_command.h"
#include "core/stats/seed_statistics.h"

namespace sedem::app {

// The tests a run reports, in the order of every batch table.
const std::vector<std::string>& batch_tests();

// A run's run.json, or null when it is missing or unreadable.
nlohmann::json read_run_record(const std::filesystem::path& dir);

// results.<test>.<figure> of a run.json ("error_pp", "bias_pp"), NaN when the run has no such
// result, could not compute it (null) or the test took no reading.
double run_figure(const nlohmann::json& record, const std::string& test, const std::string& figure);

// summary.csv: run, scene, the swept key (when there is one), seed (empty without seeds), each
// test's error_pp and bias_pp, wall_time_s, particle_count, status; one row per run from its
// run.json (a missing or unreadable one gives status "missing").
void write_summary_csv(const std::vector<BatchRun>& runs, const std::string& sweep_key,
                       const std::filesystem::path& out_dir);

// The runs of one scene at one swept value, over the seeds.
struct SeedGroup {
  std::string scene;  // the scene file
  std::string label;  // its folder name without the seed: "demo", "demo__key=value"
  std::string value;  // the swept value, empty without a sweep
  std::vector<BatchRun> runs;
  std::vector<std::string> complete;  // folders of the runs whose run.json says "complete"
  // "<test>_error_pp" and "<test>_bias_pp" over the complete runs that have that result.
  std::vector<std::pair<std::string, Interval>> figures;
};

// The runs grouped by scene and swept value (in plan order), each group's figures computed
// from the run folders in out_dir.
std::vector<SeedGroup> seed_groups(const std::vector<BatchRun>& runs,
                                   const std::filesystem::path& out_dir);

// summary_stats.csv: scene, the swept key (when there is one), runs, then for each test and
// figure its mean, sd, ci95_low and ci95_high; empty cells where too few runs count.
void write_summary_stats_csv(const std::vector<SeedGroup>& groups, const std::string& sweep_key,
                             const std::filesystem::path& out_dir);

// Each group's figures as mean ± half-width of the 95 % interval, one line per test.
void print_summary_stats(const std::vector<SeedGroup>& groups, std::FILE* out);

}  // namespace sedem::app
