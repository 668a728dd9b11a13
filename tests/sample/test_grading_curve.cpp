#include <gtest/gtest.h>

#include <cmath>

#include "core/sample/grading_curve.h"

namespace sedem {
namespace {

GradingConfig table(std::vector<double> d_um, std::vector<double> percent) {
  GradingConfig g;
  g.family = "table";
  g.diameters.clear();
  for (double d : d_um) g.diameters.push_back(d * 1e-6);
  g.percent_finer = std::move(percent);
  return g;
}

TEST(GradingCurve, TableIsLinearInLogDiameter) {
  const GradingCurve c(table({2.5, 5, 10, 20, 60, 65, 70}, {0, 15, 40, 60, 60, 80, 100}));
  EXPECT_NEAR(c.percent_finer(5e-6), 15, 1e-12);
  // The geometric mean of 5 and 10 um is half way in log d: half way between 15 and 40.
  EXPECT_NEAR(c.percent_finer(std::sqrt(50.0) * 1e-6), 27.5, 1e-12);
  // A quarter of the way from 10 to 20 um in log d.
  EXPECT_NEAR(c.percent_finer(10e-6 * std::pow(2.0, 0.25)), 45.0, 1e-12);
  EXPECT_DOUBLE_EQ(c.percent_finer(40e-6), 60);  // the plateau
  EXPECT_DOUBLE_EQ(c.percent_finer(1e-6), 0);
  EXPECT_NEAR(c.percent_finer(2.5e-6), 0, 1e-12);
  EXPECT_DOUBLE_EQ(c.percent_finer(70e-6), 100);
  EXPECT_DOUBLE_EQ(c.percent_finer(1e-3), 100);
  EXPECT_DOUBLE_EQ(c.min_diameter(), 2.5 * 1e-6);
  EXPECT_DOUBLE_EQ(c.max_diameter(), 70e-6);
}

TEST(GradingCurve, LogUniformHasHalfItsMassBelowTheGeometricMean) {
  GradingConfig g;
  g.family = "log_uniform";
  g.min_diameter = 2.5e-6;
  g.max_diameter = 70e-6;
  const GradingCurve c(g);
  EXPECT_NEAR(c.percent_finer(std::sqrt(2.5e-6 * 70e-6)), 50, 1e-10);
  EXPECT_NEAR(c.percent_finer(2.5e-6 * std::pow(28.0, 0.1)), 10, 1e-10);
  EXPECT_DOUBLE_EQ(c.captured_share(), 1);
}

TEST(GradingCurve, LogNormalTruncatedSymmetricallyKeepsItsMedian) {
  GradingConfig g;
  g.family = "log_normal";
  g.median_diameter = 10e-6;
  g.spread = 0.5;
  g.min_diameter = 10e-6 / 4;
  g.max_diameter = 10e-6 * 4;
  const GradingCurve c(g);
  EXPECT_NEAR(c.percent_finer(10e-6), 50, 1e-10);
  // Within +-ln 4 = 2.77 sigma the normal holds erf(2.77 / sqrt 2) of its mass.
  EXPECT_NEAR(c.captured_share(), std::erf(std::log(4.0) / 0.5 / std::sqrt(2.0)), 1e-12);
  // One sigma above the median: Phi(1) renormalised to the truncated range.
  const double phi1 = 0.5 * std::erfc(-1 / std::sqrt(2.0));
  const double lo = 0.5 * std::erfc(std::log(4.0) / 0.5 / std::sqrt(2.0));
  EXPECT_NEAR(c.percent_finer(10e-6 * std::exp(0.5)), 100 * (phi1 - lo) / c.captured_share(),
              1e-10);
}

TEST(GradingCurve, RosinRammlerHas63PercentBelowItsScale) {
  GradingConfig g;
  g.family = "rosin_rammler";
  g.median_diameter = 20e-6;
  g.spread = 2;
  g.min_diameter = 1e-9;  // wide enough that truncation changes nothing visible
  g.max_diameter = 1e-3;
  const GradingCurve c(g);
  EXPECT_NEAR(c.percent_finer(20e-6), 100 * (1 - std::exp(-1.0)), 1e-6);
  EXPECT_NEAR(c.percent_finer(10e-6), 100 * (1 - std::exp(-0.25)), 1e-6);
}

TEST(GradingCurve, SingleSizeStepsFrom0To100) {
  GradingConfig g;
  g.family = "single";
  g.diameter = 30e-6;
  const GradingCurve c(g);
  EXPECT_DOUBLE_EQ(c.min_diameter(), 30e-6);
  EXPECT_DOUBLE_EQ(c.max_diameter(), 30e-6);
  EXPECT_DOUBLE_EQ(c.percent_finer(29.9e-6), 0);
  EXPECT_DOUBLE_EQ(c.percent_finer(30e-6), 100);
}

}  // namespace
}  // namespace sedem
