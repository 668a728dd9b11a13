// The paper's conclusions turned into verdicts, on hand-made runs whose answer is known.
#include <gtest/gtest.h>

#include "bench/validation/checks.h"
#include "core/physics/stokes.h"
#include "tests/validation/validation_test_support.h"

namespace sedem::validation {
namespace {

using testing::curve;
using testing::run;
using testing::run_test;

// The true curve of testing::linear_sample() at the given diameters (um), as readings at
// times 1, 2, ...
TestReadings truth_curve(const std::string& test, const std::vector<double>& diameters_um) {
  std::vector<std::tuple<double, double, double>> points;
  for (std::size_t k = 0; k < diameters_um.size(); ++k)
    points.emplace_back(double(k + 1), diameters_um[k], 100.0 * diameters_um[k] / 70.0);
  return curve(test, points);
}

TestReadings shifted(TestReadings c, const std::vector<double>& by) {
  for (std::size_t k = 0; k < c.rows.size(); ++k) c.rows[k].percent_finer += by[k];
  return c;
}

TEST(Checks, SmallSizesAgainstLargeSizes) {
  // 50 and 30 um are large (off by 6 and 2 pp), 10 um small (off by 1 pp).
  const auto truth = truth_curve("pipette", {50, 30, 10});
  const RunFolder r = run("s", {run_test(shifted(truth, {6, -2, 1}), truth)});
  const auto rows = size_range_rows({r});
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].large_readings, 2u);
  EXPECT_EQ(rows[0].small_readings, 1u);
  EXPECT_NEAR(rows[0].large_deviation, 4.0, 1e-9);
  EXPECT_NEAR(rows[0].small_deviation, 1.0, 1e-9);
  EXPECT_EQ(size_range_verdict(rows), Verdict::supports);
  const RunFolder worse = run("s", {run_test(shifted(truth, {0, 1, 9}), truth)});
  EXPECT_EQ(size_range_verdict(size_range_rows({worse})), Verdict::contradicts);
  const auto large_only = truth_curve("pipette", {50, 30});
  const RunFolder early = run("s", {run_test(large_only, large_only)});
  EXPECT_EQ(size_range_verdict(size_range_rows({early})), Verdict::inconclusive);
}

TEST(Checks, SmoothingSupportedWhenTheHydrometerIsSmootherThanTheTruthAndTheOthers) {
  // A kinked truth (100 % above 45 um, 10 % per 10 um below), read at 60 ... 20 um: along
  // the diameter 20, 30, 40, 100, 100; second differences 0, 50, -60, roughness 45.09.
  // The hydrometer reads a straight chord (roughness 0), buoyancy and pipette bend.
  std::vector<RunFolder> runs;
  for (const char* name : {"s1", "s2", "s3"}) {
    RunFolder r = run(name, {});
    r.classes = classes_from_true_curve(  // as curve() makes diameters: a reading falls on a class
        {{10 * 1e-6, 10}, {20 * 1e-6, 20}, {30 * 1e-6, 30}, {40 * 1e-6, 40}, {45 * 1e-6, 100}});
    const auto hyd =
        curve("hydrometer", {{1, 60, 100}, {2, 50, 85}, {3, 40, 70}, {4, 30, 55}, {5, 20, 40}});
    const auto buoy =
        curve("buoyancy", {{1, 60, 100}, {2, 50, 90}, {3, 40, 45}, {4, 30, 30}, {5, 20, 25}});
    auto pip = shifted(buoy, {0, 5, 0, 5, 0});
    pip.test = "pipette";
    r.tests = {run_test(hyd, hyd), run_test(buoy, buoy), run_test(pip, pip)};
    runs.push_back(r);
  }
  const auto rows = smoothing_rows(runs);
  ASSERT_EQ(rows.size(), 9u);
  EXPECT_EQ(rows[0].test, "hydrometer");
  EXPECT_NEAR(rows[0].roughness, 0.0, 1e-12);
  EXPECT_NEAR(rows[0].truth_roughness, std::sqrt(6100.0 / 3), 1e-9);
  EXPECT_NEAR(rows[1].roughness, std::sqrt(2225.0 / 3), 1e-9);  // 10, 30, -35
  EXPECT_NEAR(rows[2].roughness, std::sqrt(3625.0 / 3), 1e-9);  // 0, 40, -45
  EXPECT_EQ(smoothing_verdict(rows), Verdict::supports);
}

