// Laboratory files in the forms labs keep: ';' with decimal commas, tabs, the columns under
// the lab's names and units; errors that say what was found and what was expected; a sieve
// analysis merged with the hydrometer's reduction into the whole curve, against hand
// computation.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "core/lab/hydrometer_reduction.h"
#include "core/lab/lab_csv.h"
#include "core/lab/sieve_analysis.h"
#include "core/lab/whole_curve.h"
#include "tests/lab/worked_example.h"

namespace sedem {
namespace {

using test::expect_worked_example;
const auto& kDiameter = test::kWorkedDiameter;
const auto& kPercent = test::kWorkedPercent;

std::string message_of(const std::string& text) {
  std::istringstream in(text);
  try {
    read_lab_readings_csv(in);
  } catch (const LabCsvError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(LabFormats, SemicolonsAndDecimalCommasInTheLabsWords) {
  // As a spreadsheet in a comma locale saves "CSV": ';' between cells, ',' in numbers.
  std::istringstream in(
      "\xEF\xBB\xBFtime (min);R (g/L);T (\xC2\xB0"
      "C);C (g/L)\r\n"
      "2,0;42,0;22,0;5\r\n"
      "60;20;22;5,0\r\n"
      "1440;10;22;5\r\n");
  const auto r = read_lab_readings_csv(in);
  EXPECT_EQ(r[2].line, 4u);
  // Each value as the worked example's, whichever way its decimals were written.
  expect_worked_example(r);
}

TEST(LabFormats, TabsSecondsHoursFahrenheitAndBrackets) {
  // Tab-separated, the time in s, the temperature in F, the names in brackets and after a
  // comma: 71.6 F is 22 C.
  std::istringstream tsv(
      "elapsed time, s\tR [g/L]\tTemperature [\xC2\xB0"
      "F]\tcomposite correction (g/L)\tnote\n"
      "120\t42\t71.6\t5\tfirst\n3600\t20\t71.6\t5\t\n86400\t10\t71.6\t5\tnext day\n");
  const auto r = read_lab_readings_csv(tsv);
  EXPECT_NEAR(r.at(0).temperature, 22.0, 1e-12);
  expect_worked_example(r);  // the times in s to min: the diameters by hand
  // Hours, and the internal names with their units as words (time_h is no internal column).
  std::istringstream hours(
      "Time [h],Reading (g/l),temperature_c,Cc\n"
      "0.0333333333333333,42,22,5\n1,20,22,5\n24,10,22,5\n");
  const auto h = read_lab_readings_csv(hours);
  EXPECT_NEAR(h[0].time, 120.0, 1e-9);
  EXPECT_DOUBLE_EQ(h[2].time, 86400.0);
}

TEST(LabFormats, CommaFilesRefuseADecimalComma) {
  // With ',' between cells "42,5" can only come quoted; it is refused rather than guessed.
  EXPECT_EQ(message_of("time_min,reading_g_per_l,temperature_c\n2,\"42,5\",22\n"),
            "line 2, column reading_g_per_l: '42,5' is not a number");
}

TEST(LabFormats, WrongColumnNamesSayWhatWasFoundAndExpected) {
  // A German header: nothing is the reading time.
  const std::string zeit = message_of(
      "Zeit (min);R (g/L);T (\xC2\xB0"
      "C)\n2;42;22\n");
  EXPECT_NE(zeit.find("line 1, column time_min: missing from the header"), std::string::npos)
      << zeit;
  EXPECT_NE(zeit.find("found 'Zeit (min)', 'R (g/L)', 'T (\xC2\xB0"
                      "C)'"),
            std::string::npos)
      << zeit;
  EXPECT_NE(zeit.find("expected the reading time, as time_min or e.g. time (min)"),
            std::string::npos)
      << zeit;
  // The right name in a unit that is not the time's.
  const std::string days = message_of("time (days),R (g/L),T (C)\n2,42,22\n");
  EXPECT_NE(days.find("'time (days)': 'days' is not a unit of the reading time (min, mins"),
            std::string::npos)
      << days;
  // A time without a unit: minutes or seconds?
  const std::string bare = message_of("time,R,T (C)\n2,42,22\n");
  EXPECT_NE(bare.find("'time' gives no unit for the reading time"), std::string::npos) << bare;
  // Two columns for one quantity.
  const std::string two = message_of("time (min),time (s),R (g/L),T (C)\n2,120,42,22\n");
  EXPECT_EQ(two, "line 1, column time_min: two columns for it: 'time (min)' and 'time (s)'");
  // A bad cell is named by the column as the file names it.
  EXPECT_EQ(message_of("time (min);R (g/L);T (C)\n2;42;22\n5;3O;22\n"),
            "line 3, column 'R (g/L)': '3O' is not a number");
  // The range checks stay: the time in seconds converted first, then checked.
  EXPECT_NE(message_of("time (s);R (g/L);T (C)\n-60;42;22\n")
                .find("line 2, column time_min: -1 "
                      "is out of range"),
            std::string::npos);
}

LabTable table_of(const std::string& text) {
  std::istringstream in(text);
  return read_lab_text(in);
}

// A sieve analysis by hand (ASTM D6913), 200 g in all:
//   opening 9.5 mm: 0 g retained, cumulative 0, passing 100 %
//           4.75:  12 g, 12,  94 %;   2.0: 18 g, 30, 85 %;   0.425: 30 g, 60, 70 %
//           0.075: 40 g, 100, 50 %;   pan 100 g (the sieves and the pan: 200 g, the total)
// The hydrometer's specimen passed the 2 mm sieve (85 % of the sample): its percent finer of
// that fraction times 0.85 is of the whole sample: 73.178690 -> 62.201887,
// 29.667037 -> 25.216981, 9.889012 -> 8.405660.
const char* kSieves =
    "Sieve;Opening (mm);Mass retained (g)\n"
    "3/8 in;9,5;0\n#4;4,75;12,0\n#40;0,425;30\n#10;2;18\n#200;0,075;40\n"
    "Pan;;100\nTotal;;200,0\n";

TEST(LabFormats, SieveAnalysisByHand) {
  const auto analysis = read_sieve_analysis(table_of(kSieves));
  ASSERT_EQ(analysis.sieves.size(), 5u);
  ASSERT_TRUE(analysis.pan_g && analysis.total_g);
  EXPECT_DOUBLE_EQ(*analysis.pan_g, 100.0);
  EXPECT_DOUBLE_EQ(*analysis.total_g, 200.0);
  const auto points = sieve_percent_passing(analysis);
  const double opening[] = {9.5, 4.75, 2.0, 0.425, 0.075};
  const double passing[] = {100, 94, 85, 70, 50};
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_DOUBLE_EQ(points[i].opening_mm, opening[i]) << i;  // sorted coarsest first
    EXPECT_NEAR(points[i].percent_passing, passing[i], 1e-12) << i;
  }
  EXPECT_NEAR(sieve_mass_difference_percent(analysis, std::nullopt), 0.0, 1e-12);
  // Without the total row the total is the sieves' and the pan's sum; a flag overrides both.
  const auto no_total = read_sieve_analysis(table_of(
      "opening [\xC2\xB5m],retained (g)\n9500,0\n4750,12\n2000,18\n425,30\n75,40\npan,100\n"));
  EXPECT_NEAR(sieve_percent_passing(no_total)[2].percent_passing, 85.0, 1e-12);
  EXPECT_NEAR(sieve_percent_passing(no_total, 400.0)[2].percent_passing, 92.5, 1e-12);
  EXPECT_NEAR(sieve_mass_difference_percent(no_total, 400.0), -50.0, 1e-12);
}

TEST(LabFormats, SieveAnalysisErrors) {
  auto message = [](const std::string& text) {
    try {
      sieve_percent_passing(read_sieve_analysis(table_of(text)));
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message("size,retained (g)\n2,10\npan,5\n")
                .find("'size' gives no unit for the sieve "
                      "opening"),
            std::string::npos);
  EXPECT_EQ(message("opening (mm),retained (g)\n2,10\n2,5\npan,1\n"),
            "line 3, column opening_mm: 2 mm twice (line 2)");
  EXPECT_EQ(message("opening (mm),retained (g)\n2,-1\npan,1\n"),
            "line 2, column mass_retained_g: -1 g is out of range; allowed 0 to 1e+06");
  EXPECT_NE(message("opening (mm),retained (g)\n2,10\n")
                .find("neither a total dry mass nor the "
                      "pan's mass"),
            std::string::npos);
  EXPECT_NE(
      message("opening (mm),retained (g)\n2,10\n1,10\ntotal,15\n").find("more than the total"),
      std::string::npos);
}

TEST(LabFormats, SieveAndHydrometerMergeIntoTheWholeCurve) {
  const auto sieves = sieve_percent_passing(read_sieve_analysis(table_of(kSieves)));
  std::istringstream in("time (min);R (g/L);T (C);C (g/L)\n2;42;22;5\n60;20;22;5\n1440;10;22;5\n");
  const auto points =
      reduce_lab_readings(read_lab_readings_csv(in), {2.70, 50e-3}, LabMethod::d7928);
  std::vector<SedimentationPoint> sedimentation;
  for (const auto& p : points) sedimentation.push_back({p.diameter, p.percent_finer, p.time});
  const auto curve = whole_curve(sieves, 2.0, "hydrometer", sedimentation);
  ASSERT_EQ(curve.size(), 8u);
  // Coarsest first: the five sieves, then the hydrometer's three readings.
  const double whole[] = {100, 94, 85, 70, 50, 62.201887, 25.216981, 8.405660};
  for (std::size_t i = 0; i < 8; ++i) {
    EXPECT_EQ(curve[i].source, i < 5 ? "sieve" : "hydrometer") << i;
    EXPECT_NEAR(curve[i].percent_finer, whole[i], 1e-6) << i;
    if (i >= 5) {
      EXPECT_NEAR(curve[i].diameter, kDiameter[i - 5], 2e-6 * kDiameter[i - 5]) << i;
      EXPECT_NEAR(curve[i].fraction_percent_finer, kPercent[i - 5], 1e-6) << i;
    }
  }
  std::ostringstream csv;
  write_whole_curve_csv(csv, curve);
  const std::string text = csv.str();
  EXPECT_EQ(text.substr(0, text.find('\n')),
            "source,diameter_m,diameter_mm,diameter_um,percent_finer,time_s,time_min,"
            "percent_finer_of_fraction,mass_retained_g");
  EXPECT_NE(text.find("\nsieve,0.002,2,2000,85,,,,18\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\nhydrometer,"), std::string::npos);
  // These made-up readings say 62.2 % finer at 28.4 µm where the sieves let 50 % pass 75 µm:
  // no curve does that, and the merge says so.
  EXPECT_EQ(whole_curve_conflict(curve),
            "hydrometer: 62.2 % finer at 28.4 um, above the 50 % passing the 0.075 mm "
            "sieve: a curve cannot rise toward finer sizes (check the separating sieve, the dry "
            "masses and the sieves)");
  // Separated on the No. 200 (50 % passing) they fit: 36.6 % finer at 28.4 µm.
  EXPECT_EQ(whole_curve_conflict(whole_curve(sieves, 0.075, "hydrometer", sedimentation)), "");
  // A separating sieve the analysis lacks is named, with the openings there are.
  try {
    whole_curve(sieves, 0.85, "hydrometer", sedimentation);
    ADD_FAILURE() << "accepted a separating sieve of 0.85 mm";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("openings are 9.5, 4.75, 2, 0.425, 0.075 mm"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace sedem
