// Run folders that never mix, the result on the terminal, batches that compare, a suggestion
// on a mistyped command: `sedem` driven as a user would.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "cli_runner.h"

namespace sedem {
namespace {

namespace fs = std::filesystem;
const fs::path kOut = fs::path(SEDEM_TEST_OUTPUT) / "runs";
const std::string kDemo = std::string(SEDEM_SOURCE_DIR) + "/scenes/demo.toml";
// A short, small demo: a few seconds of simulation, no frames.
const std::string kSmall =
    " --set sample.simulated_count=300 --set output.frames=false --set run.end_time_s=";

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

std::string text_of(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path fresh(const std::string& name) {
  const fs::path dir = kOut / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Every file of the folder but run.json, relative to it.
std::set<std::string> files_in(const fs::path& dir) {
  std::set<std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file() && e.path().filename() != "run.json")
      files.insert(e.path().lexically_relative(dir).generic_string());
  return files;
}

// run.json lists exactly what the folder holds: every file listed exists, and every file in
// the folder is listed.
void expect_one_run(const fs::path& dir) {
  const auto run = read_json(dir / "run.json");
  ASSERT_TRUE(run.contains("files")) << dir;
  std::set<std::string> listed;
  for (const auto& f : run["files"]) listed.insert(f.get<std::string>());
  EXPECT_EQ(listed, files_in(dir)) << dir;
}

TEST(Runs, ARunRefusesAFolderHoldingAnotherRun) {
  const fs::path out = fresh("refuse") / "run";
  ASSERT_EQ(
      test::run_sedem("run " + kDemo + " --out " + out.string() + kSmall + "20 --quiet").status, 0);
  const std::string before = text_of(out / "run.json");
  auto r = test::run_sedem("run " + kDemo + " --out " + out.string() + kSmall + "10 --quiet");
  EXPECT_EQ(r.status, 3) << r.output;
  EXPECT_NE(r.output.find("holds another run"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--overwrite"), std::string::npos) << r.output;
  EXPECT_EQ(text_of(out / "run.json"), before);  // untouched
}

TEST(Runs, OverwriteLeavesNothingOfTheOldRun) {
  const fs::path out = fresh("overwrite") / "run";
  // A 40 s run with frames every 10 s, then a 20 s run over it.
  ASSERT_EQ(test::run_sedem("run " + kDemo + " --out " + out.string() +
                            " --set sample.simulated_count=300 --set run.end_time_s=40"
                            " --set instruments.hydrometer.times_min=[0.25,0.5] --quiet")
                .status,
            0);
  ASSERT_TRUE(fs::exists(out / "frames/column_000004.png"));
  auto r =
      test::run_sedem("run " + kDemo + " --out " + out.string() +
                      " --set sample.simulated_count=300 --set run.end_time_s=20"
                      " --set instruments.hydrometer.times_min=[0.25,0.5] --overwrite --quiet");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_FALSE(fs::exists(out / "frames/column_000003.png"));
  // 0, 10, 15 (a reading) and 20 s now; 30 and 40 s were the old run's.
  EXPECT_TRUE(fs::exists(out / "particles/particles_000003.vtp"));
  EXPECT_FALSE(fs::exists(out / "particles/particles_000004.vtp"));
  // The old run's reading at 30 s is gone with it.
  EXPECT_EQ(text_of(out / "readings_hydrometer.csv").find("\n30,"), std::string::npos);
  EXPECT_EQ(read_json(out / "run.json")["simulated_time_s"], 20.0);
  expect_one_run(out);
}

TEST(Runs, ATestThatReadNothingHasNoNumberAnywhere) {
  // The hydrometer's first reading (30 s) lies past the end (20 s): no error, no bias.
  const fs::path out = fresh("no_readings");
  auto r = test::run_sedem("run " + kDemo + " --out " + out.string() + kSmall + "20");
  ASSERT_EQ(r.status, 0) << r.output;
  const auto hydrometer = read_json(out / "run.json")["results"]["hydrometer"];
  EXPECT_EQ(hydrometer["readings"], 0);
  EXPECT_TRUE(hydrometer["error_pp"].is_null());
  EXPECT_TRUE(hydrometer["bias_pp"].is_null());
  EXPECT_NE(hydrometer.value("note", "").find("no readings"), std::string::npos);
  const std::string csv = text_of(out / "granulometry.csv");
  EXPECT_NE(csv.find("hydrometer,error_pp,,,\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find("hydrometer,bias_pp,,,\n"), std::string::npos) << csv;
  EXPECT_NE(r.output.find("hydrometer              -            -         0"), std::string::npos)
      << r.output;
}

TEST(Runs, OverwriteNeverDeletesFilesNoRunWrites) {
  const fs::path out = fresh("foreign");
  std::ofstream(out / "notes.txt") << "mine\n";
  auto r = test::run_sedem("run " + kDemo + " --out " + out.string() + kSmall +
                           "10 --overwrite --quiet");
  EXPECT_EQ(r.status, 3) << r.output;
  EXPECT_NE(r.output.find("notes.txt"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::exists(out / "notes.txt"));
  EXPECT_FALSE(fs::exists(out / "run.json"));
}

TEST(Runs, TheDefaultOutputFolderIsNamedAfterTheScene) {
  const fs::path dir = fresh("default_out");
  std::ofstream(dir / "other.toml") << "name = \"other\"\n";
  std::ofstream(dir / "escape.toml") << "name = \"../../escaped\"\n";
  const std::string cd = "--version > /dev/null; cd " + dir.string() + " && " SEDEM_EXE " run ";
  ASSERT_EQ(test::run_sedem(cd + kDemo + kSmall + "10 --quiet").status, 0);
  ASSERT_EQ(test::run_sedem(cd + "other.toml" + kSmall + "10 --quiet").status, 0);
  EXPECT_EQ(read_json(dir / "out/demo/run.json")["scene"]["name"], "demo");
  EXPECT_EQ(read_json(dir / "out/other/run.json")["scene"]["name"], "other");
  // A scene's name cannot take its run out of out/.
  auto r = test::run_sedem(cd + "escape.toml" + kSmall + "10 --quiet");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_FALSE(fs::exists(dir / "escaped"));
  EXPECT_FALSE(fs::exists(kOut / "escaped"));
  EXPECT_TRUE(fs::exists(dir / "out/_.._.._escaped/run.json"));
}

TEST(Runs, TwoRunsIntoOneFolderCannotBothProceed) {
  const fs::path out = fresh("lock") / "run";
  // A long run in the background; once it has started, a second one into the same folder.
  const std::string first = "run " + kDemo + " --out " + out.string() + kSmall +
                            "1e6 --quiet > /dev/null 2>&1 & pid=$!; "
                            "for i in $(seq 100); do [ -f " +
                            (out / "run.json").string() + " ] && break; sleep 0.1; done; " +
                            SEDEM_EXE " run " + kDemo + " --out " + out.string() + kSmall +
                            "10 --overwrite --quiet 2>&1; status=$?; kill -TERM $pid; wait $pid; "
                            "exit $status";
  auto r = test::run_sedem(first);
  EXPECT_EQ(r.status, 3) << r.output;
  EXPECT_NE(r.output.find("another sedem run is writing into"), std::string::npos) << r.output;
  // The first run was not disturbed: it stopped on SIGTERM with its folder whole.
  EXPECT_EQ(read_json(out / "run.json")["status"], "interrupted");
  expect_one_run(out);
  // A new run into the interrupted run's folder is pointed to --resume.
  auto again = test::run_sedem("run " + kDemo + " --out " + out.string() + kSmall + "10");
  EXPECT_EQ(again.status, 3);
  EXPECT_NE(again.output.find("sedem run --resume " + out.string()), std::string::npos)
      << again.output;
}

TEST(Runs, AFinishedRunPrintsEachTestsErrorAndBias) {
  const fs::path out = fresh("summary") / "run";
  auto r = test::run_sedem("run " + kDemo + " --out " + out.string() +
                           " --set sample.simulated_count=300 --set output.frames=false");
  ASSERT_EQ(r.status, 0) << r.output;
  const auto results = read_json(out / "run.json")["results"];
  EXPECT_NE(r.output.find("error (pp)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("bias (pp)"), std::string::npos) << r.output;
  char row[128];
  std::snprintf(row, sizeof row, "%-12s %12.2f %12.2f", "hydrometer",
                results["hydrometer"]["error_pp"].get<double>(),
                results["hydrometer"]["bias_pp"].get<double>());
  EXPECT_NE(r.output.find(row), std::string::npos) << row << "\n" << r.output;
  EXPECT_NE(r.output.find("figures:  " + (out / "figures/").string()), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("report:   " + (out / "report.html").string()), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("done in"), std::string::npos) << r.output;
}

TEST(Runs, TheDemoReadsTheHydrometerThreeTimesInSeconds) {
  const fs::path out = fresh("demo") / "run";
  auto r = test::run_sedem("run " + kDemo + " --out " + out.string() + " --quiet");
  ASSERT_EQ(r.status, 0) << r.output;
  const auto run = read_json(out / "run.json");
  EXPECT_GE(run["results"]["hydrometer"]["readings"].get<int>(), 3);
  EXPECT_LT(run["wall_time_s"].get<double>(), 60.0);  // seconds, even on a loaded machine
  expect_one_run(out);
}

TEST(Runs, AMistypedCommandGetsASuggestion) {
  auto r = test::run_sedem("rnu scenes/demo.toml");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("did you mean 'run'?"), std::string::npos) << r.output;
  auto b = test::run_sedem("bacth");
  EXPECT_NE(b.output.find("did you mean 'batch'?"), std::string::npos) << b.output;
}

TEST(Batch, WritesASummaryAndAFigureAndRunsJobsAtOnce) {
  const fs::path out = fresh("batch_summary");
  auto r = test::run_sedem("batch " + kDemo + " --out " + out.string() +
                           " --sweep sample.simulated_count=300,400,600 --jobs 2" + kSmall +
                           "20 --set instruments.hydrometer.times_min=[0.25] --quiet");
  ASSERT_EQ(r.status, 0) << r.output;
  std::istringstream csv(text_of(out / "summary.csv"));
  std::string header, line;
  std::getline(csv, header);
  EXPECT_EQ(header,
            "run,scene,sample.simulated_count,seed,hydrometer_error_pp,hydrometer_bias_pp,"
            "buoyancy_error_pp,buoyancy_bias_pp,pipette_error_pp,pipette_bias_pp,wall_time_s,"
            "particle_count,status");
  int rows = 0;
  for (const char* count : {"300", "400", "600"}) {
    ASSERT_TRUE(std::getline(csv, line));
    ++rows;
    const std::string folder = std::string("demo__sample.simulated_count=") + count;
    // No --seeds: the seed cell is empty.
    EXPECT_EQ(line.rfind(folder + "," + kDemo + "," + count + ",,", 0), 0u) << line;
    EXPECT_EQ(line.substr(line.size() - 9), ",complete") << line;
    const auto run = read_json(out / folder / "run.json");
    std::string count_field = ",";
    count_field += std::to_string(run["particle_count"].get<int>());
    count_field += ',';
    EXPECT_NE(line.find(count_field), std::string::npos) << line;
    // Two at once: each has half of the cores.
    const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
    EXPECT_EQ(run["scene"]["integrator.threads"], std::max(1, cores / 2));
  }
  EXPECT_EQ(rows, 3);
  EXPECT_TRUE(fs::exists(out / "summary_error.png"));
  EXPECT_NE(text_of(out / "summary_error.csv").find("hydrometer"), std::string::npos);
  // The batch's page: each run's report, the summary figure and CSV.
  const std::string index = text_of(out / "index.html");
  for (const char* count : {"300", "400", "600"})
    EXPECT_NE(
        index.find(std::string("href=\"demo__sample.simulated_count=") + count + "/report.html\""),
        std::string::npos)
        << index;
  EXPECT_NE(index.find("<img src=\"summary_error.png\""), std::string::npos) << index;
  EXPECT_NE(index.find("href=\"summary.csv\""), std::string::npos) << index;
  EXPECT_NE(index.find("3 runs over <code>sample.simulated_count</code>, 3 complete."),
            std::string::npos)
      << index;
}

TEST(Batch, ScenesSharingANameGetTheirOwnFolders) {
  const fs::path out = fresh("batch_names");
  fs::create_directories(out / "copy");
  fs::copy_file(kDemo, out / "copy/demo.toml");
  auto r = test::run_sedem("batch " + kDemo + " " + (out / "copy/demo.toml").string() + " --out " +
                           (out / "runs").string() + kSmall + "10 --quiet");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(read_json(out / "runs/demo/run.json")["scene_file"], kDemo);
  EXPECT_EQ(read_json(out / "runs/demo_2/run.json")["scene_file"],
            (out / "copy/demo.toml").string());
}

TEST(Batch, ASweptValueCannotLeaveTheOutputFolder) {
  const fs::path out = fresh("batch_escape");
  auto r = test::run_sedem("batch " + kDemo + " --out " + (out / "runs").string() +
                           " --sweep 'name=\"/../../escaped\",\"_.._.._escaped\"'" + kSmall +
                           "10 --quiet");
  ASSERT_EQ(r.status, 0) << r.output;
  // Two values that give one safe name: two folders still.
  std::vector<fs::path> made;
  for (const auto& e : fs::directory_iterator(out / "runs"))
    if (e.is_directory()) made.push_back(e.path());
  ASSERT_EQ(made.size(), 2u);
  for (const auto& dir : made) EXPECT_TRUE(fs::exists(dir / "run.json")) << dir;
  for (const auto& e : fs::directory_iterator(out)) EXPECT_EQ(e.path().filename(), "runs");
}

}  // namespace
}  // namespace sedem
