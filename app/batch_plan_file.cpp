#include "app/batch_plan_file.h"

#include <fstream>

#include <nlohmann/json.hpp>

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
  if (j.is_discarded() || !j.is_object() || j.value("format", "") != kFormat)
    throw PlanFileError(file.string() + ": not a batch plan written by sedem batch --emit");
  if (j.value("format_version", 0) != kFormatVersion)
    throw PlanFileError(file.string() + ": a plan of format version " +
                        j.value("format_version", nlohmann::json(0)).dump() +
                        "; this sedem reads version " + std::to_string(kFormatVersion));
  BatchPlan plan;
  try {
    plan.options.out_dir = dir.string();
    plan.options.scheduler = j.at("emit").get<std::string>();
    plan.options.sweep = j.at("sweep").get<std::string>();
    if (!j.at("seeds").is_null()) plan.options.seeds = j["seeds"].get<int>();
    if (!j.at("seed0").is_null()) plan.options.seed0 = j["seed0"].get<std::int64_t>();
    for (const auto& r : j.at("runs")) {
      BatchRun run;
      run.folder = r.at("folder").get<std::string>();
      run.scene = r.at("scene").get<std::string>();
      run.group = r.at("group").get<std::string>();
      run.value = r.at("value").get<std::string>();
      if (!r.at("seed").is_null()) run.seed = r["seed"].get<std::int64_t>();
      run.overrides = r.at("overrides").get<std::vector<std::string>>();
      // A folder is one path component inside the batch's: a damaged or edited plan cannot
      // send the summary elsewhere.
      if (run.folder.empty() || run.folder.find('/') != std::string::npos || run.folder == "." ||
          run.folder == "..")
        throw PlanFileError(file.string() + ": the run folder \"" + run.folder +
                            "\" is not one folder inside the batch's");
      plan.runs.push_back(std::move(run));
    }
  } catch (const nlohmann::json::exception& e) {
    throw PlanFileError(file.string() + ": " + e.what());
  }
  return plan;
}

}  // namespace sedem::app
