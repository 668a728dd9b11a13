#include "app/batch_scripts.h"

#include <algorithm>

namespace sedem::app {

namespace {

std::string q(const std::filesystem::path& p) {
  return shell_quote(p.string());
}

// The program a script runs, for an assignment (sedem=...): SEDEM, else the program that wrote
// the scripts, the same version as their scenes.
std::string sedem_default(const TaskScripts& t) {
  return "${SEDEM:-" + q(t.sedem) + "}";
}

// Seconds before the time limit at which a task is asked to stop (SIGTERM), so that it writes
// its checkpoint before Slurm kills it: a tenth of the limit, from 10 s to 2 min.
std::int64_t stop_lead_seconds(const SlurmOptions& slurm) {
  return std::clamp<std::int64_t>(slurm_time_seconds(slurm.time) / 10, 10, 120);
}

}  // namespace

std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (const char c : text) {
    if (c == '\'')
      out += "'\\''";
    else
      out += c;
  }
  return out + "'";
}

std::string gather_command(const TaskScripts& t) {
  return q(t.sedem) + " batch --gather " + q(t.dir);
}

std::string task_script(const TaskScripts& t) {
  std::string s =
      "#!/bin/sh\n"
      "# One run of a batch written by `sedem batch --emit`: the scene tasks/RUN.toml (resolved:\n"
      "# every key) into the folder RUN beside tasks/.";
  s += t.overwrite ? " The run replaces what the folder holds (--overwrite).\n"
                   : " A run that a stop or a time limit left in\n"
                     "# its folder goes on from its checkpoint; a complete run is left as it "
                     "is.\n";
  s += "# THREADS sets integrator.threads (default 1). SEDEM names another sedem program.\n"
       "#\n"
       "#   tasks/run_task.sh RUN [THREADS]\n"
       "set -eu\n"
       "cd " +
       q(t.dir) +
       "\n"
       "run=$1\n"
       "threads=${2:-1}\n"
       "sedem=" +
       sedem_default(t) +
       "\n"
       "[ -f \"tasks/$run.toml\" ] || { echo \"run_task.sh: no run $run in $PWD\" >&2; exit 2; "
       "}\n";
  const std::string sets = t.set_threads ? " --set \"integrator.threads=$threads\"" : "";
  if (t.overwrite) {
    s += "exec \"$sedem\" run \"tasks/$run.toml\" --out \"$run\" --overwrite" + sets + "\n";
  } else {
    s += "if [ -f \"$run/run.json\" ]; then\n"
         "  exec \"$sedem\" run --resume \"$run\"\n"
         "fi\n"
         "exec \"$sedem\" run \"tasks/$run.toml\" --out \"$run\"" +
         sets + "\n";
  }
  return s;
}

std::string task_list(const std::vector<BatchRun>& runs) {
  std::string s;
  for (const auto& r : runs) s += r.folder + '\n';
  return s;
}

std::string slurm_script(const TaskScripts& t, std::size_t runs, const SlurmOptions& slurm,
                         const std::string& mem) {
  const std::string logs = (t.dir / kBatchTasksFolder / "logs").string();
  std::string s =
      "#!/bin/bash\n"
      "# " +
      std::to_string(runs) +
      " runs of a sedem batch as a Slurm job array, one run per task (written by\n"
      "# `sedem batch --emit slurm`). Submit the array and its summary with "
      "./submit.sh, or\n"
      "#   sbatch sedem.sbatch\n"
      "# and, once every task has ended:\n"
      "#   " +
      gather_command(t) +
      "\n"
      "# Each task's output: tasks/logs/<job>_<task>.out; task k runs line k + 1 of "
      "tasks/runs.txt.\n";
  s += "#SBATCH --job-name=" + t.name + "\n";
  s += "#SBATCH --array=0-" + std::to_string(runs == 0 ? 0 : runs - 1) + "\n";
  s += "#SBATCH --time=" + slurm.time + "\n";
  s += "#SBATCH --mem=" + mem + "\n";
  s += "#SBATCH --cpus-per-task=" + std::to_string(slurm.cpus) + "\n";
  s += "#SBATCH --ntasks=1\n";
  if (!slurm.partition.empty()) s += "#SBATCH --partition=" + slurm.partition + "\n";
  if (!slurm.account.empty()) s += "#SBATCH --account=" + slurm.account + "\n";
  // #SBATCH lines are not read by a shell: a path with a space cannot be quoted there, and
  // sbatch rejects such a line; the batch's folder is checked for that when it is written.
  s += "#SBATCH --output=" + logs + "/%A_%a.out\n";
  s += "#SBATCH --chdir=" + t.dir.string() + "\n";
  // A stop asked ahead of the limit lets the run write its checkpoint (the batch shell is the
  // run itself, through exec); submitting again goes on from it.
  s += "#SBATCH --signal=B:TERM@" + std::to_string(stop_lead_seconds(slurm)) + "\n";
  s += "set -eu\n"
       "cd " +
       q(t.dir) +
       "  # as --chdir does, for a task run by hand\n"
       "run=$(sed -n \"$((SLURM_ARRAY_TASK_ID + 1))p\" tasks/runs.txt)\n"
       "echo \"sedem: task $SLURM_ARRAY_TASK_ID of job $SLURM_ARRAY_JOB_ID: run $run\"\n"
       "exec " +
       q(t.dir / kBatchTasksFolder / "run_task.sh") + " \"$run\" \"${SLURM_CPUS_PER_TASK:-1}\"\n";
  return s;
}

