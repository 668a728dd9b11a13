// Statistics over seeds, against values computed by hand and from Student-t tables.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "core/stats/seed_statistics.h"

namespace sedem {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(StudentT, QuantilesMatchTheTables) {
  EXPECT_NEAR(student_t_quantile(0.95, 1), 12.7062, 1e-3);
  EXPECT_NEAR(student_t_quantile(0.95, 9), 2.2622, 1e-3);
  EXPECT_NEAR(student_t_quantile(0.95, 30), 2.0423, 1e-3);
  EXPECT_NEAR(student_t_quantile(0.99, 4), 4.6041, 1e-3);
}

TEST(StudentT, OneDegreeOfFreedomIsTheCauchyDistribution) {
  // P(|T| <= t) = 2 atan(t) / pi: exact at any level, even far in the tail.
  for (const double level : {0.5, 0.9, 0.999, 0.999999})
    EXPECT_NEAR(student_t_quantile(level, 1), std::tan(std::numbers::pi * level / 2),
                1e-9 * std::tan(std::numbers::pi * level / 2))
        << level;
}

TEST(StudentT, ManyDegreesOfFreedomApproachTheNormal) {
  EXPECT_NEAR(student_t_quantile(0.95, 100000), 1.959964, 1e-4);
}

TEST(StudentT, RejectsALevelOrDofOutOfRange) {
  EXPECT_THROW(student_t_quantile(0.95, 0), std::invalid_argument);
  EXPECT_THROW(student_t_quantile(1.0, 3), std::invalid_argument);
  EXPECT_THROW(student_t_quantile(0.0, 3), std::invalid_argument);
  EXPECT_THROW(student_t_quantile(kNaN, 3), std::invalid_argument);
}

TEST(MeanInterval, OneToFive) {
  const Interval r = mean_interval({1, 2, 3, 4, 5});
  EXPECT_EQ(r.n, 5u);
  EXPECT_DOUBLE_EQ(r.mean, 3.0);
  EXPECT_NEAR(r.sd, std::sqrt(2.5), 1e-12);
  const double half = 2.7764 * std::sqrt(2.5) / std::sqrt(5.0);  // t(0.95, 4) = 2.7764
  EXPECT_NEAR(r.low, 3 - half, 1e-4);
  EXPECT_NEAR(r.high, 3 + half, 1e-4);
  EXPECT_NEAR(r.half_width(), half, 1e-4);
}

TEST(MeanInterval, SkipsNaN) {
  const Interval with = mean_interval({kNaN, 1, 2, kNaN, 3, 4, 5});
  const Interval without = mean_interval({1, 2, 3, 4, 5});
  EXPECT_EQ(with.n, 5u);
  EXPECT_DOUBLE_EQ(with.mean, without.mean);
  EXPECT_DOUBLE_EQ(with.sd, without.sd);
  EXPECT_DOUBLE_EQ(with.low, without.low);
  EXPECT_DOUBLE_EQ(with.high, without.high);
}

TEST(MeanInterval, OneValueHasAMeanButNoSpread) {
  const Interval r = mean_interval({kNaN, 4.5});
  EXPECT_EQ(r.n, 1u);
  EXPECT_DOUBLE_EQ(r.mean, 4.5);
  EXPECT_TRUE(std::isnan(r.sd));
  EXPECT_TRUE(std::isnan(r.low));
  EXPECT_TRUE(std::isnan(r.high));
  EXPECT_TRUE(std::isnan(r.half_width()));
}

TEST(MeanInterval, NoValueIsAllNaN) {
  for (const auto& values : {std::vector<double>{}, std::vector<double>{kNaN, kNaN}}) {
    const Interval r = mean_interval(values);
    EXPECT_EQ(r.n, 0u);
    EXPECT_TRUE(std::isnan(r.mean));
    EXPECT_TRUE(std::isnan(r.sd));
    EXPECT_TRUE(std::isnan(r.low));
    EXPECT_TRUE(std::isnan(r.high));
  }
}

TEST(MeanInterval, TheLevelWidensTheInterval) {
  // {2, 4}: sd = sqrt(2), t(0.99, 1) = 63.6567: half-width 63.6567 * sqrt(2) / sqrt(2).
  const Interval r = mean_interval({2, 4}, 0.99);
  EXPECT_NEAR(r.half_width(), 63.6567, 1e-3);
  EXPECT_GT(r.half_width(), mean_interval({2, 4}).half_width());
}

TEST(CountForHalfWidth, ByHand) {
  // sd = 1, target 1: t_{n-1} / sqrt(n) is 2.4843 at n = 3, 1.5910 at 4, 1.2417 at 5,
  // 1.0495 at 6 and 0.9249 at 7.
  EXPECT_EQ(count_for_half_width(1.0, 1.0), 7u);
  // sd = 2, target 0.5: 2 t_62 / sqrt(63) = 2 * 1.99897 / 7.93725 = 0.5037 > 0.5, and
  // 2 t_63 / sqrt(64) = 2 * 1.99834 / 8 = 0.4996.
  EXPECT_EQ(count_for_half_width(2.0, 0.5), 64u);
  // No spread: the smallest sample that has an interval.
  EXPECT_EQ(count_for_half_width(0.0, 0.1), 2u);
}

TEST(CountForHalfWidth, NothingToAimAt) {
  EXPECT_EQ(count_for_half_width(kNaN, 1.0), 0u);
  EXPECT_EQ(count_for_half_width(1.0, 0.0), 0u);
  EXPECT_EQ(count_for_half_width(1.0, -1.0), 0u);
  // 1.96 / sqrt(1e6) = 0.00196: a tenth of it is out of reach.
  EXPECT_EQ(count_for_half_width(1.0, 0.000196), 0u);
}

}  // namespace
}  // namespace sedem
