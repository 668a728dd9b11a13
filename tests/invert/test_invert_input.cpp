// Bad input to the inversion: each gets an error naming the column (or option), the value
// and what is allowed, and the command exits 2, as `sedem reduce` does. And the command on
// the clay loam record of docs/invert.md.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/invert/invert_input.h"
#include "core/lab/lab_csv.h"
#include "tests/app/cli_runner.h"

namespace sedem::invert {
namespace {

namespace fs = std::filesystem;

std::vector<Measurement> pipette_readings() {
  // Dry masses (g) of 35 mL at 0.3 H from the paper's cylinder with 60 g: 1.451 g is 100 %.
  return {{60, 1.40}, {240, 1.10}, {900, 0.80}, {3600, 0.40}};
}

std::string message_of(const std::vector<Measurement>& data, Test test,
                       const InversionOptions& o = {}) {
  try {
    validate_measurements(TestSetup{}, test, data, o);
  } catch (const InvalidInversionInput& e) {
    return e.what();
  }
  return "";
}

TEST(InvertInput, AcceptsPlausibleReadings) {
  EXPECT_EQ(message_of(pipette_readings(), invert::Test::pipette), "");
}

TEST(InvertInput, TimesNotIncreasing) {
  auto data = pipette_readings();
  data[2].time = 200;
  const auto m = message_of(data, invert::Test::pipette);
  EXPECT_NE(m.find("row 3, time_min = 3.33333: times must increase (previous row: 4.000 min)"),
            std::string::npos)
      << m;
}

TEST(InvertInput, ReadingOffTheScale) {
  auto data = pipette_readings();
  data[1].value = 2.5;  // more than the whole sample in 35 mL
  const auto m = message_of(data, invert::Test::pipette);
  EXPECT_NE(m.find("row 2, dry_mass_g = 2.5: outside"), std::string::npos) << m;
  EXPECT_NE(m.find("-10 % to 110 % finer"), std::string::npos) << m;
  data = {{60, 11.70}, {240, 11.75}, {900, 12.5}};  // heavier than in clear water (11.819 g)
  EXPECT_NE(message_of(data, invert::Test::buoyancy).find("row 3, apparent_mass_g = 12.5"),
            std::string::npos);
}

TEST(InvertInput, TooFewReadingsOrTooFineAGrid) {
  auto data = pipette_readings();
  data.resize(2);
  EXPECT_NE(message_of(data, invert::Test::pipette)
                .find("readings = 2: the inversion needs 3 readings or more"),
            std::string::npos);
  InversionOptions o;
  o.refine = 9;
  EXPECT_NE(message_of(pipette_readings(), invert::Test::pipette, o)
                .find("refine = 9: allowed 0 to 6 nodes between two readings' diameters"),
            std::string::npos);
}

// The sphere's and the pipette's readings in the lab's words and units, ';' and decimal commas:
// seconds to s as they are, mg to g.
TEST(InvertInput, ReadsTheLabsNamesAndUnits) {
  struct Case {
    const char* csv;
    invert::Test test;
    double first_time_s, first_value_g;
  };
  for (const Case& c :
       {Case{"elapsed time, s;Apparent mass (mg)\n30;1250,5\n120;1248\n", invert::Test::buoyancy,
             30.0, 1.2505},
        Case{"Time [h]\tDry mass [g]\n0.5\t1.4\n2\t1.1\n", invert::Test::pipette, 1800.0, 1.4}}) {
    std::istringstream in(c.csv);
    const auto m = read_measurements_csv(in, c.test);
    EXPECT_EQ(m.size(), 2u) << c.csv;
    EXPECT_DOUBLE_EQ(m.at(0).time, c.first_time_s) << c.csv;
    EXPECT_DOUBLE_EQ(m.at(0).value, c.first_value_g) << c.csv;
  }
}

TEST(InvertInput, ReadsTheSphereAndPipetteColumns) {
  std::istringstream csv("dry_mass_g,time_min\n1.4,1\n1.1,4\n");
  const auto m = read_measurements_csv(csv, invert::Test::pipette);
  ASSERT_EQ(m.size(), 2u);
  EXPECT_DOUBLE_EQ(m[1].time, 240.0);
  EXPECT_DOUBLE_EQ(m[1].value, 1.1);
  std::istringstream bad("time_min,dry_mass_g\n1,abc\n");
  EXPECT_THROW(read_measurements_csv(bad, invert::Test::pipette), LabCsvError);
  std::istringstream missing("time_min,mass\n1,2\n");
  try {
    read_measurements_csv(missing, invert::Test::pipette);
    FAIL();
  } catch (const LabCsvError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("line 1, column dry_mass_g: missing from the header", 0),
              0u)
        << e.what();
    // "mass" alone is not the pipette's dry mass (a wet mass?): what was expected follows.
    EXPECT_NE(std::string(e.what()).find("expected the pipette sample's dry mass, as dry_mass_g "
                                         "or e.g. dry mass (g)"),
              std::string::npos)
        << e.what();
  }
}

TEST(InvertInput, StandardReductionIsZeroAndHundredAtTheEnds) {
  const TestSetup setup;
  const ForwardModel model(setup, invert::Test::buoyancy, log_grid(1e-6, 1e-4, 2), {});
  const auto p = standard_reduction(setup, invert::Test::buoyancy,
                                    {{60, model.empty_reading()}, {120, model.full_reading()}});
  EXPECT_NEAR(p[0].percent_finer, 0.0, 1e-9);
  EXPECT_NEAR(p[1].percent_finer, 100.0, 1e-6);
}

// The command, as a user runs it.
const fs::path kOut = fs::path(SEDEM_TEST_OUTPUT) / "invert";

fs::path write(const std::string& name, const std::string& text) {
  fs::create_directories(kOut);
  std::ofstream(kOut / name) << text;
  return kOut / name;
}

const char* kClayLoam =
    "time_min,reading_g_per_l,temperature_c,composite_correction_g_per_l\n"
    "0.66,39,23,2\n2,33,23,2\n5,29,23,2\n15,23,23,2\n30,22,23,2\n60,20,23,2\n180,18,23,2\n";

TEST(InvertCommand, ClayLoamRecordWritesCurveBandAndFigure) {
  const auto file = write("clay_loam.csv", kClayLoam);
  const auto dir = kOut / "clay_loam";
  const auto r = test::run_sedem("invert " + file.string() +
                                 " --test hydrometer --mass-g 50 --gs 2.65 --replicas 50 --out " +
                                 dir.string() + " -q");
  ASSERT_EQ(r.status, 0) << r.output;
  for (const char* f :
       {"inverted_curve.csv", "readings_fit.csv", "invert.json", "invert.png", "invert.csv"})
    EXPECT_TRUE(fs::exists(dir / f)) << f;
  std::ifstream fit(dir / "readings_fit.csv");
  std::string header;
  std::getline(fit, header);
  EXPECT_EQ(header,
            "time_s,measured_g_per_l,fitted_g_per_l,pinned_diameter_m,inverted_percent_finer,"
            "standard_diameter_m,standard_percent_finer,time_min,pinned_diameter_um,"
            "standard_diameter_um");
  // The summary, read back: the discrepancy principle met, the band's prior spread never
  // below the chosen lambda's, the resolved diameters those of the first and last readings.
  const auto summary = nlohmann::json::parse(std::ifstream(dir / "invert.json"));
  EXPECT_GT(summary.at("lambda").get<double>(), 0.0);
  EXPECT_LE(summary.at("chi2").get<double>(), summary.at("chi2_target").get<double>() * 1.0001);
  EXPECT_GE(summary.at("band_prior_scale").get<double>(), 1.0);
  EXPECT_EQ(summary.at("band_replicas").get<int>(), 50);
  const auto resolved = summary.at("resolved_diameter_m");
  // The bulb's depth from R (not R - C = R - 2) in the blank's liquid: 2 % finer than the
  // 3.80 and 55.1 um of a depth from R - C in water at 23 C.
  EXPECT_NEAR(resolved.at(0).get<double>(), 3.74e-6, 0.01e-6);
  EXPECT_NEAR(resolved.at(1).get<double>(), 53.9e-6, 0.1e-6);
  // What the readings allow holds the inverted curve at every node, and is widest inside the
  // resolved range where it says so.
  std::ifstream curve(dir / "inverted_curve.csv");
  std::getline(curve, header);
  EXPECT_EQ(header,
            "diameter_m,percent_finer,percent_finer_low,percent_finer_high,readings_allow_low,"
            "readings_allow_high,diameter_um,readings_tell");
  int nodes = 0;
  for (std::string line; std::getline(curve, line); ++nodes) {
    std::vector<double> v;
    std::stringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) v.push_back(std::stod(cell));
    ASSERT_EQ(v.size(), 8u) << line;
    EXPECT_NEAR(v[6], v[0] * 1e6, 1e-9 * v[6]) << line;
    EXPECT_LE(v[4], v[1] + 1e-6) << line;
    EXPECT_GE(v[5], v[1] - 1e-6) << line;
    // Where the bounds hold the curve within 10 pp the readings tell it; where they cannot
    // tell it (a knee between readings, tests/invert/test_open_rule.cpp), the band is what
    // they allow.
    if (v[5] - v[4] <= 10) {
      EXPECT_EQ(v[7], 1) << line;
    }
    if (v[7] == 0) {
      EXPECT_TRUE(v[2] <= v[4] + 1e-6 && v[3] >= v[5] - 1e-6) << line;
    }
  }
  EXPECT_GT(nodes, 7);
  const auto allow = summary.at("readings_allow");
  const double widest_at = allow.at("at_diameter_m").get<double>();
  EXPECT_GT(allow.at("widest_pp").get<double>(), 0.0);
  EXPECT_GE(widest_at, resolved.at(0).get<double>());
  EXPECT_LE(widest_at, resolved.at(1).get<double>());
  EXPECT_EQ(allow.at("tolerance").size(), 7u);
}

