// Where the readings cannot tell the curve (InvertedCurve::open_at), on hand-made curves whose
// answer follows from the rule: a rise of more than open_rise between two readings' diameters
// that the strict bounds do not hold within open_width.
#include <gtest/gtest.h>

#include "core/invert/inversion.h"

namespace sedem::invert {
namespace {

// Readings pinned at 10, 20 and 40 um, each seeing sizes 5 % either side of its pin; the
// curve, linear in log d between nodes, is 5 % at 10 um, 15 % at 20 um and 80 % at 40 um: a
// knee of 65 pp between the two coarser readings, 20 pp above the coarsest (to 100 %).
InvertedCurve knee_between_readings() {
  InvertedCurve c;
  c.diameter = {5e-6, 10e-6, 20e-6, 30e-6, 40e-6, 80e-6};
  c.percent_finer = {0, 5, 15, 50, 80, 100};
  c.reading_diameter = {40e-6, 10e-6, 20e-6};  // in the readings' order, not sorted
  for (const double d : c.reading_diameter) c.reading_window.push_back({0.95 * d, 1.05 * d});
  c.open_rise = 50;
  c.open_width = 10;
  return c;
}

TEST(OpenRule, AKneeBetweenTwoReadingsIsOpenBetweenThemAndInTheirWindows) {
  const InvertedCurve c = knee_between_readings();
  EXPECT_TRUE(c.open_at(30e-6));    // inside the 65 pp rise
  EXPECT_TRUE(c.open_at(20.5e-6));  // the 20 um reading's window reaches into it
  EXPECT_TRUE(c.open_at(19.5e-6));  // ... on both sides of its pin: it averages over both
  EXPECT_TRUE(c.open_at(41e-6));    // and the 40 um reading's, above its pin
  EXPECT_FALSE(c.open_at(18e-6));   // below the window: 10 pp between 10 and 20 um
  EXPECT_FALSE(c.open_at(10e-6));
  EXPECT_FALSE(c.open_at(50e-6));  // above the coarsest: 20 pp to 100 %
  // The diameters open within the resolved ones: one range, from the 20 um window's lower
  // edge to the 40 um window's upper edge, as the grid's nodes give it.
  InvertedCurve fine = c;
  fine.diameter.clear();
  fine.percent_finer.clear();
  for (double d = 8e-6; d < 50e-6; d *= 1.01) {
    fine.diameter.push_back(d);
    fine.percent_finer.push_back(c.at(d));
  }
  fine.resolved_min = 10e-6;
  fine.resolved_max = 40e-6;
  const auto ranges = fine.open_ranges();
  ASSERT_EQ(ranges.size(), 1u);
  EXPECT_NEAR(ranges[0].first, 19e-6, 0.2e-6);
  EXPECT_NEAR(ranges[0].second, 40e-6, 0.5e-6);
}

TEST(OpenRule, TheEndsCountAsReadingsOf0And100Percent) {
  InvertedCurve c = knee_between_readings();
  c.percent_finer = {0, 5, 15, 20, 30, 100};  // 30 % at the coarsest: 70 pp above it
  EXPECT_TRUE(c.open_at(60e-6));
  EXPECT_TRUE(c.open_at(39e-6));               // in the coarsest reading's window
  EXPECT_FALSE(c.open_at(30e-6));              // 15 pp between 20 and 40 um
  c.percent_finer = {0, 60, 70, 75, 80, 100};  // 60 % at the finest: 60 pp below it
  EXPECT_TRUE(c.open_at(7e-6));
  EXPECT_TRUE(c.open_at(10.2e-6));
  EXPECT_FALSE(c.open_at(15e-6));
}

TEST(OpenRule, BoundsThatHoldTheCurveCloseIt) {
  InvertedCurve c = knee_between_readings();
  // Bounds at 30 um 8 pp wide: the readings hold the curve there whatever the rise does.
  c.bound_diameter = {20e-6, 30e-6, 40e-6};
  c.bound_lower = {12, 46, 76};
  c.bound_upper = {18, 54, 84};
  EXPECT_FALSE(c.open_at(30e-6));
  // Between 30 and 40 um the bounds are taken from the nodes around: 46 to 84, 38 pp.
  EXPECT_TRUE(c.open_at(35e-6));
  c.open_width = 40;
  EXPECT_FALSE(c.open_at(35e-6));
  c.open_rise = 70;  // no rise between readings over 70 pp: nothing open
  c.open_width = 0;
  EXPECT_FALSE(c.open_at(35e-6));
}

}  // namespace
}  // namespace sedem::invert
