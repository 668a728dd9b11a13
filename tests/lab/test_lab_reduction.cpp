// Reduction of laboratory hydrometer readings (ASTM D422 and the D7928 form) against a
// worked example computed by hand from the standards' formulas, and the rejection of
// invalid readings.
#include <gtest/gtest.h>

#include <string>

#include "core/lab/hydrometer_reduction.h"
#include "core/lab/water.h"

namespace sedem {
namespace {

TEST(Water, ViscosityAndDensityAtReferenceTemperatures) {
  // Vogel: 2.414e-5 * 10^(247.8 / 153.15) = 1.001749e-3 Pa*s at 20 C (IAPWS: 1.0016e-3).
  EXPECT_NEAR(water::viscosity(20.0), 1.001749e-3, 1e-9);
  EXPECT_NEAR(water::viscosity(20.0), 1.0016e-3, 0.003 * 1.0016e-3);
  // Tanaka et al. 2001: 998.2067 at 20 C; maximum 999.9750 near 3.98 C.
  EXPECT_NEAR(water::density(20.0), 998.2067, 1e-4);
  EXPECT_NEAR(water::density(3.983035), 999.974950, 1e-9);
}

// Worked example: 50 g of oven-dry soil, Gs = 2.70, suspension at 22 C, composite
// correction 5 g/L, 152H read at 2, 60 and 1440 min: R = 42, 20, 10.
//   mu(22 C) = 2.414e-5 * 10^(247.8 / 155.15) = 9.547756e-4 Pa*s = 9.547756e-3 poise
//   rho_w(22 C) = 997.77298 kg/m^3 -> G1 = 0.99777298
//   K = sqrt(30 * 9.547756e-3 / (980 * (2.70 - 0.99777298))) = 0.01310357
//   a = 1.65 * 2.70 / (1.70 * 2.65) = 0.98890122
//   R = 42: L = 16.29 - 0.164 * 42 = 9.402 cm, D = K sqrt(9.402 / 2) = 0.02841088 mm,
//           P = (42 - 5) * 0.98890122 / 50 * 100 = 73.178690 %
//   R = 20: L = 13.01 cm, D = K sqrt(13.01 / 60) = 0.006101723 mm, P = 29.667037 %
//   R = 10: L = 14.65 cm, D = K sqrt(14.65 / 1440) = 0.001321682 mm, P = 9.889012 %
// D7928 form: rho_s = 2.70 * 998.20675 = 2695.15822, D = sqrt(18 mu L / ((rho_s - rho_w) g t))
//   R = 42: sqrt(18 * 9.547756e-4 * 0.09402 / (1697.38524 * 9.80665 * 120)) = 2.844172e-5 m
//   R = 20: 6.108348e-6 m; R = 10: 1.323117e-6 m.
std::vector<LabReading> worked_example() {
  return {{120.0, 42.0, 22.0, 5.0}, {3600.0, 20.0, 22.0, 5.0}, {86400.0, 10.0, 22.0, 5.0}};
}

TEST(LabReduction, AstmD422WorkedExample) {
  const LabSpecimen specimen{2.70, 50e-3};
  const auto points = reduce_astm_d422(worked_example(), specimen);
  ASSERT_EQ(points.size(), 3u);
  const double diameter_mm[] = {0.02841088, 0.006101723, 0.001321682};
  const double percent[] = {73.178690, 29.667037, 9.889012};
  const double depth_cm[] = {9.402, 13.01, 14.65};
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(points[i].diameter * 1e3, diameter_mm[i], 2e-6 * diameter_mm[i]) << i;
    EXPECT_NEAR(points[i].percent_finer, percent[i], 1e-6) << i;
    EXPECT_NEAR(points[i].effective_depth * 1e2, depth_cm[i], 1e-12) << i;
    EXPECT_NEAR(points[i].corrected_reading, worked_example()[i].reading - 5.0, 1e-12);
  }
}

TEST(LabReduction, AstmD7928WorkedExample) {
  const LabSpecimen specimen{2.70, 50e-3};
  const auto points = reduce_astm_d7928(worked_example(), specimen);
  const double diameter_m[] = {2.844172e-5, 6.108348e-6, 1.323117e-6};
  const double percent[] = {73.178690, 29.667037, 9.889012};
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(points[i].diameter, diameter_m[i], 2e-6 * diameter_m[i]) << i;
    EXPECT_NEAR(points[i].percent_finer, percent[i], 1e-6) << i;
  }
}

