#include <gtest/gtest.h>

#include <cstdlib>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include <vtkImageData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>
#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "render/offscreen_view.h"
#include "render/series_reader.h"

namespace sedem {
namespace {

namespace fs = std::filesystem;
const fs::path kOut = fs::path(SEDEM_TEST_OUTPUT) / "cli";
const std::string kDemo = std::string(SEDEM_SOURCE_DIR) + "/scenes/demo.toml";

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

TEST(Cli, DemoRunWritesAReadableSeriesAndANonBlankFrame) {
  const fs::path out = kOut / "demo";
  fs::remove_all(out);
  auto r = test::run_sedem("run " + kDemo + " --out " + out.string() + " --quiet");
  ASSERT_EQ(r.status, 0) << r.output;

  auto run = read_json(out / "run.json");
  EXPECT_EQ(run["status"], "complete");
  EXPECT_GT(run["particle_count"].get<int>(), 1000);
  EXPECT_GT(run["particle_steps_per_s"].get<double>(), 0);
  EXPECT_EQ(run["scene"]["name"], "demo");
  for (const char* test : {"hydrometer", "buoyancy", "pipette"}) {
    EXPECT_TRUE(fs::exists(out / (std::string("readings_") + test + ".csv"))) << test;
    EXPECT_GE(run["results"][test]["error_pp"].get<double>(), 0) << test;
    EXPECT_GE(run["results"][test]["bias_pp"].get<double>(), 0) << test;
  }
  for (const char* file :
       {"granulometry.csv", "fields.pvd", "hydrometer.pvd", "figures/fig11_column.png",
        "figures/fig18_granulometry.png", "figures/fig18_granulometry.csv"})
    EXPECT_TRUE(fs::exists(out / file)) << file;

  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  reader->SetFileName((out / "particles/particles_000001.vtp").c_str());
  reader->Update();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), run["particle_count"].get<int>());

  // A frame is not blank: the column's grey bands cover a good share of it.
  auto image = render::read_png(out / "frames/column_000000.png");
  int dims[3];
  image->GetDimensions(dims);
  long inked = 0;
  for (int y = 0; y < dims[1]; ++y)
    for (int x = 0; x < dims[0]; ++x) {
      auto* px = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
      if (px[0] < 240 || px[1] < 240 || px[2] < 240) ++inked;
    }
  EXPECT_GT(inked, long(dims[0]) * dims[1] / 10);
}

TEST(Cli, HelpForEveryCommand) {
  auto top = test::run_sedem("--help");
  EXPECT_EQ(top.status, 0);
  EXPECT_NE(top.output.find("run"), std::string::npos);
  auto run = test::run_sedem("run --help");
  EXPECT_EQ(run.status, 0);
  EXPECT_NE(run.output.find("--set"), std::string::npos) << run.output;
}

TEST(Cli, MissingSceneFails) {
  auto r = test::run_sedem("run /no/such/scene.toml --out " + (kOut / "x").string());
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("/no/such/scene.toml"), std::string::npos) << r.output;
}

TEST(Cli, InvalidValueNamesKeyValueAndRange) {
  auto r = test::run_sedem("run " + kDemo + " --out " + (kOut / "bad").string() +
                           " --set fluid.viscosity=-2");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find("fluid.viscosity = -2 is out of range"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(kOut / "bad" / "run.json"));  // nothing ran
}

TEST(Cli, UnknownKeySuggestsTheNearest) {
  auto r = test::run_sedem("run " + kDemo + " --out " + (kOut / "bad").string() +
                           " --set sample.simulated_cuont=5");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find("did you mean 'sample.simulated_count'"), std::string::npos) << r.output;
}

TEST(Cli, UnwritableOutputFolderFails) {
  auto r = test::run_sedem("run " + kDemo + " --out /proc/sedem-cannot-write-here");
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.output.find("cannot write to the output folder"), std::string::npos) << r.output;
}

