#include "app/batch_gather.h"

#include <cstdio>
#include <filesystem>

#include "app/batch_outputs.h"
#include "app/batch_plan_file.h"
#include "app/batch_summary.h"
#include "app/exit_codes.h"

namespace sedem::app {
namespace fs = std::filesystem;

namespace {

// The runs named on stderr before "and N more".
constexpr std::size_t kNamed = 10;

// A run's status from its folder: run.json's, or "missing" when it has none.
std::string run_status(const fs::path& dir) {
  const auto record = read_run_record(dir);
  if (!record.is_object()) return "missing";
  const auto status = record.value("status", nlohmann::json());
  return status.is_string() ? status.get<std::string>() : "missing";
}

}  // namespace

int gather_batch(const std::string& dir, bool quiet) {
  BatchPlan plan;
  try {
    plan = read_plan_file(dir);
  } catch (const PlanFileError& e) {
    std::fprintf(stderr, "sedem: %s\n", e.what());
    return exit_code::invalid_scene;
  }
  plan.options.quiet = quiet;
  try {
    write_batch_outputs(plan.runs, plan.options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sedem: the batch summary could not be written: %s\n", e.what());
    return exit_code::io_failure;
  }
  std::size_t unfinished = 0;
  bool failed = false;
  std::string named;
  for (const auto& r : plan.runs) {
    const std::string status = run_status(fs::path(dir) / r.folder);
    if (status == "complete") continue;
    failed = failed || status == "failed";
    if (++unfinished <= kNamed) named += "\n  " + r.folder + ": " + status;
  }
  if (unfinished > kNamed) named += "\n  and " + std::to_string(unfinished - kNamed) + " more";
  if (unfinished > 0)
    std::fprintf(stderr,
                 "sedem: %zu of %zu runs did not complete (summary.csv lists them with their "
                 "status):%s\n"
                 "sedem: once their tasks have ended, gather again; a task run again goes on "
                 "where its run stopped\n",
                 unfinished, plan.runs.size(), named.c_str());
  if (!quiet)
    std::printf("sedem: batch of %zu runs, %zu complete: %s, %s\n", plan.runs.size(),
                plan.runs.size() - unfinished, (fs::path(dir) / "summary.csv").c_str(),
                (fs::path(dir) / "index.html").c_str());
  if (unfinished == 0) return exit_code::ok;
  return failed ? exit_code::engine_failure : exit_code::invalid_scene;
}

}  // namespace sedem::app