// The bulb's depth from the reading corrected for the meniscus only, the composite
// correction the concentration's only; the percent finer of the mass per litre. With C_m =
// 1 g/L on the worked example's R = 42, C = 5: L = 16.29 - 0.164 x 43 = 9.238 cm (not from
// R - C = 37: 10.222 cm), D = K sqrt(9.238 / 2) = 0.02816201 mm; 50 g in 500 mL is 100 g/L:
// P = 37 x 0.98890122 / 100 x 100 = 36.589345 %. D7928 the same depth:
// sqrt(18 x 9.547756e-4 x 0.09238 / (1697.38524 x 9.80665 x 120)) = 2.819257e-5 m.
TEST(LabReduction, DepthFromTheReadingPercentOfTheMassPerLitre) {
  auto readings = worked_example();
  for (auto& r : readings) r.meniscus_correction = 1.0;
  const LabSpecimen specimen{2.70, 50e-3, 0.5e-3};
  const auto d422 = reduce_lab_readings(readings, specimen, LabMethod::d422);
  EXPECT_NEAR(d422[0].effective_depth * 1e2, 9.238, 1e-12);
  EXPECT_NEAR(d422[0].diameter * 1e3, 0.02816201, 2e-6 * 0.02816201);
  EXPECT_NEAR(d422[0].percent_finer, 36.589345, 1e-6);
  EXPECT_NEAR(d422[0].corrected_reading, 37.0, 1e-12);
  const auto d7928 = reduce_lab_readings(readings, specimen, parse_lab_method("d7928"));
  EXPECT_NEAR(d7928[0].effective_depth * 1e2, 9.238, 1e-12);
  EXPECT_NEAR(d7928[0].diameter, 2.819257e-5, 2e-6 * 2.819257e-5);
  EXPECT_NEAR(d7928[0].percent_finer, 36.589345, 1e-6);
  EXPECT_EQ(lab_method_name(LabMethod::d7928), "ASTM D7928");
  EXPECT_THROW(parse_lab_method("d421"), std::invalid_argument);
  readings[1].meniscus_correction = 7.0;
  EXPECT_THROW(reduce_lab_readings(readings, specimen, LabMethod::d7928), InvalidLabReading);
}

// Expects reduce_astm_d422 to reject `readings` naming `row` (0-based), `field` and a
// message containing `text`.
void expect_rejected(const std::vector<LabReading>& readings, const LabSpecimen& specimen,
                     std::size_t row, const std::string& field, const std::string& text) {
  try {
    reduce_astm_d422(readings, specimen);
    ADD_FAILURE() << "accepted, expected a rejection of " << field;
  } catch (const InvalidLabReading& e) {
    EXPECT_EQ(e.row(), row);
    EXPECT_EQ(e.field(), field);
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
  }
}

TEST(LabReduction, InvalidReadingsAreRejectedWithTheirRowFieldAndValue) {
  const LabSpecimen ok{2.70, 50e-3};
  auto r = worked_example();
  r[1].time = -60.0;
  expect_rejected(r, ok, 1, "time_s", "row 2, time_s = -60: times must be positive");
  r = worked_example();
  r[2].time = 3600.0;
  expect_rejected(r, ok, 2, "time_s", "row 3, time_s = 3600: times must increase");
  r = worked_example();
  r[0].reading = 61.5;
  expect_rejected(r, ok, 0, "reading_g_per_l", "row 1, reading_g_per_l = 61.5: off the 152H");
  r = worked_example();
  r[2].reading = -6;
  expect_rejected(r, ok, 2, "reading_g_per_l", "reading_g_per_l = -6");
  r = worked_example();
  r[1].temperature = 55;
  expect_rejected(r, ok, 1, "temperature_c", "temperature_c = 55");
  expect_rejected(worked_example(), {2.70, 0.0}, InvalidLabReading::kSpecimen, "dry_mass_kg",
                  "specimen, dry_mass_kg = 0: the dry mass must be positive");
  expect_rejected(worked_example(), {0.9, 50e-3}, InvalidLabReading::kSpecimen, "specific_gravity",
                  "specific_gravity = 0.9");
  // The D7928 form checks the same.
  r = worked_example();
  r[0].time = 0;
  EXPECT_THROW(reduce_astm_d7928(r, ok), InvalidLabReading);
}

}  // namespace
}  // namespace sedem
