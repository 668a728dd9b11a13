#include "app/batch_plan_file.h"

#include <fstream>
#include <limits>

#include <nlohmann/json.hpp>

#include "app/json_fields.h"
#include "app/run_folder.h"
#include "render/atomic_write.h"

namespace sedem::app {
namespace fs = std::filesystem;

namespace {

// What the file is, for a reader that finds it alone.
constexpr const char* kFormat = "sedem batch plan";
constexpr int kFormatVersion = 1;

nlohmann::json optional_number(const auto& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

}  // namespace

void write_plan_file(const BatchOptions& options, const std::vector<BatchRun>& runs) {
  nlohmann::json j;
  j["format"] = kFormat;
  j["format_version"] = kFormatVersion;
  j["version"] = SEDEM_VERSION;
  j["emit"] = options.scheduler;
  j["sweep"] = options.sweep;
  j["seeds"] = optional_number(options.seeds);
  j["seed0"] = optional_number(options.seed0);
  j["runs"] = nlohmann::json::array();
  for (std::size_t task = 0; task < runs.size(); ++task) {
    const BatchRun& r = runs[task];
    j["runs"].push_back({{"task", task},
                         {"folder", r.folder},
                         {"scene", r.scene},
                         {"group", r.group},
                         {"value", r.value},
                         {"seed", optional_number(r.seed)},
                         {"overrides", r.overrides}});
  }
  write_atomically(fs::path(options.out_dir) / kBatchPlanFile,
                   [&](std::ostream& out) { out << j.dump(2) << '\n'; });
}

BatchPlan read_plan_file(const fs::path& dir) {
  const fs::path file = dir / kBatchPlanFile;
  std::ifstream in(file);
  if (!in)
    throw PlanFileError(file.string() +
                        ": cannot read it (a folder written by sedem batch --emit holds it)");
  const auto j = nlohmann::json::parse(in, nullptr, false);
  const auto format = j.is_object() ? j.find("format") : j.end();
  if (j.is_discarded() || !j.is_object() || format == j.end() || *format != kFormat)
    throw PlanFileError(file.string() + ": not a batch plan written by sedem batch --emit");
  const auto version = j.find("format_version");
  if (version == j.end() || *version != kFormatVersion)
    throw PlanFileError(file.string() + ": a plan of format version " +
                        (version == j.end() ? "(none)" : json_quoted(*version)) +
                        "; this sedem reads version " + std::to_string(kFormatVersion));
  // Every key read with its name: a plan edited by hand or cut short by a full disk is
  // refused naming the key and what it holds, never read as something else.
  constexpr auto kMostSeed = std::numeric_limits<std::int64_t>::max();
  BatchPlan plan;
  try {
    plan.options.out_dir = dir.string();
    plan.options.scheduler = json_string(json_key(j, "emit", ""), "emit");
    plan.options.sweep = json_string(json_key(j, "sweep", ""), "sweep");
    if (const auto seeds = json_optional_integer(json_key(j, "seeds", ""), "seeds", 1,
                                                 std::numeric_limits<int>::max()))
      plan.options.seeds = int(*seeds);
    plan.options.seed0 = json_optional_integer(json_key(j, "seed0", ""), "seed0", 0, kMostSeed);
    // The bounds a batch's command line has (a plan cannot ask for more seeds than it could).
    if (const std::string why = seed_options_error(plan.options); !why.empty())
      throw std::invalid_argument("seeds, seed0: " + why);
    const auto& runs = json_key(j, "runs", "");
    if (!runs.is_array() || runs.empty())
      throw std::invalid_argument("runs: expected a list of one or more runs, found " +
                                  json_quoted(runs));
    for (std::size_t i = 0; i < runs.size(); ++i) {
      const auto& r = runs[i];
      const std::string at = "runs[" + std::to_string(i) + "]";
      BatchRun run;
      run.folder = json_string(json_key(r, "folder", at), at + ".folder");
      run.scene = json_string(json_key(r, "scene", at), at + ".scene");
      run.group = json_string(json_key(r, "group", at), at + ".group");
      run.value = json_string(json_key(r, "value", at), at + ".value");
      run.seed = json_optional_integer(json_key(r, "seed", at), at + ".seed", 0, kMostSeed);
      run.overrides = json_strings(json_key(r, "overrides", at), at + ".overrides");
      // A folder is one path component inside the batch's, named as plan_batch names it: a
      // damaged or edited plan cannot send the summary elsewhere (nor into a name a terminal
      // or a shell would mangle).
      if (run.folder != safe_folder_name(run.folder))
        throw std::invalid_argument(at + ".folder: " + json_quoted(json_key(r, "folder", at)) +
                                    " is not one folder inside the batch's");
      plan.runs.push_back(std::move(run));
    }
  } catch (const std::invalid_argument& e) {
    throw PlanFileError(file.string() + ": " + e.what());
  } catch (const nlohmann::json::exception& e) {  // none expected: the reads above check first
    throw PlanFileError(file.string() + ": " + e.what());
  }
  return plan;
}

}  // namespace sedem::app
