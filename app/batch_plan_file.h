#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/batch_command.h"

namespace sedem::app {

// batch.json, in the folder of a batch written by --emit: the batch's options (the sweep, the
// seeds) and its runs in task order (each run's folder, scene file as given, swept value,
// seed, overrides), so that `sedem batch --gather DIR` summarises the runs exactly as the
// local batch of the same command would, with nothing but the folder.
inline constexpr const char* kBatchPlanFile = "batch.json";

struct BatchPlan {
  BatchOptions options;  // sweep, seeds, seed0, emit; out_dir the folder it was read from
  std::vector<BatchRun> runs;
};

struct PlanFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Writes out_dir/batch.json atomically. Throws WriteError.
void write_plan_file(const BatchOptions& options, const std::vector<BatchRun>& runs);

// The plan of the batch in `dir`. Throws PlanFileError naming the file and what is wrong.
BatchPlan read_plan_file(const std::filesystem::path& dir);

}  // namespace sedem::app
