// The measures behind the validation report, on curves small enough to work out by hand.
#include <gtest/gtest.h>

#include "bench/validation/curve_checks.h"
#include "tests/validation/validation_test_support.h"

namespace sedem::validation {
namespace {

using testing::curve;
using testing::linear_sample;

TEST(CurveChecks, RoughnessIsZeroForAStraightLineAndTheRmsOfSecondDifferencesOtherwise) {
  // Readings in time order: the diameter falls; roughness orders them by diameter.
  EXPECT_NEAR(roughness(curve("t", {{1, 40, 80}, {2, 30, 60}, {3, 20, 40}, {4, 10, 20}})), 0.0,
              1e-12);
  // w = 0, 10, 0, 10 along the diameter: second differences -20 and +20, RMS 20.
  EXPECT_NEAR(roughness(curve("t", {{1, 40, 10}, {2, 30, 0}, {3, 20, 10}, {4, 10, 0}})), 20.0,
              1e-12);
  EXPECT_EQ(roughness(curve("t", {{1, 40, 10}, {2, 30, 0}})), 0.0);
}

TEST(CurveChecks, ExcessVariationIsTwiceEachWiggleAndZeroWhenMonotone) {
  EXPECT_NEAR(excess_variation(curve("t", {{1, 40, 90}, {2, 30, 60}, {3, 20, 60}, {4, 10, 5}})),
              0.0, 1e-12);
  // Along the diameter 0, 10, 5, 20: travels 30 where a monotone curve travels 20; the dip
  // of 5 counts twice.
  EXPECT_NEAR(excess_variation(curve("t", {{1, 40, 20}, {2, 30, 5}, {3, 20, 10}, {4, 10, 0}})),
              10.0, 1e-12);
}

TEST(CurveChecks, TrueCurveRebuiltFromItsPointsIsAStepFunction) {
  const auto classes =
      classes_from_true_curve({{40e-6, 100.0}, {10e-6, 20.0}, {20e-6, 50.0}});  // any order
  ASSERT_EQ(classes.size(), 3u);
  EXPECT_NEAR(classes[0].mass_fraction, 0.2, 1e-12);
  EXPECT_NEAR(classes[1].mass_fraction, 0.3, 1e-12);
  EXPECT_NEAR(classes[2].mass_fraction, 0.5, 1e-12);
  // 15 um holds the 10 um grains only (20 %): a test reading 15 % there is 5 pp low.
  const auto dev = deviations_from_truth(curve("t", {{60, 15, 15}, {120, 30, 55}}), classes);
  ASSERT_EQ(dev.size(), 2u);
  EXPECT_NEAR(dev[0], -5.0, 1e-9);
  EXPECT_NEAR(dev[1], 5.0, 1e-9);
}

TEST(CurveChecks, FiltersKeepTheLargeSizesAndTheEarlyReadings) {
  const auto c = curve("t", {{30, 70, 100}, {60, 40, 80}, {120, 25, 60}, {900, 12, 30}});
  const auto large = large_sizes(c, 24e-6);
  ASSERT_EQ(large.rows.size(), 3u);
  EXPECT_DOUBLE_EQ(large.rows.back().diameter, 25 * 1e-6);
  const auto early = up_to(c, 120);
  ASSERT_EQ(early.rows.size(), 3u);
  EXPECT_DOUBLE_EQ(early.rows.back().time, 120);
  EXPECT_EQ(large.test, "t");
}

TEST(CurveChecks, SummariesOfDeviations) {
  const std::vector<double> v{-3, 1, 2};
  EXPECT_NEAR(mean(v), 0.0, 1e-12);
  EXPECT_NEAR(mean_abs(v), 2.0, 1e-12);
  EXPECT_NEAR(max_abs(v), 3.0, 1e-12);
  EXPECT_NEAR(root_mean_square(v), std::sqrt(14.0 / 3.0), 1e-12);
  EXPECT_EQ(mean({}), 0.0);
  EXPECT_THROW(differences(curve("a", {{1, 10, 1}}), curve("b", {})), std::invalid_argument);
}

TEST(CurveChecks, RankCorrelation) {
  EXPECT_NEAR(rank_correlation({1, 2, 3, 4}, {1, 4, 9, 16}), 1.0, 1e-12);  // monotone
  EXPECT_NEAR(rank_correlation({1, 2, 3, 4}, {8, 4, 2, 1}), -1.0, 1e-12);  // reversed
  EXPECT_NEAR(rank_correlation({1, 2, 3}, {5, 5, 5}), 0.0, 1e-12);         // constant
  // Ranks x = 0 1 2, y = 0.5 0.5 2 (a tie): r = 1.5 / sqrt(2 * 1.5) = sqrt(3)/2.
  EXPECT_NEAR(rank_correlation({1, 2, 3}, {1, 1, 7}), std::sqrt(3.0) / 2, 1e-12);
  EXPECT_NEAR(linear_sample().back().diameter, 70e-6, 1e-18);
}

}  // namespace
}  // namespace sedem::validation
