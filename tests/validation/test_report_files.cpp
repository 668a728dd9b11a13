// The report's files: run folders read back, variant folders, markdown sections replaced.
#include <gtest/gtest.h>

#include <fstream>

#include "bench/validation/markdown.h"
#include "bench/validation/report.h"
#include "bench/validation/run_folder.h"

namespace sedem::validation {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

// A run folder as `sedem run` writes it, small enough to check by hand.
fs::path fake_run(const std::string& name) {
  const fs::path dir = fs::path(SEDEM_TEST_OUTPUT) / "validation" / name;
  fs::remove_all(dir);
  write(dir / "run.json", R"({"status": "complete", "particle_count": 200, "steps": 1000,
    "simulated_time_s": 120, "wall_time_s": 4, "particle_steps_per_s": 50000,
    "scene": {"name": ")" + name +
                              R"(", "sample.weighting": "equal_mass",
              "instruments.pipette.depth_fraction": 0.3, "fluid.density": 1000}})");
  write(dir / "granulometry.csv",
        "test,source,time_s,diameter_m,percent_finer\n"
        "true,true,,1e-05,40\n"
        "true,true,,5e-05,100\n"
        "pipette,dem,30,6e-05,97\n"
        "pipette,dem,60,3e-05,45\n"
        "pipette,reference,30,6e-05,100\n"
        "pipette,reference,60,3e-05,40\n"
        "pipette,error_pp,,,5\n"
        "pipette,bias_pp,,,0\n");
  write(dir / "readings_pipette.csv",
        "time_s,diameter_m,percent_finer,depth_m,radius_m\n30,6e-05,97,0.13,0.01\n"
        "60,3e-05,45,0.15,0.01\n");
  write(dir / "figures" / "fig12_largest_diameter.csv",
        "t = 60 s/" + name + ":depth_m,t = 60 s/" + name +
            ":diameter_um,t = 60 s/Eq. 16:depth_m,t = 60 s/Eq. 16:diameter_um\n"
            "0.1,40,0.1,41\n0.2,55,0.2,58\n,,0.3,71\n");
  return dir;
}

TEST(ReportFiles, ReadsARunFolder) {
  const RunFolder run = read_run_folder(fake_run("sample9"));
  EXPECT_EQ(run.name, "sample9");
  EXPECT_EQ(run.status, "complete");
  EXPECT_EQ(run.particle_count, 200u);
  EXPECT_DOUBLE_EQ(run.wall_time_s, 4);
  EXPECT_DOUBLE_EQ(run.number("instruments.pipette.depth_fraction"), 0.3);
  EXPECT_EQ(run.text("sample.weighting"), "equal_mass");
  ASSERT_EQ(run.true_curve.size(), 2u);
  ASSERT_EQ(run.classes.size(), 2u);
  EXPECT_NEAR(run.classes[1].mass_fraction, 0.6, 1e-12);
  const RunTest* p = run.test("pipette");
  ASSERT_NE(p, nullptr);
  ASSERT_EQ(p->dem.rows.size(), 2u);
  ASSERT_EQ(p->reference.rows.size(), 2u);
  EXPECT_DOUBLE_EQ(p->dem.rows[1].percent_finer, 45);
  EXPECT_DOUBLE_EQ(p->reference.rows[0].percent_finer, 100);
  EXPECT_DOUBLE_EQ(p->error_pp, 5);
  EXPECT_NEAR(p->depth_m, 0.14, 1e-12);  // the mean of its readings' depth_m
  EXPECT_EQ(run.test("hydrometer"), nullptr);
  ASSERT_EQ(run.profiles.size(), 1u);  // the Eq. 16 curve is not the sample's
  EXPECT_DOUBLE_EQ(run.profiles[0].time_s, 60);
  ASSERT_EQ(run.profiles[0].depth_m.size(), 2u);  // the empty cells are left out
  EXPECT_NEAR(run.profiles[0].largest_diameter_m[1], 55e-6, 1e-15);
}

TEST(ReportFiles, AMissingFileIsNamed) {
  const fs::path dir = fake_run("sample8");
  fs::remove(dir / "granulometry.csv");
  try {
    read_run_folder(dir);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("granulometry.csv"), std::string::npos) << e.what();
  }
}

