#pragma once

// The text of the files `sedem batch --emit` writes for a scheduler: the script that runs one
// task, the Slurm job array and its submission, GNU parallel's command file and its script.
// Plain strings, so that the tests read them as the schedulers do.

#include <filesystem>
#include <string>
#include <vector>

#include "app/batch_command.h"

namespace sedem::app {

struct TaskScripts {
  std::filesystem::path dir;    // the batch's folder, absolute: tasks may start anywhere
  std::filesystem::path sedem;  // the program every task runs, absolute (SEDEM overrides it)
  std::string name;             // the job's name
  bool overwrite = false;       // a task replaces its folder's run instead of going on with it
  bool set_threads = true;      // a task sets integrator.threads (not when --set gave it)
};

// `text` as one word for sh: in single quotes, with each ' as '\''.
std::string shell_quote(const std::string& text);

// The command that summarises the batch once its tasks have ended.
std::string gather_command(const TaskScripts& t);

// tasks/run_task.sh RUN [THREADS]: RUN's resolved scene, tasks/RUN.toml, into the folder RUN;
// a run that a stop left in its folder goes on with --resume, a complete one is left as it is.
std::string task_script(const TaskScripts& t);

// tasks/runs.txt: the run folders, the k-th line task k - 1's.
std::string task_list(const std::vector<BatchRun>& runs);

// sedem.sbatch: the job array, one task per run, with the options' #SBATCH lines.
std::string slurm_script(const TaskScripts& t, std::size_t runs, const SlurmOptions& slurm,
                         const std::string& mem);

// submit.sh: sbatch the array, then the summary as a job that starts when every task ended.
std::string slurm_submit_script(const TaskScripts& t, const SlurmOptions& slurm);

// parallel.txt: one line per run, each a whole command that runs from any folder and any
// machine that sees the batch's folder at the same path, its output in tasks/logs/RUN.log.
std::string parallel_commands(const TaskScripts& t, const std::vector<BatchRun>& runs);

// parallel.sh [PARALLEL OPTIONS]: parallel.txt through GNU parallel, then the summary.
std::string parallel_script(const TaskScripts& t, int jobs);

}  // namespace sedem::app
