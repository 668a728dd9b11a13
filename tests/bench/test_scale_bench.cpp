#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "bench/bench_support.h"
#include "bench/scale_run.h"
#include "core/run/simulation.h"
#include "core/run/stage_setups.h"
#include "core/sample/sample_builder.h"
#include "core/scene/scene_loader.h"

namespace sedem {
namespace {

namespace fs = std::filesystem;

// A CSV line's cells; a quoted cell may hold commas.
std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (char c : line) {
    if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted)
      cells.emplace_back();
    else
      cells.back() += c;
  }
  return cells;
}

// The demo scene at 200 particles for 20 s, every test reading three times: the scale
// benchmark's row and CSV, end to end, in about a second.
TEST(ScaleBench, WritesOneSaneCsvRowPerRun) {
  const fs::path out = fs::path(SEDEM_TEST_OUTPUT) / "bench_scale";
  fs::remove_all(out);
  bench::ScaleOptions options;
  options.scenes = {std::string(SEDEM_SOURCE_DIR) + "/scenes/demo.toml"};
  options.counts = {200};
  options.end_time_s = 20;
  options.sets = {"instruments.hydrometer.times_min=[0.1, 0.2, 0.3]",
                  "instruments.buoyancy.times_min=[0.1, 0.2, 0.3]",
                  "instruments.pipette.times_min=[0.1, 0.2, 0.3]",
                  "instruments.profile_times_min=[]"};
  options.label = "tiny";
  options.out = out;
  const auto rows = bench::run_scale_bench(options, nullptr);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].status, "ok") << rows[0].message;

  std::ifstream csv(out / "bench_scale.csv");
  std::string header, line, extra;
  ASSERT_TRUE(std::getline(csv, header));
  ASSERT_TRUE(std::getline(csv, line));
  EXPECT_FALSE(std::getline(csv, extra)) << "one run, one row";
  const auto names = split(header), cells = split(line);
  ASSERT_EQ(names.size(), cells.size()) << header << '\n' << line;
  auto value = [&](const std::string& name) {
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == name) return cells[i];
    ADD_FAILURE() << "no column " << name << " in " << header;
    return std::string();
  };
  auto number = [&](const std::string& name) { return std::stod(value(name)); };
  EXPECT_EQ(value("label"), "tiny");
  EXPECT_EQ(value("sample"), "demo");
  EXPECT_EQ(value("status"), "ok");
  EXPECT_NE(value("sets").find("instruments.pipette.times_min"), std::string::npos);
  EXPECT_EQ(number("particles"), 200);
  EXPECT_DOUBLE_EQ(number("simulated_s"), 18);  // the last reading
  // ... and the row says why it stopped short of the 20 s asked for.
  EXPECT_EQ(value("message"),
            "stopped at the last reading before the end time, t = 18 s (nothing later is read)");
  const double wall = number("wall_s");
  EXPECT_GT(wall, 0);
  EXPECT_GT(number("steps"), 0);
  EXPECT_GT(number("particle_steps"), 0);
  EXPECT_GT(number("engine_peak_bytes"), 200 * 8);
  EXPECT_GT(number("process_peak_rss_bytes"), 0);
  for (const char* test : {"error_hydrometer_pp", "error_buoyancy_pp", "error_pipette_pp"}) {
    const double e = number(test);
    EXPECT_TRUE(std::isfinite(e) && e >= 0 && e <= 100) << test << " = " << e;
  }
  EXPECT_NEAR(number("merit_particle_s_per_wall_s"), 200 * 18 / wall, 1e-6 * 200 * 18 / wall);
  EXPECT_TRUE(fs::exists(out / "bench_scale_plot.png"));
  // 20 s reach neither 60 s nor 600 s: those cells are empty, the whole run's are not.
  EXPECT_EQ(value("wall_to_60_s"), "");
  EXPECT_EQ(value("steps_to_600"), "");
  EXPECT_GE(number("members_per_step"), 0);
  EXPECT_GE(number("contacts_per_step"), 0);
}