TEST(ReportFiles, AVariantChangesTheSceneAndLinksTheParticles) {
  const fs::path dir = fake_run("sample7");
  write(dir / "particles.pvd", "<VTKFile/>\n");
  write(dir / "particles" / "particles_000000.vtp", "x");
  const fs::path variant = dir.parent_path() / "sample7_deep";
  fs::remove_all(variant);
  make_variant(dir, variant, {"instruments.pipette.depth_fraction=0.7", "name=\"deep\""});
  std::ifstream in(variant / "run.json");
  const auto j = nlohmann::json::parse(in);
  EXPECT_DOUBLE_EQ(j["scene"]["instruments.pipette.depth_fraction"].get<double>(), 0.7);
  EXPECT_EQ(j["scene"]["name"], "deep");
  EXPECT_EQ(j["particle_count"], 200);
  EXPECT_TRUE(fs::is_symlink(variant / "particles.pvd"));
  EXPECT_TRUE(fs::exists(variant / "particles" / "particles_000000.vtp"));
  EXPECT_THROW(make_variant(dir, variant, {"no.such.key=1"}), std::invalid_argument);
}

TEST(ReportFiles, ReplacesOnlyTheNamedGeneratedSection) {
  const std::string doc =
      "intro\n<!-- generated:begin a -->\nold a\n<!-- generated:end -->\nmiddle\n"
      "<!-- generated:begin b -->\nold b\n<!-- generated:end -->\nend\n";
  const std::string out = replace_generated(doc, "b", "new b");
  EXPECT_EQ(out,
            "intro\n<!-- generated:begin a -->\nold a\n<!-- generated:end -->\nmiddle\n"
            "<!-- generated:begin b -->\nnew b\n<!-- generated:end -->\nend\n");
  EXPECT_EQ(replace_generated(out, "b", "new b"), out);  // running twice changes nothing
  EXPECT_THROW(replace_generated(doc, "c", "x"), std::invalid_argument);
}

TEST(ReportFiles, MarkdownTablesAndNumbers) {
  EXPECT_EQ(markdown_table({"a", "b"}, {{"1", "2"}, {"3"}}),
            "| a | b |\n|---|---|\n| 1 | 2 |\n| 3 |  |\n");
  EXPECT_EQ(fixed(-0.001, 2), "0.00");
  EXPECT_EQ(fixed(2.345, 1), "2.3");
  EXPECT_EQ(significant(1234567, 3), "1.23e+06");
}

TEST(ReportFiles, TheReportHasEverySectionOfTheDocumentAndOneVerdictPerConclusion) {
  ReportInputs in;
  in.runs = {read_run_folder(fake_run("sample2"))};
  in.early_s = 30;
  const Report report = build_report(in);
  ASSERT_EQ(report.checks.size(), 6u);
  std::ifstream doc(fs::path(SEDEM_SOURCE_DIR) / "docs" / "validation.md");
  std::stringstream text;
  text << doc.rdbuf();
  std::string markdown = text.str();
  for (const auto& s : report.sections) markdown = replace_generated(markdown, s.name, s.markdown);
  // The short-run label, the paper's 60 h beside sample 2, and each verdict line.
  EXPECT_NE(markdown.find("Short pipeline run"), std::string::npos);
  EXPECT_NE(markdown.find("| sample2 | 200 | 0.03 | 4.0 | 120.0 | 60 h (19440 s) | 162x |"),
            std::string::npos)
      << markdown;
  for (const auto& c : report.checks) {
    const std::string line = verdict_line(c);
    EXPECT_EQ(line.rfind(c.id + ": ", 0), 0u) << line;
  }
  // The pipette reads 97 at 60 um (true 100) and 45 at 30 um (true 40): at large sizes the
  // mean is (-3 + 5) / 2 = +1 pp; one row positive -> contradicts.
  EXPECT_EQ(report.checks[3].id, "large_sizes");
  EXPECT_EQ(report.checks[3].verdict, Verdict::contradicts);
}

}  // namespace
}  // namespace sedem::validation