TEST(Checks, SmoothingContradictedWhenTheHydrometerIsTheRoughest) {
  std::vector<SmoothingRow> rows;
  for (const char* s : {"s1", "s2"}) {
    rows.push_back({s, "hydrometer", 9, 4, 0});  // rougher than the truth
    rows.push_back({s, "buoyancy", 2, 4, 0});
    rows.push_back({s, "pipette", 3, 4, 0});
  }
  EXPECT_EQ(smoothing_verdict(rows), Verdict::contradicts);
  rows[0].roughness = 1;  // one sample each way: no majority
  EXPECT_EQ(smoothing_verdict(rows), Verdict::inconclusive);
}

TEST(Checks, OscillationIsTheScatterAroundTheReferenceAtLargeSizes) {
  // Readings at 70, 50, 30 um (large) and 10 um (small). The buoyancy and pipette DEM curves
  // swing +-3 pp around their reference at large sizes; the hydrometer follows its own.
  const auto ref = truth_curve("buoyancy", {70, 50, 30, 10});
  const auto wobbly = shifted(ref, {3, -3, 3, 40});  // the small-size reading does not count
  auto hyd_ref = truth_curve("hydrometer", {70, 50, 30, 10});
  RunFolder r = run("s", {run_test(hyd_ref, hyd_ref), run_test(wobbly, ref)});
  TestReadings pip = wobbly, pip_ref = ref;
  pip.test = pip_ref.test = "pipette";
  r.tests.push_back(run_test(pip, pip_ref));
  const auto rows = oscillation_rows({r});
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[1].readings, 3u);
  EXPECT_NEAR(rows[1].scatter, 3.0, 1e-9);
  EXPECT_NEAR(rows[0].scatter, 0.0, 1e-9);
  // Along the diameter (30, 50, 70 um): 45.86, 68.43, 103 -> monotone, so no excess; one
  // reading above 100 %.
  EXPECT_NEAR(rows[1].excess, 0.0, 1e-9);
  EXPECT_EQ(rows[1].above_100, 1u);
  EXPECT_EQ(oscillation_verdict(rows), Verdict::supports);

  // All three equally calm: contradicts.
  RunFolder calm = run("s", {run_test(hyd_ref, hyd_ref), run_test(ref, ref)});
  calm.tests.push_back(run_test(pip_ref, pip_ref));
  EXPECT_EQ(oscillation_verdict(oscillation_rows({calm})), Verdict::contradicts);
}

TEST(Checks, LargeSizesOverpredictedWhenTheTestsReadLessFinerThanTheTruth) {
  const auto truth = truth_curve("hydrometer", {60, 40, 10});
  RunFolder r = run("s", {});
  r.scene["sample.weighting"] = "equal_mass";
  r.particle_count = 500;
  for (const char* test : {"hydrometer", "buoyancy", "pipette"}) {
    auto t = truth;
    t.test = test;
    r.tests.push_back(run_test(shifted(t, {-2, -4, +30}), t));  // +30 at 10 um: not large
  }
  const auto rows = large_size_rows({r});
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].weighting, "equal_mass");
  EXPECT_EQ(rows[0].particles, 500u);
  EXPECT_EQ(rows[0].readings, 2u);
  EXPECT_NEAR(rows[0].dem_deviation, -3.0, 1e-9);
  EXPECT_NEAR(rows[0].reference_deviation, 0.0, 1e-9);
  EXPECT_EQ(large_size_verdict(rows), Verdict::supports);

  for (auto& t : r.tests) t.dem = shifted(t.reference, {2, 4, 0});
  EXPECT_EQ(large_size_verdict(large_size_rows({r})), Verdict::contradicts);
}

