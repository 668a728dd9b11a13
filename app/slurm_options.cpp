#include "app/slurm_options.h"

#include <algorithm>
#include <cctype>
#include <regex>

namespace sedem::app {

namespace {

// The process's own share, beyond the particles: Qt, VTK, the figures' drawing.
constexpr std::size_t kProgramBytes = 256u << 20;

}  // namespace

std::int64_t slurm_time_seconds(const std::string& text) {
  // sbatch(1), --time: "minutes", "minutes:seconds", "hours:minutes:seconds", "days-hours",
  // "days-hours:minutes" and "days-hours:minutes:seconds".
  static const std::regex form(R"((?:(\d+)-)?(\d+)(?::(\d+))?(?::(\d+))?)");
  std::smatch m;
  if (!std::regex_match(text, m, form)) return -1;
  auto number = [&](int i) { return m[i].matched ? std::stoll(m[i].str()) : 0LL; };
  if (m[2].str().size() > 9 || m[1].str().size() > 6) return -1;
  std::int64_t seconds = 0;
  const int fields = 1 + int(m[3].matched) + int(m[4].matched);
  if (m[1].matched) {  // days-hours[:minutes[:seconds]]
    seconds = number(1) * 86400 + number(2) * 3600 + number(3) * 60 + number(4);
  } else if (fields == 1) {
    seconds = number(2) * 60;
  } else if (fields == 2) {
    seconds = number(2) * 60 + number(3);
  } else {
    seconds = number(2) * 3600 + number(3) * 60 + number(4);
  }
  return seconds > 0 ? seconds : -1;
}

bool is_slurm_memory(const std::string& text) {
  static const std::regex form(R"([1-9]\d{0,9}[KMGT]?)");
  return std::regex_match(text, form);
}

std::string slurm_memory_for(std::size_t bytes) {
  // A quarter more than the estimate, which counts the particles' arrays only.
  const std::size_t total = bytes + bytes / 4 + kProgramBytes;
  const std::size_t mb = (total + (1u << 20) - 1) >> 20;
  return std::to_string(mb) + "M";
}

std::string slurm_options_error(const SlurmOptions& o) {
  if (slurm_time_seconds(o.time) < 0)
    return "--slurm-time " + o.time +
           " is not a Slurm time limit; allowed: minutes, minutes:seconds, "
           "hours:minutes:seconds, days-hours[:minutes[:seconds]] (e.g. 90, 02:00:00, 1-12)";
  if (!o.mem.empty() && !is_slurm_memory(o.mem))
    return "--slurm-mem " + o.mem +
           " is not a memory size; allowed: a number of megabytes "
           "with an optional unit K, M, G or T (e.g. 800M, 4G)";
  if (o.cpus < 1 || o.cpus > 1024)
    return "--slurm-cpus " + std::to_string(o.cpus) + " is out of range; allowed: [1, 1024]";
  // Each is one word on an #SBATCH line.
  for (const auto* name : {&o.partition, &o.account})
    if (std::any_of(name->begin(), name->end(), [](unsigned char c) {
          return !(std::isalnum(c) || c == '_' || c == '-' || c == '.' || c == ',');
        }))
      return std::string(name == &o.partition ? "--slurm-partition " : "--slurm-account ") + *name +
             ": letters, digits and _ - . , only";
  return "";
}

}  // namespace sedem::app
