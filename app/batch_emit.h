#pragma once

#include <vector>

#include "app/batch_command.h"

namespace sedem::app {

// `sedem batch --emit slurm|parallel`: the batch's runs written as tasks for a scheduler, none
// run here. Into options.out_dir: batch.json (the plan, which --gather reads), tasks/RUN.toml
// (each run's resolved scene, all a task needs), tasks/runs.txt, tasks/run_task.sh and
// tasks/logs/; for Slurm sedem.sbatch (the job array) and submit.sh, for GNU parallel
// parallel.txt (one line per run) and parallel.sh. Every run's scene is loaded first, so an
// invalid one stops it before anything is written. The run folders themselves are left as
// they are. Returns the exit status.
int emit_batch(const BatchOptions& options, const std::vector<BatchRun>& runs);

}  // namespace sedem::app