TEST(Checks, DepthTrendFromTheSameSampleReadAtSeveralDepths) {
  std::vector<RunFolder> runs;
  for (double fraction : {0.1, 0.3, 0.5}) {
    const auto truth = truth_curve("buoyancy", {50, 30, 10});
    const double off = 10 * fraction;  // deeper: further from the truth
    RunFolder r = run("s", {run_test(shifted(truth, {off, -off, off}), truth)});
    r.scene["instruments.buoyancy.depth_fraction"] = fraction;
    r.tests[0].depth_m = fraction * 0.457;
    runs.push_back(r);
  }
  const auto rows = depth_rows(runs);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_DOUBLE_EQ(rows[0].depth_fraction, 0.1);
  EXPECT_NEAR(rows[0].mean_abs_deviation, 1.0, 1e-9);
  EXPECT_NEAR(rows[2].max_abs_deviation, 5.0, 1e-9);
  EXPECT_NEAR(depth_trend(rows), 1.0, 1e-12);
  EXPECT_NEAR(rows[2].reference_mean_abs_deviation, 0.0, 1e-9);  // the reference is the truth
  EXPECT_EQ(depth_trend(rows, true), 0.0);                       // no trend in a constant
  EXPECT_EQ(depth_verdict(rows), Verdict::supports);

  std::reverse(runs.begin(), runs.end());  // the same deviations, now shallow is worse
  for (std::size_t k = 0; k < runs.size(); ++k)
    runs[k].scene["instruments.buoyancy.depth_fraction"] = 0.1 + 0.2 * double(k);
  EXPECT_EQ(depth_verdict(depth_rows(runs)), Verdict::contradicts);
}

TEST(Checks, ProfileGapToEq16PerThirdOfTheColumn) {
  // At 900 s Eq. 16 stays below the largest grain (70 um) down to the bottom. The profile
  // follows it at 5 cm, is 10 % short at 20 cm and 50 % short at 40 cm.
  RunFolder r = run("s", {});
  RunProfile p;
  p.time_s = 900;
  const std::vector<double> depth{0.05, 0.2, 0.4}, share{1.0, 0.9, 0.5};
  for (std::size_t k = 0; k < depth.size(); ++k) {
    p.depth_m.push_back(depth[k]);
    p.largest_diameter_m.push_back(share[k] * stokes::limiting_diameter(depth[k], 900, 2500, {}));
  }
  r.profiles = {p};
  auto rows = profile_gap_rows({r});
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_NEAR(rows[0].upper, 0.0, 1e-12);
  EXPECT_NEAR(rows[0].middle, 0.1, 1e-12);
  EXPECT_NEAR(rows[0].lower, 0.5, 1e-12);
  // At 60 s Eq. 16 passes 70 um above 40 cm: that depth says nothing.
  r.profiles[0].time_s = 60;
  rows = profile_gap_rows({r});
  EXPECT_TRUE(std::isnan(rows[0].lower));
  EXPECT_FALSE(std::isnan(rows[0].upper));
}

TEST(Checks, EarlyReadingsAndReducedRunsWithinTheReasonableError) {
  const auto ref = truth_curve("pipette", {70, 50, 30, 10});
  RunFolder full = run("s", {run_test(shifted(ref, {1, 2, 9, 20}), ref)});
  full.particle_count = 1000;
  full.wall_time_s = 40;
  // Up to t = 2 s: errors 1 and 2 pp; the whole run's error is 20 pp.
  const auto early = early_rows({full}, 2.0);
  ASSERT_EQ(early.size(), 1u);
  EXPECT_EQ(early[0].early_readings, 2u);
  EXPECT_NEAR(early[0].early_error, 2.0, 1e-12);
  EXPECT_NEAR(early[0].error, 20.0, 1e-12);
  EXPECT_NEAR(early[0].early_smallest_diameter, 50e-6, 1e-18);
  EXPECT_NEAR(early[0].smallest_diameter, 10e-6, 1e-18);

  RunFolder small = run("s", {run_test(shifted(ref, {3, 3, 3, 3}), ref)});
  small.particle_count = 250;
  small.wall_time_s = 10;
  const auto reduced = reduced_rows({full}, {small});
  ASSERT_EQ(reduced.size(), 1u);
  EXPECT_EQ(reduced[0].reduced_particles, 250u);
  EXPECT_NEAR(reduced[0].reduced_error, 3.0, 1e-12);
  EXPECT_NEAR(reduced[0].error, 20.0, 1e-12);
  EXPECT_EQ(early_reduced_verdict(early, reduced), Verdict::supports);

  // Up to t = 4 s everything counts: 20 pp early; a reduced run 12 pp off.
  RunFolder bad = run("s", {run_test(shifted(ref, {12, 0, 0, 0}), ref)});
  EXPECT_EQ(early_reduced_verdict(early_rows({full}, 4.0), reduced_rows({full}, {bad})),
            Verdict::contradicts);
  EXPECT_EQ(early_reduced_verdict(early_rows({full}, 0.5), {}), Verdict::inconclusive);
}

}  // namespace
}  // namespace sedem::validation
