// `sedem batch --seeds N`: one run per seed, and the statistics over the seeds that
// summary_stats.csv gives agree with the runs that summary.csv lists.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "core/stats/seed_statistics.h"
#include "csv_rows.h"

namespace sedem {
namespace {

namespace fs = std::filesystem;
const fs::path kOut = fs::path(SEDEM_TEST_OUTPUT) / "seed_batch";
const std::string kDemo = std::string(SEDEM_SOURCE_DIR) + "/scenes/demo.toml";
// A few seconds in all: 200 particles, 20 s, each test read once.
const std::string kTiny =
    " --set sample.simulated_count=200 --set output.frames=false --set output.particles=false"
    " --set run.end_time_s=20 --set instruments.hydrometer.times_min=[0.25]"
    " --set instruments.buoyancy.times_min=[0.25] --set instruments.pipette.times_min=[0.25]"
    " --quiet";

using test::cell;
using test::read_rows;

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

fs::path fresh(const std::string& name) {
  fs::remove_all(kOut / name);
  fs::create_directories(kOut / name);
  return kOut / name;
}

// summary_granulometry.csv's hydrometer curve (one reading) is the mean of the runs' DEM
// readings in their granulometry.csv, and its band the interval of that mean.
void expect_mean_curve(const fs::path& out, int seeds) {
  ASSERT_TRUE(fs::exists(out / "summary_granulometry.png"));
  std::vector<double> finer, diameter;
  for (int k = 1; k <= seeds; ++k)
    for (const auto& row :
         read_rows(out / ("demo__seed=" + std::to_string(k)) / "granulometry.csv"))
      if (row.at("test") == "hydrometer" && row.at("source") == "dem") {
        finer.push_back(cell(row, "percent_finer"));
        diameter.push_back(1e6 * cell(row, "diameter_m"));
      }
  ASSERT_EQ(finer.size(), std::size_t(seeds));
  const Interval expected = mean_interval(finer);
  const auto figure = read_rows(out / "summary_granulometry.csv");
  ASSERT_FALSE(figure.empty());
  const std::string mean = "hydrometer (mean of " + std::to_string(seeds) + "):";
  EXPECT_NEAR(cell(figure[0], mean + "percent_finer"), expected.mean, 1e-6);
  EXPECT_NEAR(cell(figure[0], mean + "diameter_um"), mean_interval(diameter).mean, 1e-5);
  EXPECT_NEAR(cell(figure[0], "hydrometer 95 % band:percent_finer_low"), expected.low, 1e-6);
  EXPECT_NEAR(cell(figure[0], "hydrometer 95 % band:percent_finer_high"), expected.high, 1e-6);
}

TEST(SeedBatch, ThreeSeedsGiveThreeRunsAndTheirStatistics) {
  const fs::path out = fresh("three");
  const auto r =
      test::run_sedem("batch " + kDemo + " --out " + out.string() + " --seeds 3 --jobs 2" + kTiny);
  ASSERT_EQ(r.status, 0) << r.output;

  std::set<long long> seeds;
  for (int k = 1; k <= 3; ++k) {
    const fs::path dir = out / ("demo__seed=" + std::to_string(k));
    ASSERT_TRUE(fs::exists(dir / "run.json")) << dir;
    const auto record = read_json(dir / "run.json");
    EXPECT_EQ(record["seed"].get<long long>(), k);
    EXPECT_EQ(record["scene"]["sample.seed"].get<long long>(), k);
    seeds.insert(record["seed"].get<long long>());
  }
  EXPECT_EQ(seeds.size(), 3u);

  const auto runs = read_rows(out / "summary.csv");
  ASSERT_EQ(runs.size(), 3u);
  for (int k = 1; k <= 3; ++k) {
    EXPECT_EQ(runs[k - 1].at("seed"), std::to_string(k));
    EXPECT_EQ(runs[k - 1].at("status"), "complete");
  }

  const auto stats = read_rows(out / "summary_stats.csv");
  ASSERT_EQ(stats.size(), 1u);
  EXPECT_EQ(stats[0].at("scene"), kDemo);
  EXPECT_EQ(cell(stats[0], "runs"), 3);
  int compared = 0;
  for (const char* test : {"hydrometer", "buoyancy", "pipette"})
    for (const char* figure : {"error_pp", "bias_pp"}) {
      const std::string column = std::string(test) + "_" + figure;
      std::vector<double> values;
      for (const auto& row : runs) values.push_back(cell(row, column));
      const Interval expected = mean_interval(values);
      if (expected.n < 2) continue;
      // summary.csv rounds to 6 significant digits.
      const double tolerance = 1e-5 * (1 + std::abs(expected.mean) + expected.sd);
      EXPECT_NEAR(cell(stats[0], column + "_mean"), expected.mean, tolerance) << column;
      EXPECT_NEAR(cell(stats[0], column + "_sd"), expected.sd, tolerance) << column;
      EXPECT_NEAR(cell(stats[0], column + "_ci95_low"), expected.low, 10 * tolerance) << column;
      EXPECT_NEAR(cell(stats[0], column + "_ci95_high"), expected.high, 10 * tolerance) << column;
      EXPECT_LE(cell(stats[0], column + "_ci95_low"), cell(stats[0], column + "_mean"));
      ++compared;
    }
  // The seeds place the grains differently: the DEM's readings differ (the reference's bias
  // does not depend on the seed).
  EXPECT_GT(cell(stats[0], "hydrometer_error_pp_sd"), 0);
  // Every test reads at least once in 20 s: all six figures have their statistics.
  EXPECT_EQ(compared, 6);
  expect_mean_curve(out, 3);
}

TEST(SeedBatch, SeedsFollowTheSweptValuesAndTheFirstSeed) {
  const fs::path out = fresh("sweep");
  const auto r =
      test::run_sedem("batch " + kDemo + " --out " + out.string() +
                      " --sweep sample.simulated_count=200,250 --seeds 2 --seed0 40" + kTiny);
  ASSERT_EQ(r.status, 0) << r.output;
  for (const char* count : {"200", "250"})
    for (const int seed : {40, 41}) {
      const fs::path dir = out / ("demo__sample.simulated_count=" + std::string(count) +
                                  "__seed=" + std::to_string(seed));
      ASSERT_TRUE(fs::exists(dir / "run.json")) << dir;
      EXPECT_EQ(read_json(dir / "run.json")["seed"].get<long long>(), seed);
    }
  const auto stats = read_rows(out / "summary_stats.csv");
  ASSERT_EQ(stats.size(), 2u);
  EXPECT_EQ(stats[0].at("sample.simulated_count"), "200");
  EXPECT_EQ(stats[1].at("sample.simulated_count"), "250");
  EXPECT_EQ(cell(stats[1], "runs"), 2);
}

TEST(SeedBatch, OneSeedWritesNoStatistics) {
  const fs::path out = fresh("one");
  const auto r =
      test::run_sedem("batch " + kDemo + " --out " + out.string() + " --seeds 1 --seed0 5" + kTiny);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(read_json(out / "demo__seed=5/run.json")["seed"].get<long long>(), 5);
  EXPECT_FALSE(fs::exists(out / "summary_stats.csv"));
  EXPECT_FALSE(fs::exists(out / "summary_granulometry.png"));
  EXPECT_EQ(read_rows(out / "summary.csv").at(0).at("seed"), "5");
}

TEST(SeedBatch, RefusesSeedsOutOfRangeOrASeedOfItsOwn) {
  const fs::path out = fresh("refused");
  const std::string batch = "batch " + kDemo + " --out " + out.string();
  auto r = test::run_sedem(batch + " --seeds 0");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_EQ(r.output, "sedem: --seeds 0 is out of range; allowed: [1, 10000]\n");
  r = test::run_sedem(batch + " --seeds -3");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("--seeds -3 is out of range; allowed: [1, 10000]"), std::string::npos)
      << r.output;
  r = test::run_sedem(batch + " --seeds 3 --set sample.seed=9");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("--set sample.seed=9 cannot go with --seeds"), std::string::npos)
      << r.output;
  r = test::run_sedem(batch + " --seeds 2 --seed0 -1");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("--seed0 -1 is out of range"), std::string::npos) << r.output;
  // Nothing ran.
  EXPECT_TRUE(fs::is_empty(out));
}

}  // namespace
}  // namespace sedem
