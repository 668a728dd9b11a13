#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "bench/scale_run.h"

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
}

}  // namespace
}  // namespace sedem
