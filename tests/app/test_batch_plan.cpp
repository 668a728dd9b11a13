// A batch's plan (batch.json) damaged or edited by hand: `sedem batch --gather` refuses it
// naming the file, the key and what it holds; never an uncaught exception, a number taken
// modulo or a folder outside the batch's (bench/fuzz_bench.cpp fuzzes the same file).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <tuple>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/batch_plan_file.h"
#include "tests/app/cli_runner.h"

namespace sedem::app {
namespace {

namespace fs = std::filesystem;

// A folder holding the plan of a batch of two seeds, as --emit writes it, changed by `edit`.
fs::path plan_folder(const std::string& name, const std::function<void(nlohmann::json&)>& edit) {
  const fs::path dir = fs::path(SEDEM_TEST_OUTPUT) / "batch_plan" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  BatchOptions options;
  options.out_dir = dir.string();
  options.scheduler = "parallel";
  options.seeds = 2;
  std::vector<BatchRun> runs;
  for (int seed : {1, 2})
    runs.push_back({"scenes/demo.toml",
                    "demo__seed=" + std::to_string(seed),
                    "demo",
                    "",
                    seed,
                    {"sample.seed=" + std::to_string(seed)}});
  write_plan_file(options, runs);
  std::ifstream in(dir / kBatchPlanFile);
  auto j = nlohmann::json::parse(in);
  in.close();
  edit(j);
  std::ofstream(dir / kBatchPlanFile) << j.dump(2);
  return dir;
}

// What read_plan_file says of the plan edited by `edit` ("" when it reads it).
std::string refusal(const std::string& name, const std::function<void(nlohmann::json&)>& edit) {
  try {
    read_plan_file(plan_folder(name, edit));
    return "";
  } catch (const PlanFileError& e) {
    return e.what();
  }
}

TEST(BatchPlan, ReadsWhatItWrites) {
  const auto plan = read_plan_file(plan_folder("good", [](nlohmann::json&) {}));
  ASSERT_EQ(plan.runs.size(), 2u);
  EXPECT_EQ(plan.runs[1].folder, "demo__seed=2");
  EXPECT_EQ(plan.runs[1].seed, 2);
  EXPECT_EQ(plan.options.seeds, 2);
}

TEST(BatchPlan, DamageIsNamedByKeyAndValue) {
  using J = nlohmann::json;
  const std::vector<std::tuple<std::string, std::function<void(J&)>, std::string>> cases = {
      {"format_number", [](J& j) { j["format"] = 3; }, "not a batch plan written by"},
      {"version_text", [](J& j) { j["format_version"] = "1"; }, "a plan of format version \"1\""},
      {"seeds_huge", [](J& j) { j["seeds"] = 1e308; },
       "seeds: expected a whole number in [1, 2147483647], found 1e+308"},
      {"seeds_many", [](J& j) { j["seeds"] = 1000000; }, "--seeds 1000000 is out of range"},
      {"seed0_text", [](J& j) { j["seed0"] = "x"; }, "seed0: expected a whole number"},
      {"seed_text", [](J& j) { j["runs"][1]["seed"] = "x"; },
       "runs[1].seed: expected a whole number in [0, 9223372036854775807], found \"x\""},
      {"seed_over", [](J& j) { j["runs"][0]["seed"] = 18446744073709551615u; },
       "runs[0].seed: expected a whole number"},
      {"no_overrides", [](J& j) { j["runs"][0].erase("overrides"); }, "runs[0].overrides: missing"},
      {"override_number", [](J& j) { j["runs"][0]["overrides"][0] = 7; },
       "runs[0].overrides[0]: expected a string, found 7"},
      {"no_emit", [](J& j) { j.erase("emit"); }, "emit: missing"},
      {"runs_object", [](J& j) { j["runs"] = J::object(); },
       "runs: expected a list of one or more"},
      {"runs_empty", [](J& j) { j["runs"] = J::array(); }, "runs: expected a list of one or more"},
      {"run_number", [](J& j) { j["runs"][1] = 5; }, "runs[1]: expected an object holding"},
      {"folder_up", [](J& j) { j["runs"][1]["folder"] = "../outside"; },
       "runs[1].folder: \"../outside\" is not one folder inside the batch's"},
      {"folder_dots", [](J& j) { j["runs"][0]["folder"] = ".."; }, "runs[0].folder: \"..\""},
      {"folder_line", [](J& j) { j["runs"][0]["folder"] = "a\nb"; }, "runs[0].folder: \"a\\nb\""},
  };
  for (const auto& [name, edit, expected] : cases) {
    const std::string why = refusal(name, edit);
    EXPECT_NE(why.find("batch.json: "), std::string::npos) << name << ": " << why;
    EXPECT_NE(why.find(expected), std::string::npos) << name << ": " << why;
  }
}

// The command itself: exit 2 and the message, not an abort (a JSON type error escaped it).
TEST(BatchPlan, GatherOfADamagedPlanExits2) {
  const fs::path dir = plan_folder("gather", [](nlohmann::json& j) { j["format_version"] = "1"; });
  const auto r = test::run_sedem("batch --gather " + dir.string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("batch.json: a plan of format version \"1\""), std::string::npos)
      << r.output;
}

}  // namespace
}  // namespace sedem::app