// A long run of the demo into kOut/name with `sets`, sent `signals` (shell commands on $pid)
// `seconds` after it catches SIGTERM (the first instruction of its set-up): its folder, and the
// run's exit status and output.
test::CommandResult stopped_run(const std::string& name, const std::string& sets, double seconds,
                                const std::string& signals, fs::path& out) {
  out = kOut / name;
  fs::remove_all(out);
  return test::run_sedem("run " + kDemo + " --out " + out.string() +
                         " --set run.end_time_s=1e6 --set output.frames=false" + sets +
                         " --quiet 2>&1 & pid=$!; " + test::until_sigterm_caught() + "sleep " +
                         std::to_string(seconds) + "; " + signals + " wait $pid");
}

TEST(Cli, InterruptedRunSaysSoAndKeepsWhatItWrote) {
  fs::path out;
  auto r = stopped_run("interrupted", "", 1.5, "kill -TERM $pid;", out);
  EXPECT_EQ(r.status, 130) << r.output;
  auto run = read_json(out / "run.json");
  EXPECT_EQ(run["status"], "interrupted");
  EXPECT_GT(run["simulated_time_s"].get<double>(), 0);
  EXPECT_TRUE(fs::exists(out / "particles.pvd"));
  EXPECT_FALSE(fs::exists(out / "particles.pvd.tmp"));
}

TEST(Cli, AnIncompleteRunIsRedrawnOrInvertedOnlyWhenAskedAndSaidPartial) {
  fs::path out;
  ASSERT_EQ(stopped_run("partial", "", 1.5, "kill -TERM $pid;", out).status, 130);
  for (const std::string& command :
       {"render " + out.string(), "invert --run " + out.string() + " --out " +
                                      (out / "inverted").string() + " --test hydrometer"}) {
    auto refused = test::run_sedem(command + " --quiet");
    EXPECT_EQ(refused.status, 2) << command << "\n" << refused.output;
    EXPECT_NE(refused.output.find("interrupted, not complete"), std::string::npos)
        << refused.output;
    EXPECT_NE(refused.output.find("--partial"), std::string::npos) << refused.output;
    auto taken = test::run_sedem(command + " --partial --quiet");
    EXPECT_EQ(taken.status, 0) << command << "\n" << taken.output;
    EXPECT_NE(taken.output.find("warning: partial"), std::string::npos) << taken.output;
  }
}

TEST(Cli, TwoSigtermsStillStopCleanly) {
  // coreutils timeout, and others, repeat the request: the second one must not kill.
  fs::path out;
  auto r = stopped_run("two_sigterms", "", 1.5, "kill -TERM $pid; kill -TERM $pid;", out);
  EXPECT_EQ(r.status, 130) << r.output;
  EXPECT_EQ(read_json(out / "run.json")["status"], "interrupted");
  EXPECT_TRUE(fs::exists(out / "checkpoint.bin"));
}

TEST(Cli, ASigtermDuringTheSetUpStopsCleanlyToo) {
  // Sent as soon as the run catches SIGTERM, while the scene is read and the 200 000 particles
  // placed (or, on a fast machine, just after): either way a record that says interrupted and a
  // checkpoint to go on from, never exit 143.
  fs::path out;
  auto r = stopped_run("sigterm_setup",
                       " --set sample.simulated_count=200000 --set output.particles=false", 0,
                       "kill -TERM $pid;", out);
  EXPECT_EQ(r.status, 130) << r.output;
  EXPECT_EQ(read_json(out / "run.json")["status"], "interrupted");
  EXPECT_TRUE(fs::exists(out / "checkpoint.bin"));
}

}  // namespace
}  // namespace sedem

