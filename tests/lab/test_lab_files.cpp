// Laboratory files as `sedem reduce` and `sedem invert` take them: .xlsx workbooks (made here
// by tests/lab/make_workbook.py with Debian's python3-openpyxl, and by hand with shared
// strings), ';' with decimal commas and tab-separated text, each reduced to the same curve;
// a sieve analysis and the hydrometer's readings merged into the whole curve, with its lab
// report; wrong column names refused with the file, what was found and what was expected.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/xlsx_reader.h"
#include "core/lab/hydrometer_reduction.h"
#include "core/lab/lab_csv.h"
#include "tests/app/cli_runner.h"
#include "tests/lab/worked_example.h"

namespace sedem {
namespace {

namespace fs = std::filesystem;

// Each test's own folder: ctest runs them in parallel, and a workbook one test was rewriting
// while another unpacked it failed as "cannot unpack xl/worksheets/sheet2.xml".
fs::path out_dir() {
  const fs::path dir = fs::path(SEDEM_TEST_OUTPUT) / "lab_files" /
                       ::testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::create_directories(dir);
  return dir;
}

fs::path write(const std::string& name, const std::string& text) {
  const fs::path file = out_dir() / name;
  std::ofstream(file, std::ios::binary) << text;
  return file;
}

// A workbook made by make_workbook.py: "lab.xlsx" (openpyxl) or "shared.xlsx" (by hand).
fs::path workbook(const std::string& name) {
  const fs::path file = out_dir() / name;
  const std::string command = std::string(SEDEM_PYTHON) + " " + SEDEM_SOURCE_DIR +
                              "/tests/lab/make_workbook.py " + file.string();
  EXPECT_EQ(std::system(command.c_str()), 0) << command << " (python3-openpyxl installed?)";
  return file;
}

std::string read(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

using test::expect_worked_example;
const auto& kDiameter = test::kWorkedDiameter;
const auto& kPercent = test::kWorkedPercent;

TEST(LabFiles, XlsxFromOpenpyxl) {
  const fs::path book = workbook("lab.xlsx");
  EXPECT_EQ(app::xlsx_sheet_names(book), (std::vector<std::string>{"Notes", "Readings", "Sieves"}));
  const LabTable table = app::read_xlsx_table(book, "Readings");
  EXPECT_EQ(table.header_line, 1u);
  EXPECT_EQ(table.lines, (std::vector<std::size_t>{2, 4, 5}));  // the empty row 3 skipped
  const auto readings = read_lab_readings(table);
  EXPECT_EQ(readings[1].temperature, 22.0);  // the text cell "22,0"
  expect_worked_example(readings);
  // The first sheet by default: the notes, where no column is the time; said by its row.
  try {
    read_lab_readings(app::read_xlsx_table(book));
    ADD_FAILURE() << "read the notes as readings";
  } catch (const LabCsvError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("sheet 'Notes', row 1, column time_min: missing from the "
                                          "header (found 'Sample B-12, 50 g oven-dry, Gs 2.70')",
                                          0),
              0u)
        << e.what();
  }
  try {
    app::read_xlsx_table(book, "Hydrometer");
    ADD_FAILURE() << "found a sheet that is not there";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "the workbook has no sheet 'Hydrometer'; it has 'Notes', 'Readings', 'Sieves'");
  }
}

TEST(LabFiles, XlsxWithSharedStrings) {
  const LabTable table = app::read_xlsx_table(workbook("shared.xlsx"));
  // The comment row 1 and the empty row 2 above the header; the rich string's runs joined,
  // its phonetic guide left out.
  EXPECT_EQ(table.header_line, 3u);
  EXPECT_EQ(table.header[0], "elapsed time, s");
  const auto readings = read_lab_readings(table);
  EXPECT_DOUBLE_EQ(readings[2].time, 86400.0);
  EXPECT_EQ(readings[2].line, 6u);
  expect_worked_example(readings);
  // A cell reference past any column: that cell is left out (no overflow, no huge row), and
  // the row then lacks its time.
  try {
    read_lab_readings(app::read_xlsx_table(workbook("damaged.xlsx")));
    ADD_FAILURE() << "read a row without its time";
  } catch (const LabCsvError& e) {
    EXPECT_STREQ(e.what(),
                 "sheet 'Hydrometer', row 5, column 'elapsed time, s': '' is not a number");
  }
  // Not a workbook at all.
  const fs::path fake = write("fake.xlsx", "time_min,reading_g_per_l\n");
  EXPECT_THROW(app::read_xlsx_table(fake), std::invalid_argument);
}

// A value a reduction refuses, read from a workbook, is named by its sheet and the row a
// spreadsheet program shows (the empty row 3 counted), never by a text file's "line"; the same
// value in a CSV still names the reading and the file's line.
TEST(LabFiles, XlsxValueErrorsNameTheSheetAndRow) {
  const fs::path book = workbook("bad.xlsx");
  const auto r = test::run_sedem("reduce " + book.string() + " --sheet Readings");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find(book.string() +
                          ": sheet 'Readings', row 4, temperature_c = 99: outside 0-40 C"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("line"), std::string::npos) << r.output;
  const auto s =
      test::run_sedem("reduce " + workbook("lab.xlsx").string() + " --sheet Readings --sieve " +
                      book.string() + " --sieve-sheet Sieves");
  EXPECT_EQ(s.status, 2);
  EXPECT_NE(s.output.find("more than the total dry mass 40 g (sheet 'Sieves', row 4)"),
            std::string::npos)
      << s.output;
  EXPECT_EQ(s.output.find("line"), std::string::npos) << s.output;
  const fs::path csv =
      write("hot.csv", "time_min,reading_g_per_l,temperature_c\n2,42,22\n\n60,20,99\n");
  const auto c = test::run_sedem("reduce " + csv.string());
  EXPECT_EQ(c.status, 2);
  EXPECT_NE(c.output.find(": row 2, temperature_c = 99: outside 0-40 C, where the water density "
                          "formula holds (line 4 of the file)"),
            std::string::npos)
      << c.output;
}

// The same readings as ';' with decimal commas, as tabs and as a workbook: one curve.
TEST(LabFiles, EveryFormReducesToTheSameCurve) {
  const fs::path semicolons = write("readings_semicolon.csv",
                                    "time (min);R (g/L);T (\xC2\xB0"
                                    "C);C (g/L)\n2,0;42;22,0;5\n60;20;22;5\n1440;10;22;5\n");
  const fs::path tabs = write("readings.tsv",
                              "elapsed time, s\tR [g/L]\tTemperature [C]\tCc\n120\t42\t22\t5\n"
                              "3600\t20\t22\t5\n86400\t10\t22\t5\n");
  const fs::path book = workbook("lab.xlsx");
  std::vector<std::string> outputs;
  for (const std::string& input :
       {semicolons.string(), tabs.string(), book.string() + " --sheet Readings"}) {
    const auto r = test::run_sedem("reduce " + input + " --gs 2.70");
    ASSERT_EQ(r.status, 0) << input << ": " << r.output;
    outputs.push_back(r.output);
  }
  EXPECT_EQ(outputs[0], outputs[1]);
  EXPECT_EQ(outputs[0], outputs[2]);
  std::istringstream csv(outputs[0]);
  const auto rows =
      read_numeric_csv(csv, {"diameter_m", "percent_finer", "time_min", "diameter_um"});
  ASSERT_EQ(rows.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(rows[i][0], kDiameter[i], 2e-6 * kDiameter[i]);
    EXPECT_NEAR(rows[i][1], kPercent[i], 1e-6);
    EXPECT_NEAR(rows[i][3], kDiameter[i] * 1e6, 2e-6 * kDiameter[i] * 1e6);  // µm beside m
  }
  EXPECT_DOUBLE_EQ(rows[1][2], 60.0);
}

TEST(LabFiles, WrongColumnNamesNameTheFileWhatWasFoundAndExpected) {
  const fs::path bad = write("zeit.csv",
                             "Zeit (min);Ablesung (g/L);T (\xC2\xB0"
                             "C)\n2;42;22\n");
  const auto r = test::run_sedem("reduce " + bad.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find(bad.string() + ": line 1, column time_min: missing from the header "
                                         "(found 'Zeit (min)', 'Ablesung (g/L)', 'T (\xC2\xB0"
                                         "C)'); expected the reading time, as time_min or e.g. "
                                         "time (min), time (s)"),
            std::string::npos)
      << r.output;
  const auto s = test::run_sedem("reduce " + workbook("lab.xlsx").string() + " --sheet Sieves");
  EXPECT_EQ(s.status, 2);
  EXPECT_NE(s.output.find("row 1, column time_min: missing from the header (found 'Sieve', "
                          "'Opening (mm)', 'Mass retained (g)')"),
            std::string::npos)
      << s.output;
  const auto t = test::run_sedem("reduce " + bad.string() + " --sheet Readings");
  EXPECT_EQ(t.status, 2);
  EXPECT_NE(t.output.find("--sheet names a sheet of an .xlsx workbook"), std::string::npos)
      << t.output;
}

// A sieve analysis (the workbook's Sieves sheet: 200 g, 85 % passing the 2 mm sieve) and the
// hydrometer's readings of the fraction that passed it (the Readings sheet), reduced to the
// whole curve: by hand, the sieves pass 100, 94, 85, 70 and 50 %; the hydrometer's percent
// finer of the fraction times 0.85: 62.201887, 25.216981 and 8.405660 %.
TEST(LabFiles, SieveAndHydrometerToTheWholeCurveWithItsReport) {
  const fs::path book = workbook("lab.xlsx");
  const fs::path out = out_dir() / "whole.csv", report = out_dir() / "whole_report.html";
  fs::remove(out);
  const auto r = test::run_sedem(
      "reduce " + book.string() + " --sheet Readings --gs 2.70 --sieve " + book.string() +
      " --sieve-sheet Sieves --out " + out.string() + " --report " + report.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("sedem: warning: hydrometer: 62.2 % finer at 28.4 um, above"),
            std::string::npos)
      << r.output;
  std::ifstream in(out);
  std::vector<std::size_t> lines;
  const auto rows = read_numeric_csv(in, {"diameter_mm", "percent_finer"}, {}, &lines);
  const double diameter_mm[] = {
      9.5, 4.75, 2, 0.425, 0.075, kDiameter[0] * 1e3, kDiameter[1] * 1e3, kDiameter[2] * 1e3};
  const double whole[] = {100, 94, 85, 70, 50, 62.201887, 25.216981, 8.405660};
  ASSERT_EQ(rows.size(), 8u);
  for (std::size_t i = 0; i < 8; ++i) {
    EXPECT_NEAR(rows[i][0], diameter_mm[i], 2e-6 * diameter_mm[i]) << i;
    EXPECT_NEAR(rows[i][1], whole[i], 1e-6) << i;
  }
  const std::string text = read(out);
  EXPECT_EQ(text.substr(0, text.find('\n')),
            "source,diameter_m,diameter_mm,diameter_um,percent_finer,time_s,time_min,"
            "percent_finer_of_fraction,mass_retained_g");
  EXPECT_NE(text.find("\nsieve,0.002,2,2000,85,,,,18\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\nhydrometer,"), std::string::npos);
  // The report: the standards, the inputs, the figure beside it, the tables.
  const std::string page = read(report);
  for (const std::string& part :
       {std::string("ASTM D7928 with ASTM D6913 (sieve analysis)"),
        std::string("<img src=\"whole_report_curve.png\""),
        std::string("Sieve analysis (ASTM D6913)"), std::string("Whole grading curve"),
        std::string("<td class=\"num\">85</td>"), std::string("<td class=\"num\">62.2</td>"),
        std::string("passing the separating sieve (%)"), std::string("href=\"whole.csv\""),
        // The made-up sieves and readings do not fit (test_lab_formats.cpp): a warning.
        std::string("a curve cannot rise toward finer sizes")})
    EXPECT_NE(page.find(part), std::string::npos) << part;
  EXPECT_TRUE(fs::exists(out_dir() / "whole_report_curve.png"));
  EXPECT_TRUE(fs::exists(out_dir() / "whole_report_curve.csv"));
  // A separating sieve the analysis lacks: exit 2, the sieve file named.
  const auto no =
      test::run_sedem("reduce " + book.string() + " --sheet Readings --gs 2.70 --sieve " +
                      book.string() + " --sieve-sheet Sieves --separating-sieve-mm 0.85");
  EXPECT_EQ(no.status, 2);
  EXPECT_NE(no.output.find("the separating sieve (0.85 mm"), std::string::npos) << no.output;
  // The sieve's options without a sieve analysis would be ignored: a bad command line.
  const auto alone =
      test::run_sedem("reduce " + book.string() + " --sheet Readings --separating-sieve-mm 0.075");
  EXPECT_EQ(alone.status, 1);
  EXPECT_NE(alone.output.find("--separating-sieve-mm requires --sieve"), std::string::npos)
      << alone.output;
}

// `sedem invert` takes the same files: the whole curve holds the sieves, the standard
// reduction and the inverted curve, each marked, and the report shows them.
TEST(LabFiles, InvertTakesAWorkbookAndTheSieves) {
  const fs::path book = workbook("lab.xlsx");
  const fs::path dir = out_dir() / "invert";
  const auto r = test::run_sedem(
      "invert " + book.string() + " --sheet Readings --test hydrometer --gs 2.70 --sieve " +
      book.string() + " --sieve-sheet Sieves --replicas 0 -q --out " + dir.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string text = read(dir / "whole_curve.csv");
  for (const char* source : {"\nsieve,", "\nhydrometer,", "\ninverted,"})
    EXPECT_NE(text.find(source), std::string::npos) << source;
  // The standard's points scaled by the 85 % passing 2 mm, as reduce scales them.
  std::ifstream in(dir / "readings_fit.csv");
  const auto fit = read_numeric_csv(in, {"standard_percent_finer"});
  EXPECT_NE(text.find(",62.20188"), std::string::npos) << text;
  EXPECT_NEAR(fit[0][0], kPercent[0], 1e-6);
  const std::string page = read(dir / "report.html");
  EXPECT_NE(page.find("ASTM D7928 beside the inversion, with ASTM D6913"), std::string::npos);
  EXPECT_NE(page.find("grading_curve.png"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "grading_curve.png"));
}

}  // namespace
}  // namespace sedem