// A simulated run inverted from its folder: the readings rounded as a laboratory records
// them, reduced again as the run reduced them (within what rounding to 1 mg moves), and both
// curves against the run's true curve.
TEST(InvertCommand, RunFolderAgainstItsTrueCurve) {
  const auto run = kOut / "run_sample5";
  fs::remove_all(run);
  const auto r = test::run_sedem(
      "run " + std::string(SEDEM_SOURCE_DIR) + "/scenes/sample5.toml --set " +
      "sample.simulated_count=3000 --set output.frames=false --set output.particles=false " +
      "--out " + run.string() + " -q");
  ASSERT_EQ(r.status, 0) << r.output;
  const auto dir = kOut / "run_sample5_inverted";
  const auto inv = test::run_sedem("invert --run " + run.string() +
                                   " --test buoyancy --replicas 20 -q --out " + dir.string());
  ASSERT_EQ(inv.status, 0) << inv.output;

  std::ifstream ran(run / "readings_buoyancy.csv");
  const auto run_rows = read_numeric_csv(ran, {"time_s", "percent_finer"});
  std::ifstream fit(dir / "readings_fit.csv");
  const auto rows = read_numeric_csv(
      fit, {"time_s", "measured_g", "standard_percent_finer", "true_percent_finer"});
  ASSERT_EQ(rows.size(), run_rows.size());
  double standard_error = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_DOUBLE_EQ(rows[i][0], run_rows[i][0]);
    EXPECT_NEAR(rows[i][1], std::round(rows[i][1] * 1e3) / 1e3, 1e-9);  // to the mg
    EXPECT_NEAR(rows[i][2], run_rows[i][1], 0.3);  // 0.5 mg is about 0.25 % of the range
    standard_error = std::max(standard_error, std::abs(rows[i][2] - rows[i][3]));
  }
  const auto summary = nlohmann::json::parse(std::ifstream(dir / "invert.json"));
  EXPECT_NEAR(summary.at("true_curve_error_pp").at("standard").get<double>(), standard_error,
              1e-6);  // the CSV's 9 digits
  EXPECT_LT(summary.at("true_curve_error_pp").at("inverted").get<double>(), 100.0);
  std::ifstream figure(dir / "invert.csv");  // the figure draws the true curve too
  std::string columns;
  std::getline(figure, columns);
  EXPECT_NE(columns.find("true:diameter_um,true:percent_finer,inverted:"), std::string::npos)
      << columns;
  EXPECT_EQ(columns.rfind("readings allow:diameter_um,readings allow:percent_finer_low,", 0), 0u)
      << columns;

  EXPECT_EQ(test::run_sedem("invert --test buoyancy --out " + dir.string()).status, 1);
  EXPECT_EQ(
      test::run_sedem("invert --run " + run.string() + " --scene " + std::string(SEDEM_SOURCE_DIR) +
                      "/scenes/sample5.toml --out " + dir.string())
          .status,
      1);  // the run's scene is its own
  const auto missing = test::run_sedem("invert --run " + (kOut / "no_run").string() +
                                       " --test pipette --out " + dir.string());
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.output.find("cannot open the readings file"), std::string::npos)
      << missing.output;
}

