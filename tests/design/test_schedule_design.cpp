// The design of a reading schedule: its score against a truth computed by hand, the clock
// times, and the search against every schedule of a small candidate set.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/design/schedule_design.h"
#include "core/run/stage_setups.h"
#include "core/scene/scene.h"

namespace sedem {
namespace {

// A table curve: 0 % at 10 um, 10 % at 20, 90 % at 40, 100 % at 80 (linear in log d between).
Scene knee_scene() {
  Scene s;
  s.sample.grading.family = "table";
  s.sample.grading.diameters = {10e-6, 20e-6, 40e-6, 80e-6};
  s.sample.grading.percent_finer = {0, 10, 90, 100};
  return s;
}

Reading at(double diameter_um, double percent) {
  Reading r;
  r.diameter = diameter_um * 1e-6;
  r.percent_finer = percent;
  return r;
}

TEST(ScheduleScore, ExactReadingsAtTheTablePointsHaveNoError) {
  const TruthGrid grid = truth_grid(knee_scene().sample.grading, 10e-6, 80e-6);
  const auto score = score_readings({at(10, 0), at(20, 10), at(40, 90), at(80, 100)}, grid);
  EXPECT_LT(score.worst_error, 1e-9);
  EXPECT_LT(score.mean_error, 1e-9);
}

TEST(ScheduleScore, TwoReadingsMissTheKneeByHandComputedAmount) {
  // The straight line from (10, 0) to (80, 100) in log d is 100/3 % at 20 um and 200/3 % at
  // 40 um: 23.33 pp from the truth at both, the worst of the range (first found: 20 um).
  const TruthGrid grid = truth_grid(knee_scene().sample.grading, 10e-6, 80e-6);
  const auto score = score_readings({at(10, 0), at(80, 100)}, grid);
  EXPECT_NEAR(score.worst_error, 100.0 / 3 - 10, 1e-9);
  EXPECT_NEAR(score.worst_diameter, 20e-6, 1e-12);
  EXPECT_NEAR(score.worst_truth, 10, 1e-9);
  // The mean gap, by hand in u = log2(d / 10 um): a triangle of height 23.33 pp on [0, 1],
  // two of half that base on [1, 2] (the gap changes sign at 28.3 um) and one on [2, 3]:
  // 35 pp x u over a range of 3, half the worst.
  EXPECT_NEAR(score.mean_error, (100.0 / 3 - 10) / 2, 0.05);
}

TEST(ScheduleScore, AReadingsOwnErrorCounts) {
  // A reading 5 pp off the truth at 40 um, the others exact: the worst is that reading.
  const TruthGrid grid = truth_grid(knee_scene().sample.grading, 10e-6, 80e-6);
  const auto score = score_readings({at(10, 0), at(20, 10), at(40, 85), at(80, 100)}, grid);
  EXPECT_NEAR(score.worst_error, 5, 1e-9);
  EXPECT_NEAR(score.worst_diameter, 40e-6, 1e-12);
}

TEST(ClockTimes, ReadableAndAscending) {
  const auto t = clock_times(120, 86400);
  ASSERT_GE(t.size(), 3u);
  EXPECT_DOUBLE_EQ(t.front(), 120);
  EXPECT_DOUBLE_EQ(t.back(), 86400);
  for (std::size_t i = 1; i < t.size(); ++i) {
    EXPECT_GT(t[i], t[i - 1]);
    const double step = t[i] <= 120 ? 15 : t[i] <= 600 ? 30 : t[i] <= 14400 ? 60 : 300;
    EXPECT_NEAR(std::fmod(t[i], step), 0, 1e-9) << t[i];
  }
  // 120..600 every 30 s (17), 660..14400 every 60 s (230), 14700..86400 every 300 s (240).
  EXPECT_EQ(t.size(), 17u + 230u + 240u);
  const auto early = clock_times(30, 130);
  EXPECT_EQ(early, (std::vector<double>{30, 45, 60, 75, 90, 105, 120, 130}));
}

// A short test read at 2, 5 and 10 min in a dilute Stokes suspension: few enough candidates
// (every 15-30 s up to 10 min) to try every schedule of three readings.
Scene short_test() {
  Scene s;
  s.forces.drag = "stokes";
  s.sample.grading.family = "table";
  s.sample.grading.diameters = {2.5e-6, 25e-6, 30e-6, 35e-6, 70e-6};
  s.sample.grading.percent_finer = {0, 5, 50, 97, 100};
  s.instruments.buoyancy = false;
  s.instruments.pipette = false;
  s.instruments.hydrometer_times = {120, 300, 600};
  return s;
}

TEST(DesignSchedule, TheSearchFindsTheBestOfEverySchedule) {
  const Scene scene = short_test();
  DesignOptions options;
  options.test = "hydrometer";
  options.size_count = 300;
  options.last_time = 600;
  const ScheduleDesign design = design_schedule(test_setup(scene), sample_setup(scene), options);
  ASSERT_EQ(design.designed.times.size(), 3u);
  EXPECT_GE(design.designed.times.front(), 120);
  EXPECT_LE(design.designed.times.back(), 600);
  EXPECT_LE(design.designed_score.worst_error, design.standard_score.worst_error + 1e-9);

  // Brute force over every three candidate times that span the standard's diameters.
  const ScheduleReader reader(test_setup(scene), sample_setup(scene), options.size_count);
  ReadingSchedule all;
  all.times = clock_times(120, 600);
  all.depth_fraction = std::nan("");
  const auto rows = reader.readings("hydrometer", all);
  ASSERT_EQ(rows.size(), all.times.size());
  double best = 1e9;
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t j = i + 1; j < rows.size(); ++j)
      for (std::size_t k = j + 1; k < rows.size(); ++k) {
        if (rows[i].diameter < design.truth.high * (1 - 1e-9)) continue;
        if (rows[k].diameter > design.truth.low * (1 + 1e-9)) continue;
        best =
            std::min(best, score_readings({rows[i], rows[j], rows[k]}, design.truth).worst_error);
      }
  EXPECT_NEAR(design.designed_score.worst_error, best, 1e-9);
  // Every designed time is one a person reads off a clock.
  for (double t : design.designed.times)
    EXPECT_NE(std::find(all.times.begin(), all.times.end(), t), all.times.end()) << t;
}

TEST(DesignSchedule, TheFloorReadsEveryMinuteOverTheStandardsTimes) {
  DesignOptions options;
  options.test = "hydrometer";
  options.size_count = 300;
  const ScheduleDesign design =
      design_schedule(test_setup(short_test()), sample_setup(short_test()), options);
  EXPECT_EQ(design.floor.times, (std::vector<double>{120, 180, 240, 300, 360, 420, 480, 540, 600}));
  // The standard's readings are among the floor's: its score cannot be better at them.
  EXPECT_GE(design.standard_score.worst_error, design.floor_score.worst_error - 1e-9);
}

TEST(DesignSchedule, BadOptionsNameTheValueAndWhatIsAllowed) {
  Scene scene = short_test();
  auto message = [&](DesignOptions o) {
    try {
      check_design_options(test_setup(scene), o);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  DesignOptions o;
  o.test = "sieve";
  EXPECT_EQ(message(o), "--test sieve: allowed hydrometer, buoyancy or pipette");
  o.test = "pipette";
  EXPECT_EQ(message(o),
            "--test pipette: the scene disables it (instruments.pipette.enabled = false)");
  o.test = "hydrometer";
  o.readings = 1;
  EXPECT_EQ(message(o), "--readings 1: allowed 2 to 200 (0: the standard's count)");
  o.readings = 0;
  EXPECT_EQ(message(o), "");
}

}  // namespace
}  // namespace sedem