namespace sedem {
namespace {

TEST(Cli, BatchSweepRunsEachValueIntoItsOwnFolder) {
  const fs::path out = kOut / "batch";
  fs::remove_all(out);
  auto r = test::run_sedem("batch " + kDemo + " --out " + out.string() +
                           " --sweep sample.simulated_count=500,800 --set run.end_time_s=10"
                           " --set output.frames=false --quiet");
  ASSERT_EQ(r.status, 0) << r.output;
  auto a = read_json(out / "demo__sample.simulated_count=500" / "run.json");
  auto b = read_json(out / "demo__sample.simulated_count=800" / "run.json");
  EXPECT_EQ(a["scene"]["sample.simulated_count"], 500);
  EXPECT_EQ(b["scene"]["sample.simulated_count"], 800);
  EXPECT_EQ(a["status"], "complete");
}

TEST(Cli, ABatchStoppedPassesTheStopOnToItsRuns) {
  // SIGTERM to the batch alone (not its process group): its two runs stop cleanly with their
  // checkpoints, and the batch ends now, not when they would have finished.
  const fs::path out = kOut / "batch_stopped";
  fs::remove_all(out);
  auto r = test::run_sedem("batch " + kDemo + " --out " + out.string() +
                           " --jobs 2 --sweep sample.seed=1,2 --set run.end_time_s=1e6"
                           " --set output.frames=false --quiet 2>&1 & pid=$!; sleep 2.5; "
                           "kill -TERM $pid; wait $pid");
  EXPECT_EQ(r.status, 130) << r.output;
  for (const char* seed : {"1", "2"}) {
    const fs::path run = out / (std::string("demo__sample.seed=") + seed);
    EXPECT_EQ(read_json(run / "run.json")["status"], "interrupted") << run;
    EXPECT_TRUE(fs::exists(run / "checkpoint.bin")) << run;
  }
  EXPECT_TRUE(fs::exists(out / "summary.csv"));
}

TEST(Cli, BatchRejectsAMalformedSweep) {
  auto r = test::run_sedem("batch " + kDemo + " --sweep sample.simulated_count");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("expected key=v1,v2"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace sedem

namespace sedem {
namespace {

std::string text_of(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(Cli, RenderTakesTheSameReadingsAgainFromTheSavedFiles) {
  const fs::path out = kOut / "render";
  fs::remove_all(out);
  ASSERT_EQ(test::run_sedem("run " + kDemo + " --out " + out.string() +
                            " --set output.frames=false --quiet")
                .status,
            0);
  const std::string readings = text_of(out / "readings_pipette.csv");
  const std::string granulometry = text_of(out / "granulometry.csv");
  fs::remove(out / "readings_pipette.csv");
  fs::remove(out / "granulometry.csv");
  fs::remove_all(out / "figures");

  auto r = test::run_sedem("render " + out.string() + " --quiet");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(text_of(out / "readings_pipette.csv"), readings);
  EXPECT_EQ(text_of(out / "granulometry.csv"), granulometry);
  EXPECT_TRUE(fs::exists(out / "figures/fig17_pipette.png"));
}

TEST(Cli, RenderOfRunsOfOneSceneNamesThemByTheKeyThatDiffers) {
  const fs::path base = kOut / "render_sweep";
  fs::remove_all(base);
  std::string render = "render";
  for (const char* count : {"300", "600"}) {
    const fs::path out = base / count;
    ASSERT_EQ(test::run_sedem("run " + kDemo + " --out " + out.string() +
                              " --set sample.simulated_count=" + count +
                              " --set run.end_time_s=120 --set output.frames=false --quiet")
                  .status,
              0);
    render.append(" ").append(out.string());
  }
  render.append(" --out ").append((base / "figures").string()).append(" --quiet");
  auto r = test::run_sedem(render);
  ASSERT_EQ(r.status, 0) << r.output;
  // Panels (and their CSV columns) named by the swept key, not "demo" twice.
  const std::string csv = text_of(base / "figures/fig18_granulometry.csv");
  EXPECT_NE(csv.find("sample.simulated_count=300/true:diameter_um"), std::string::npos) << csv;
  EXPECT_NE(csv.find("sample.simulated_count=600/true:diameter_um"), std::string::npos);
  EXPECT_EQ(csv.find("demo/"), std::string::npos);
}

TEST(Cli, RenderRefusesAFolderThatIsNoRun) {
  auto r = test::run_sedem("render " + std::string(SEDEM_SOURCE_DIR) + "/scenes");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find("no run.json"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace sedem

namespace sedem {
namespace {

TEST(Cli, ReduceFollowsAstmD422ByHand) {
  const fs::path dir = kOut / "reduce";
  fs::create_directories(dir);
  std::ofstream(dir / "lab.csv") << "time_min,reading_g_per_l,temperature_c\n2,40,20\n";
  auto r = test::run_sedem("reduce " + (dir / "lab.csv").string() +
                           " --method d422 --mass-g 50 --gs 2.65");
  ASSERT_EQ(r.status, 0) << r.output;
  // By hand, ASTM D422 for a 152H at 20 C, Gs = 2.65: L = 16.29 - 0.164 x 40 = 9.73 cm,
  // K = sqrt(30 x 0.010017 / (980 x (2.65 - 0.99821))) = 0.013604 (the standard's table:
  // 0.01365), D = K sqrt(9.73 / 2) = 0.030005 mm; a = 1 for Gs = 2.65, P = 40 / 50 x 100 = 80 %.
  std::istringstream lines(r.output);
  std::string header, row;
  std::getline(lines, header);
  std::getline(lines, row);
  double time = 0, diameter = 0, percent = 0;
  char comma;
  std::istringstream(row) >> time >> comma >> diameter >> comma >> percent;
  EXPECT_DOUBLE_EQ(time, 120.0);
  EXPECT_NEAR(diameter * 1e3, 0.030005, 0.0002);
  EXPECT_NEAR(percent, 80.0, 1e-9);
}

TEST(Cli, ReduceRejectsANegativeTimeNamingTheRow) {
  const fs::path dir = kOut / "reduce";
  fs::create_directories(dir);
  std::ofstream(dir / "bad.csv") << "time_min,reading_g_per_l,temperature_c\n2,40,20\n-5,30,20\n";
  auto r = test::run_sedem("reduce " + (dir / "bad.csv").string());
  EXPECT_EQ(r.status, 2);
  // The file's own line (the header is line 1), the column, the value and the range.
  EXPECT_NE(r.output.find("line 3, column time_min: -5 is out of range"), std::string::npos)
      << r.output;
}

TEST(Cli, HelpOfEachCommandNamesItsOptions) {
  for (const char* cmd : {"run", "batch", "render", "reduce", "bench"}) {
    auto r = test::run_sedem(std::string(cmd) + " --help");
    EXPECT_EQ(r.status, 0) << cmd;
    EXPECT_NE(r.output.find("Usage"), std::string::npos) << cmd << r.output;
  }
}

}  // namespace
}  // namespace sedem

namespace sedem {
namespace {

// Runs `scene` whole into `name`_whole and, interrupted by SIGINT after 2 s and resumed, into
// `name`_parts; expects the same readings, to the bit, in both. Returns the parts' folder.
// `when_stopped` looks at the interrupted run's folder before it is resumed.
fs::path interrupt_and_resume(const std::string& name, const std::string& scene,
                              const std::function<void(const fs::path&)>& when_stopped = {}) {
  const fs::path whole = kOut / (name + "_whole"), parts = kOut / (name + "_parts");
  fs::remove_all(whole);
  fs::remove_all(parts);
  EXPECT_EQ(test::run_sedem("run " + scene + " --out " + whole.string()).status, 0);

  auto stopped = test::run_sedem("run " + scene + " --out " + parts.string() +
                                 " 2>&1 & pid=$!; sleep 2; kill -INT $pid; wait $pid");
  EXPECT_EQ(stopped.status, 130) << "the run ended before it was interrupted: " << stopped.output;
  EXPECT_NE(stopped.output.find("sedem run --resume " + parts.string()), std::string::npos)
      << stopped.output;
  EXPECT_EQ(read_json(parts / "run.json")["status"], "interrupted");
  EXPECT_TRUE(fs::exists(parts / "checkpoint.bin"));
  if (when_stopped) when_stopped(parts);

  auto resumed = test::run_sedem("run --resume " + parts.string() + " --quiet");
  EXPECT_EQ(resumed.status, 0) << resumed.output;
  EXPECT_EQ(read_json(parts / "run.json")["status"], "complete");
  EXPECT_FALSE(fs::exists(parts / "checkpoint.bin"));
  for (const char* file : {"readings_hydrometer.csv", "readings_buoyancy.csv",
                           "readings_pipette.csv", "granulometry.csv"})
    EXPECT_EQ(text_of(parts / file), text_of(whole / file)) << file;
  return parts;
}

// The demo on short steps, so that a run is still going when interrupted, with a hydrometer
// reading before the interruption (1.2 s), which the resumed run replays.
const std::string kShortSteps = kDemo +
                                " --set run.end_time_s=40 --set sample.simulated_count=1500"
                                " --set output.frames=false --quiet"
                                " --set integrator.crossing_fraction=0.1 --set "
                                "integrator.local_steps=true --set integrator.max_coast_s=0.002"
                                " --set instruments.hydrometer.times_min=[0.02,0.5]";

TEST(Cli, InterruptedAndResumedRunEqualsAnUninterruptedOne) {
  const fs::path parts = interrupt_and_resume("resume", kShortSteps);
  const fs::path whole = kOut / "resume_whole";
  // The same series and final particle state, to the bit.
  for (const char* file : {"particles.pvd", "fields.pvd"})
    EXPECT_EQ(text_of(parts / file), text_of(whole / file)) << file;
  const auto last = render::read_pvd(whole / "particles.pvd").back().second;
  EXPECT_EQ(text_of(parts / last), text_of(whole / last)) << last;

  auto again = test::run_sedem("run --resume " + parts.string());
  EXPECT_EQ(again.status, 0);
  EXPECT_NE(again.output.find("nothing to resume"), std::string::npos) << again.output;
}

// Local steps give the same bits on any thread count (tested in the engine's tests), so a run
// stopped on one core goes on on two, as a job requeued on another machine would: it was
// refused as "another run". (The demo's 1 500 grains step on one thread either way: this checks
// the checkpoint's identity; the engine's tests resume two threads' checkpoints on one.)
TEST(Cli, ARunStoppedOnOneCoreGoesOnOnTwo) {
  const fs::path whole = kOut / "cores_whole", parts = kOut / "cores_parts";
  fs::remove_all(whole);
  fs::remove_all(parts);
  setenv("OMP_NUM_THREADS", "2", 1);
  EXPECT_EQ(test::run_sedem("run " + kShortSteps + " --out " + whole.string()).status, 0);
  setenv("OMP_NUM_THREADS", "1", 1);
  auto stopped = test::run_sedem("run " + kShortSteps + " --out " + parts.string() +
                                 " 2>&1 & pid=$!; sleep 2; kill -INT $pid; wait $pid");
  setenv("OMP_NUM_THREADS", "2", 1);
  auto resumed = test::run_sedem("run --resume " + parts.string() + " --quiet");
  unsetenv("OMP_NUM_THREADS");
  EXPECT_EQ(stopped.status, 130) << "the run ended before it was interrupted: " << stopped.output;
  EXPECT_EQ(resumed.status, 0) << resumed.output;
  for (const char* file : {"readings_hydrometer.csv", "granulometry.csv", "particles.pvd"})
    EXPECT_EQ(text_of(parts / file), text_of(whole / file)) << file;
}

// Particle files off: the readings so far are kept in the checkpoint, so that the run can
// still be resumed (it could not: "particles.pvd" was missing), and no snapshot is written for
// them (frames off: nothing else needs one; they were written at every reading, a fifth of a
// run's time at a million particles).
TEST(Cli, ARunWithoutParticleFilesResumesToo) {
  auto no_snapshots = [](const fs::path& parts) {
    std::size_t files = 0;
    if (fs::exists(parts / "replay"))
      for (const auto& e : fs::recursive_directory_iterator(parts / "replay"))
        files += e.is_regular_file();
    EXPECT_EQ(files, 0u);
  };
  const fs::path parts = interrupt_and_resume(
      "resume_quiet", kShortSteps + " --set output.particles=false", no_snapshots);
  EXPECT_FALSE(fs::exists(parts / "particles.pvd"));
  EXPECT_FALSE(fs::exists(parts / "replay"));
  for (const auto& f : read_json(parts / "run.json")["files"])
    EXPECT_TRUE(fs::exists(parts / f.get<std::string>())) << f;
}

}  // namespace
}  // namespace sedem

namespace sedem {
namespace {

TEST(Cli, BenchRunsTheAccuracyBenchmarkAndWritesItsCsv) {
  const fs::path out = kOut / "bench";
  fs::remove_all(out);
  auto r = test::run_sedem("bench accuracy -- --scenes " + kDemo +
                           " --vary sample.simulated_count=300 --set run.end_time_s=60 --out " +
                           out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string csv = text_of(out / "bench_accuracy.csv");
  EXPECT_EQ(
      csv.rfind("sample,test,variant,particles,wall_s,particle_steps_per_s,error_pp,bias_pp", 0),
      0u)
      << csv;
  for (const char* test : {"hydrometer", "buoyancy", "pipette"})
    EXPECT_NE(csv.find(std::string("demo,") + test + ",\"sample.simulated_count=300\""),
              std::string::npos)
        << test << "\n"
        << csv;
  EXPECT_TRUE(fs::exists(out / "bench_accuracy_pipette.png"));
}

}  // namespace
}  // namespace sedem

namespace sedem {
namespace {

TEST(Cli, AnEngineBlowUpIsReportedWithParticleAndTime) {
  const fs::path out = kOut / "blowup";
  fs::remove_all(out);
  // An explicit step a thousand times too long: the engine must say so, not write NaNs.
  auto r = test::run_sedem("run " + kDemo + " --out " + out.string() +
                           " --set integrator.method=explicit --set integrator.step_factor=1000"
                           " --set integrator.adaptive=false --set sample.simulated_count=200"
                           " --set output.frames=false --quiet");
  EXPECT_EQ(r.status, 5) << r.output;
  EXPECT_NE(r.output.find("the engine failed: instability: particle"), std::string::npos)
      << r.output;
  auto run = read_json(out / "run.json");
  EXPECT_EQ(run["status"], "failed");
}

TEST(Cli, AFullDiskStopsTheRunWithAClearMessage) {
  const fs::path out = kOut / "full";
  fs::remove_all(out);
  // A 64 KiB file-size limit stands for a full disk: writes fail with an error (EFBIG).
  auto r = test::run_sedem(
      "--version > /dev/null; ( trap '' XFSZ; ulimit -f 64; exec " SEDEM_EXE " run " + kDemo +
      " --out " + out.string() + " --set output.frames=false --quiet )");
  EXPECT_EQ(r.status, 4) << r.output;
  EXPECT_NE(r.output.find("writing the outputs failed: cannot write"), std::string::npos)
      << r.output;
  // The first cause is kept (a later failure is its consequence) and no temporary file stays.
  const auto record = read_json(out / "run.json");
  EXPECT_EQ(record["status"], "failed");
  EXPECT_EQ(record["message"].get<std::string>().rfind("writing the outputs failed", 0), 0u)
      << record["message"];
  for (const auto& e : fs::recursive_directory_iterator(out))
    EXPECT_NE(e.path().extension(), ".tmp") << e.path();
}

}  // namespace
}  // namespace sedem
