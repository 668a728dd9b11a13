// The true grading curve, the error (DEM against reference) and the bias (reference
// against the true curve), kept apart.
#include <gtest/gtest.h>

#include <cmath>

#include "core/instruments/granulometry.h"

namespace sedem {
namespace {

std::vector<SizeClass> three_classes() {
  // 10 um: 20 %, 20 um: 30 %, 40 um: 50 % of the mass (given out of order on purpose).
  std::vector<SizeClass> c(3);
  c[0].diameter = 20e-6;
  c[0].mass_fraction = 0.3;
  c[1].diameter = 10e-6;
  c[1].mass_fraction = 0.2;
  c[2].diameter = 40e-6;
  c[2].mass_fraction = 0.5;
  return c;
}

TEST(Granulometry, TrueCurveAtTheClassDiameters) {
  const auto curve = true_grading_curve(three_classes());
  ASSERT_EQ(curve.size(), 3u);
  EXPECT_DOUBLE_EQ(curve[0].diameter, 10e-6);
  EXPECT_NEAR(curve[0].percent_finer, 20.0, 1e-12);
  EXPECT_NEAR(curve[1].percent_finer, 50.0, 1e-12);
  EXPECT_NEAR(curve[2].percent_finer, 100.0, 1e-12);
  // A step function between them: grains of diameter <= d.
  EXPECT_NEAR(true_percent_finer(three_classes(), 5e-6), 0.0, 1e-12);
  EXPECT_NEAR(true_percent_finer(three_classes(), 15e-6), 20.0, 1e-12);
  EXPECT_NEAR(true_percent_finer(three_classes(), 20e-6), 50.0, 1e-12);
  EXPECT_NEAR(true_percent_finer(three_classes(), 1e-3), 100.0, 1e-12);
}

TestReadings curve(const std::string& name, std::vector<Reading> rows) {
  TestReadings t;
  t.test = name;
  t.rows = std::move(rows);
  return t;
}

TEST(Granulometry, ErrorAndBiasAreKeptApart) {
  // Reference: at 60 s phi_o = 30 um reads 52 % (truth 50: 2 points of bias); at 600 s
  // phi_o = 12 um reads 17 % (truth 20: 3 points). DEM: 55 % and 16 %, so the error is
  // max(|55 - 52|, |16 - 17|) = 3 points, the bias max(2, 3) = 3 points, from other pairs.
  const auto ref = curve("pipette", {{60, 30e-6, 52, {}}, {600, 12e-6, 17, {}}});
  const auto dem = curve("pipette", {{60, 30e-6, 55, {}}, {600, 12e-6, 16, {}}});
  EXPECT_NEAR(curve_error(dem, ref), 3.0, 1e-12);
  EXPECT_NEAR(curve_bias(ref, three_classes()), 3.0, 1e-12);
  const auto dem2 = curve("pipette", {{60, 30e-6, 52.5, {}}, {600, 12e-6, 17, {}}});
  EXPECT_NEAR(curve_error(dem2, ref), 0.5, 1e-12);

  const Granulometry g = compare({dem2}, {ref}, three_classes());
  ASSERT_EQ(g.tests.size(), 1u);
  EXPECT_NEAR(g.tests[0].error, 0.5, 1e-12);
  EXPECT_NEAR(g.tests[0].bias, 3.0, 1e-12);
  EXPECT_EQ(g.true_curve.size(), 3u);
}

TEST(Granulometry, ATestWithoutReadingsHasNoErrorAndNoBias) {
  // The run ended before the test's first reading: its figures are unknown, never a perfect 0.
  const auto none = curve("hydrometer", {});
  EXPECT_TRUE(std::isnan(curve_error(none, none)));
  EXPECT_TRUE(std::isnan(curve_bias(none, three_classes())));
  const Granulometry g = compare({none}, {none}, three_classes());
  ASSERT_EQ(g.tests.size(), 1u);
  EXPECT_TRUE(std::isnan(g.tests[0].error));
  EXPECT_TRUE(std::isnan(g.tests[0].bias));
}

TEST(Granulometry, DifferentTimesAreRefused) {
  const auto ref = curve("hydrometer", {{60, 30e-6, 52, {}}});
  const auto dem = curve("hydrometer", {{120, 30e-6, 52, {}}});
  EXPECT_THROW(curve_error(dem, ref), std::invalid_argument);
  EXPECT_THROW(compare({dem}, {}, three_classes()), std::invalid_argument);
}

}  // namespace
}  // namespace sedem
