#pragma once

#include <gtest/gtest.h>

#include <vector>

#include "core/lab/hydrometer_reduction.h"

namespace sedem::test {

// test_lab_reduction.cpp's worked example: 50 g of Gs 2.70 soil at 22 C, composite
// correction 5 g/L, R = 42, 20, 10 at 2, 60 and 1440 min. By hand (D7928): diameters
// 2.844172e-5, 6.108348e-6, 1.323117e-6 m; percent finer 73.178690, 29.667037, 9.889012.
inline constexpr double kWorkedDiameter[] = {2.844172e-5, 6.108348e-6, 1.323117e-6};
inline constexpr double kWorkedPercent[] = {73.178690, 29.667037, 9.889012};

// `readings`, however they were read, reduce to the worked example's hand computation.
inline void expect_worked_example(const std::vector<LabReading>& readings) {
  ASSERT_EQ(readings.size(), 3u);
  const auto points = reduce_lab_readings(readings, {2.70, 50e-3}, LabMethod::d7928);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(points[i].diameter, kWorkedDiameter[i], 2e-6 * kWorkedDiameter[i]) << i;
    EXPECT_NEAR(points[i].percent_finer, kWorkedPercent[i], 1e-6) << i;
  }
}

}  // namespace sedem::test