std::string slurm_submit_script(const TaskScripts& t, const SlurmOptions& slurm) {
  std::string where;
  if (!slurm.partition.empty()) where += " --partition=" + slurm.partition;
  if (!slurm.account.empty()) where += " --account=" + slurm.account;
  const std::string logs = (t.dir / kBatchTasksFolder / "logs").string();
  return "#!/bin/sh\n"
         "# Submits the batch: the job array, then its summary as a job that starts once every\n"
         "# task has ended, finished or not (a summary of unfinished runs lists them as "
         "missing).\n"
         "# Options go to both sbatch calls (e.g. --qos=short).\n"
         "set -eu\n"
         "cd " +
         q(t.dir) +
         "\n"
         "array=$(sbatch --parsable \"$@\" sedem.sbatch)\n"
         "array=${array%%;*}\n"
         "gather=$(sbatch --parsable \"$@\" --dependency=afterany:$array --job-name=" +
         t.name + "-gather" + where +
         " \\\n"
         "  --time=00:30:00 --mem=1G --cpus-per-task=1 --ntasks=1 --output=" +
         shell_quote(logs + "/gather_%j.out") +
         " \\\n  --wrap=" + shell_quote("exec " + gather_command(t)) +
         ")\n"
         "gather=${gather%%;*}\n"
         "echo \"sedem: job array $array, then the summary, job $gather: \"" +
         q(t.dir / "index.html") +
         "\n"
         "echo \"$array $gather\" > tasks/submitted\n";
}

std::string parallel_commands(const TaskScripts& t, const std::vector<BatchRun>& runs) {
  std::string s;
  const std::string task = q(t.dir / kBatchTasksFolder / "run_task.sh");
  for (const auto& r : runs)
    s += task + " " + shell_quote(r.folder) + " > " +
         q(t.dir / kBatchTasksFolder / "logs" / (r.folder + ".log")) + " 2>&1\n";
  return s;
}

std::string parallel_script(const TaskScripts& t, int jobs) {
  const std::string default_jobs = jobs > 0 ? std::to_string(jobs) : "100%";
  return "#!/bin/sh\n"
         "# The batch through GNU parallel, then its summary. Options go to parallel: e.g.\n"
         "#   ./parallel.sh --sshlogin 4/node1,4/node2,: --env SEDEM\n"
         "# runs on node1, node2 and here (each must see this folder at the same path and run\n"
         "# sedem, SEDEM naming it where it is elsewhere). JOBS sets runs at once per machine\n"
         "# (default " +
         default_jobs +
         "); each run takes one core. tasks/parallel.joblog lists how each ended; its\n"
         "# output is in tasks/logs/RUN.log. Exits with parallel's status, else the summary's.\n"
         "set -u\n"
         "cd " +
         q(t.dir) +
         "\n"
         "sedem=" +
         sedem_default(t) +
         "\n"
         "parallel --jobs \"${JOBS:-" +
         default_jobs +
         "}\" --joblog tasks/parallel.joblog \"$@\" < parallel.txt\n"
         "ran=$?\n"
         "\"$sedem\" batch --gather " +
         q(t.dir) +
         "\n"
         "gathered=$?\n"
         "[ \"$ran\" -ne 0 ] && exit \"$ran\"\n"
         "exit \"$gathered\"\n";
}

}  // namespace sedem::app
