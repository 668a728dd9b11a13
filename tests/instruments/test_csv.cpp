// The CSV forms of the readings, the granulometry and the laboratory data, read back.
#include <gtest/gtest.h>

#include <limits>

#include <sstream>
#include <string>

#include "core/instruments/readings_csv.h"
#include "core/lab/lab_csv.h"

namespace sedem {
namespace {

TEST(Csv, ReadingsWithTheInstrumentsOwnColumns) {
  PipetteReading p;
  p.time = 120;
  p.depth = 0.1371;
  p.radius = 0.0149;
  p.concentration = 20.5;
  p.dry_mass = 7.175e-4;
  p.diameter = 1.234567890123e-5;
  p.percent_finer = 49.5;
  std::ostringstream out;
  write_readings_csv(out, to_readings(std::vector<PipetteReading>{p}));
  std::istringstream in(out.str());
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  EXPECT_EQ(header,
            "time_s,diameter_m,percent_finer,depth_m,radius_m,concentration_kg_m3,dry_mass_kg");
  std::istringstream cells(row);
  std::string cell;
  std::getline(cells, cell, ',');
  EXPECT_DOUBLE_EQ(std::stod(cell), 120.0);
  std::getline(cells, cell, ',');
  EXPECT_DOUBLE_EQ(std::stod(cell), 1.234567890123e-5);  // shortest exact round trip
  std::getline(cells, cell, ',');
  EXPECT_DOUBLE_EQ(std::stod(cell), 49.5);
}

TEST(Csv, GranulometryHoldsTrueDemReferenceErrorAndBias) {
  Granulometry g;
  g.true_curve = {{10e-6, 40}, {20e-6, 100}};
  TestComparison t;
  t.test = "buoyancy";
  t.dem.test = t.reference.test = "buoyancy";
  t.dem.rows = {{60, 15e-6, 41, {}}};
  t.reference.rows = {{60, 15e-6, 40, {}}};
  t.error = 1;
  t.bias = 0;
  g.tests = {t};
  std::ostringstream out;
  write_granulometry_csv(out, g);
  EXPECT_EQ(out.str(),
            "test,source,time_s,diameter_m,percent_finer\n"
            "true,true,,1e-05,40\n"
            "true,true,,2e-05,100\n"
            "buoyancy,dem,60,1.5e-05,41\n"
            "buoyancy,reference,60,1.5e-05,40\n"
            "buoyancy,error_pp,,,1\n"
            "buoyancy,bias_pp,,,0\n");
}

TEST(Csv, GranulometryLeavesTheFiguresOfATestWithoutReadingsEmpty) {
  Granulometry g;
  TestComparison t;
  t.test = t.dem.test = t.reference.test = "hydrometer";
  t.error = t.bias = std::numeric_limits<double>::quiet_NaN();  // what compare() gives it
  g.tests = {t};
  std::ostringstream out;
  write_granulometry_csv(out, g);
  EXPECT_EQ(out.str(),
            "test,source,time_s,diameter_m,percent_finer\n"
            "hydrometer,error_pp,,,\n"
            "hydrometer,bias_pp,,,\n");
}

TEST(Csv, LabReadingsInTheLaboratorysUnits) {
  std::istringstream in(
      "temperature_c, time_min, reading_g_per_l, composite_correction_g_per_l\n"
      "22, 2, 42, 5\n"
      "\n"
      "22, 60, 20, 5\n");
  const auto r = read_lab_readings_csv(in);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_DOUBLE_EQ(r[0].time, 120.0);
  EXPECT_DOUBLE_EQ(r[1].time, 3600.0);
  EXPECT_DOUBLE_EQ(r[0].reading, 42.0);
  EXPECT_DOUBLE_EQ(r[0].temperature, 22.0);
  EXPECT_DOUBLE_EQ(r[1].composite_correction, 5.0);
  // And reduced: the worked example's first two points (test_lab_reduction.cpp).
  const auto points = reduce_astm_d422(r, {2.70, 50e-3});
  EXPECT_NEAR(points[1].percent_finer, 29.667037, 1e-6);
  std::ostringstream out;
  write_lab_points_csv(out, points);
  EXPECT_EQ(out.str().substr(0, out.str().find('\n')),
            "time_s,diameter_m,percent_finer,corrected_reading_g_per_l,effective_depth_m,"
            "viscosity_pa_s,time_min,diameter_mm,diameter_um");
}

TEST(Csv, LabReadingsErrorsNameLineAndColumn) {
  std::istringstream missing("time_min,reading_g_per_l\n2,40\n");
  try {
    read_lab_readings_csv(missing);
    ADD_FAILURE() << "accepted a header without temperature_c";
  } catch (const LabCsvError& e) {
    // What was found and what the laboratory may write for it follow.
    EXPECT_EQ(std::string(e.what()).rfind("line 1, column temperature_c: missing from the header "
                                          "(found 'time_min', 'reading_g_per_l'); expected the "
                                          "temperature, as temperature_c or e.g. T (",
                                          0),
              0u)
        << e.what();
  }
  std::istringstream bad("time_min,reading_g_per_l,temperature_c\n2,40,20\n5,3O,20\n");
  try {
    read_lab_readings_csv(bad);
    ADD_FAILURE() << "accepted '3O'";
  } catch (const LabCsvError& e) {
    EXPECT_EQ(e.line(), 3u);
    EXPECT_EQ(std::string(e.what()), "line 3, column reading_g_per_l: '3O' is not a number");
  }
}

}  // namespace
}  // namespace sedem