// The first minutes apart: 90 s of the demo, read at 0.5 and 1.5 min, reach 60 s but not
// 600 s. The span to 60 s holds part of the run's steps and wall time, and the means of the
// members and the contacts over those steps.
TEST(ScaleBench, ReportsTheFirstMinuteApart) {
  const fs::path out = fs::path(SEDEM_TEST_OUTPUT) / "bench_scale_spans";
  fs::remove_all(out);
  bench::ScaleOptions options;
  options.scenes = {std::string(SEDEM_SOURCE_DIR) + "/scenes/demo.toml"};
  options.counts = {300};
  options.end_time_s = 90;
  options.sets = {"instruments.hydrometer.times_min=[0.5, 1.5]",
                  "instruments.buoyancy.times_min=[0.5, 1.5]",
                  "instruments.pipette.times_min=[0.5, 1.5]", "instruments.profile_times_min=[]",
                  // Windows of half a mean spacing: the demo's 300 grains then share the common
                  // step in clusters, some of which would lag, within the first minute.
                  "integrator.coast_travel=0.5"};
  options.out = out;
  options.plot = false;
  const auto rows = bench::run_scale_bench(options, nullptr);
  ASSERT_EQ(rows.size(), 1u);
  ASSERT_EQ(rows[0].status, "ok") << rows[0].message;
  const auto& spans = rows[0].spans;
  ASSERT_EQ(spans.size(), 3u);
  EXPECT_TRUE(spans[0].reached);
  EXPECT_EQ(spans[0].until_s, 60);
  EXPECT_FALSE(spans[1].reached);  // the run ends at 90 s
  EXPECT_TRUE(spans[2].reached);
  EXPECT_DOUBLE_EQ(spans[2].until_s, 90);
  EXPECT_GT(spans[0].steps, 0);
  EXPECT_LT(spans[0].steps, spans[2].steps);
  EXPECT_EQ(spans[2].steps, rows[0].steps);  // every step watched
  EXPECT_GT(spans[0].wall_s, 0);
  EXPECT_LE(spans[0].wall_s, spans[2].wall_s);
  EXPECT_EQ(spans[2].wall_s, rows[0].wall_s);
  // Members: at most every particle, and some at the start, where the demo's grains crowd.
  EXPECT_GT(spans[0].members, 0);
  EXPECT_LE(spans[0].members, 300);
  EXPECT_LE(spans[0].contacts, spans[0].members);
  // The steps the members not pushed would need: no more than were taken, and some.
  EXPECT_GT(spans[0].unpushed_steps, 0);
  EXPECT_LE(spans[0].unpushed_steps, double(spans[0].steps) * (1 + 1e-12));
  EXPECT_LE(spans[0].pushed, spans[0].members);
  std::ifstream csv(out / "bench_scale.csv");
  std::string header, line;
  ASSERT_TRUE(std::getline(csv, header));
  ASSERT_TRUE(std::getline(csv, line));
  const auto names = split(header), cells = split(line);
  ASSERT_EQ(names.size(), cells.size());
  std::map<std::string, std::string> row;
  for (std::size_t i = 0; i < names.size(); ++i) row[names[i]] = cells[i];
  EXPECT_NEAR(std::stod(row.at("wall_to_60_s")), spans[0].wall_s, 1e-9 * spans[0].wall_s);
  EXPECT_EQ(std::stoll(row.at("steps_to_60")), spans[0].steps);
  EXPECT_EQ(row.at("wall_to_600_s"), "");
  EXPECT_NEAR(std::stod(row.at("unpushed_steps_to_60")), spans[0].unpushed_steps,
              1e-9 * spans[0].unpushed_steps);
  EXPECT_NEAR(std::stod(row.at("unpushed_steps")), spans[2].unpushed_steps,
              1e-9 * spans[2].unpushed_steps);
  EXPECT_EQ(row.at("pushed_per_step_to_600"), "");
  // No carried sub-steps asked for: no fast set, no sub-steps (the columns' values with them:
  // CarriedSubsteps.*, which read the same stats).
  EXPECT_EQ(spans[2].fast, 0);
  EXPECT_EQ(row.at("fast_per_step_to_60"), "0");
  EXPECT_EQ(row.at("substeps_per_split_step"), "0");
  EXPECT_EQ(row.at("fast_per_step_to_600"), "");
  // The demo's members move: their boxes moved on, as many times as the stats say.
  EXPECT_GT(rows[0].box_moves, 0);
  EXPECT_EQ(std::stoll(row.at("box_moves")), rows[0].box_moves);
  // Clusters on steps of their own would leave a share of the members' particle-steps: more
  // than none, at most all (EngineStats::own_step_share; its values: OwnStepShare.*).
  EXPECT_GT(spans[0].own_share, 0);
  EXPECT_LE(spans[0].own_share, 1 + 1e-12);
  EXPECT_NEAR(std::stod(row.at("own_step_share_to_60")), spans[0].own_share, 1e-9);
  EXPECT_NEAR(std::stod(row.at("own_step_share")), spans[2].own_share, 1e-9);
  EXPECT_EQ(row.at("own_step_share_to_600"), "");
  EXPECT_GT(spans[0].largest_cluster, 0);
  EXPECT_LE(spans[0].largest_cluster, 1 + 1e-12);
  EXPECT_NEAR(std::stod(row.at("largest_cluster_to_60")), spans[0].largest_cluster, 1e-9);
}