TEST(InvertCommand, BadReadingsExitTwoNamingTheValue) {
  auto r = test::run_sedem(
      "invert " +
      write("off_scale.csv", "time_min,reading_g_per_l,temperature_c\n2,30,20\n5,65,20\n15,20,20\n")
          .string() +
      " --test hydrometer --out " + (kOut / "x").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find("row 2, reading_g_per_l = 65: off the 152H scale (-5 to 60 g/L)"),
            std::string::npos)
      << r.output;
  r = test::run_sedem(
      "invert " +
      write("two.csv", "time_min,reading_g_per_l,temperature_c\n2,30,20\n5,25,20\n").string() +
      " --test hydrometer --out " + (kOut / "x").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find("readings = 2: the inversion needs 3 readings or more"),
            std::string::npos)
      << r.output;
  r = test::run_sedem(
      "invert " +
      write("back.csv", "# pipette, 25 mL\ntime_min,dry_mass_g\n1,1.4\n\n4,1.1\n2,0.9\n").string() +
      " --test pipette --out " + (kOut / "x").string());
  EXPECT_EQ(r.status, 2);
  // The message names the line of the file too (a note, the header and a blank line come
  // before the third reading).
  EXPECT_NE(r.output.find("line 6: row 3, time_min = 2: times must increase"), std::string::npos)
      << r.output;
}

}  // namespace
}  // namespace sedem::invert
