#pragma once

#include <cstdint>
#include <string>

namespace sedem::app {

// What each task of a Slurm job array asks for (`sedem batch --emit slurm`). Written as the
// script's #SBATCH lines, where a site's own needs can be added by hand.
struct SlurmOptions {
  std::string time = "01:00:00";   // --time, in one of Slurm's forms (minutes, D-HH:MM:SS, ...)
  std::string mem;                 // --mem ("800M", "4G"); empty: from the largest run's estimate
  int cpus = 1;                    // --cpus-per-task, and the runs' integrator.threads
  std::string partition, account;  // empty: the cluster's defaults
};

// Seconds of a Slurm time limit: "M", "M:S", "H:M:S", "D-H", "D-H:M", "D-H:M:S"; -1 when the
// text is none of these (or "0": no limit is not a limit a task should ask for).
std::int64_t slurm_time_seconds(const std::string& text);

// Whether `text` is a Slurm memory size: digits and an optional unit K, M, G or T.
bool is_slurm_memory(const std::string& text);

// The --mem a run whose estimated peak is `bytes` asks for: the estimate and the program's
// own libraries, with a margin, in whole megabytes ("612M").
std::string slurm_memory_for(std::size_t bytes);

// Why the options cannot make a job array (one line naming the option and the value), or "".
std::string slurm_options_error(const SlurmOptions& options);

}  // namespace sedem::app