// Watching every step changes nothing: the same steps, the same readings, the same particles
// bit for bit as the run that is not watched.
TEST(ScaleBench, WatchingEveryStepChangesNothing) {
  const Scene scene = load_scene(
      std::string(SEDEM_SOURCE_DIR) + "/scenes/demo.toml",
      {"sample.simulated_count=300", "run.end_time_s=90",
       "instruments.hydrometer.times_min=[0.5, 1.5]", "instruments.profile_times_min=[]"});
  const SimulationRun plain = simulate(scene, build_sample(sample_setup(scene)), true);
  std::int64_t watched_steps = 0;
  const SimulationRun watched = simulate(scene, build_sample(sample_setup(scene)), true,
                                         [&](double, const EngineStats&) { ++watched_steps; });
  EXPECT_EQ(watched_steps, plain.stats.steps);
  EXPECT_EQ(watched.stats.steps, plain.stats.steps);
  EXPECT_EQ(watched.stats.particle_steps, plain.stats.particle_steps);
  ASSERT_EQ(watched.last.size(), plain.last.size());
  for (std::size_t i = 0; i < plain.last.size(); ++i) {
    ASSERT_EQ(watched.last.x[i], plain.last.x[i]) << i;
    ASSERT_EQ(watched.last.y[i], plain.last.y[i]) << i;
    ASSERT_EQ(watched.last.vy[i], plain.last.vy[i]) << i;
  }
  EXPECT_EQ(bench::test_error(watched.results, "hydrometer"),
            bench::test_error(plain.results, "hydrometer"));
}

}  // namespace
// A short run that no reading reaches stops at once unless asked to run to its end time; then it
// takes the steps there and the readings stay empty.
TEST(ScaleBench, RunsToTheEndTimeWhenAsked) {
  const Scene scene = load_scene(std::string(SEDEM_SOURCE_DIR) + "/scenes/demo.toml",
                                 {"sample.simulated_count=300", "run.end_time_s=5",
                                  "instruments.hydrometer.times_min=[0.5, 1.5]"});
  const SimulationRun to_reading = simulate(scene, build_sample(sample_setup(scene)));
  EXPECT_EQ(to_reading.simulated_seconds, 0);
  EXPECT_EQ(to_reading.stats.steps, 0);
  const SimulationRun to_end = simulate(scene, build_sample(sample_setup(scene)), false, {}, true);
  EXPECT_DOUBLE_EQ(to_end.simulated_seconds, 5);
  EXPECT_GT(to_end.stats.steps, 0);
  EXPECT_TRUE(std::isnan(bench::test_error(to_end.results, "hydrometer")));
}

}  // namespace sedem
