// Bad input, faults and kills: each ends in a clear error (exit 2 naming the key or file, 3
// before simulating, ...) or in a correct result, never in a silent wrong one.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "core/instruments/granulometry.h"
#include "core/instruments/readings_csv.h"

namespace sedem {
namespace {

namespace fs = std::filesystem;
const fs::path kOut = fs::path(SEDEM_TEST_OUTPUT) / "faults";
const std::string kScenes = std::string(SEDEM_SOURCE_DIR) + "/scenes/";
const std::string kDemo = kScenes + "demo.toml";
// A short run, no frames: what is checked is the outcome, not the physics.
const std::string kShort = " --set run.end_time_s=2 --set output.frames=false --quiet";

fs::path fresh(const std::string& name) {
  const fs::path dir = kOut / name;
  fs::remove_all(dir);
  fs::create_directories(dir.parent_path());
  return dir;
}

std::string text_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_text(const fs::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary);
  out << text;
}

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

// Exit 2 with every one of `words` in the message.
void expect_refused(const test::CommandResult& r, std::initializer_list<const char*> words) {
  EXPECT_EQ(r.status, 2) << r.output;
  for (const char* w : words)
    EXPECT_NE(r.output.find(w), std::string::npos) << w << "\n" << r.output;
}

// A run of the demo that is killed (SIGKILL) once it has written a checkpoint.
const std::string kSlow =
    " --set run.end_time_s=60 --set output.frames=false --quiet"
    " --set integrator.crossing_fraction=0.1 --set integrator.max_coast_s=0.002 --set "
    "run.checkpoint_interval_s=0.3";

// The demo slowed so that a run lasts long enough to be killed: short coasting windows, short
// steps, every grain on the dynamics to the bottom.
std::string killable_demo(const std::string& end_time_s) {
  return kDemo + " --set run.end_time_s=" + end_time_s +
         " --set output.frames=false --quiet"
         " --set integrator.crossing_fraction=0.1 --set integrator.max_coast_s=0.002"
         " --set sample.simulated_count=600 --set integrator.retire_below_instruments=false";
}

void run_and_kill_after_checkpoint(const fs::path& dir, const std::string& extra = "") {
  auto r = test::run_sedem("run " + kDemo + kSlow + extra + " --out " + dir.string() +
                           " & pid=$!; for i in $(seq 400); do [ -f " + dir.string() +
                           "/checkpoint.json ] && break; sleep 0.05; done; kill -KILL $pid; "
                           "wait $pid");
  ASSERT_EQ(r.status, 137) << "the run ended before it was killed: " << r.output;
  ASSERT_TRUE(fs::exists(dir / "checkpoint.bin"));
}

// 64-bit FNV-1a, as checkpoint.json records checkpoint.bin's bytes.
std::string fnv(const std::string& bytes) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  char out[17];
  std::snprintf(out, sizeof out, "%016llx", static_cast<unsigned long long>(h));
  return out;
}

// Writes a damaged checkpoint.bin with a record that vouches for it: only the engine's own
// checks of the values stand between it and the run.
void forge_checkpoint(const fs::path& dir, const std::string& bytes) {
  write_text(dir / "checkpoint.bin", bytes);
  auto record = read_json(dir / "checkpoint.json");
  record["current"]["content"] = fnv(bytes);
  record.erase("previous");
  write_text(dir / "checkpoint.json", record.dump());
}

// 1. No NaN or inf reaches a CSV or run.json; an error that cannot be computed is no error.
TEST(Faults, NoGravityIsRefusedAndNanIsNeverCountedAsPerfect) {
  const fs::path out = fresh("gravity");
  expect_refused(
      test::run_sedem("run " + kDemo + kShort + " --set fluid.gravity=0 --out " + out.string()),
      {"fluid.gravity = 0", "nothing settles"});

  TestReadings dem{"hydrometer", {}, {}}, ref{"hydrometer", {}, {}};
  dem.rows.push_back({60, std::numeric_limits<double>::infinity(), std::nan(""), {}});
  ref.rows.push_back({60, 1e-5, 50, {}});
  EXPECT_TRUE(std::isnan(curve_error(dem, ref)));
  std::ostringstream csv;
  write_readings_csv(csv, dem);
  EXPECT_EQ(csv.str().find("nan"), std::string::npos) << csv.str();
  EXPECT_EQ(csv.str().find("inf"), std::string::npos) << csv.str();
}

// 2. A hydrometer off its scale, or that does not float, is refused; readings off the scale
// during a run are flagged.
TEST(Faults, AHydrometerOffItsScaleIsRefusedOrFlagged) {
  const fs::path out = fresh("off_scale");
  expect_refused(
      test::run_sedem("run " + kDemo + kShort + " --set fluid.density=1100 --out " + out.string()),
      {"fluid.density = 1100", "off its scale"});
  expect_refused(
      test::run_sedem("run " + kDemo + kShort + " --set fluid.density=950 --out " + out.string()),
      {"fluid.density = 950", "sinks"});
  auto r = test::run_sedem("run " + kDemo + kShort +
                           " --set instruments.hydrometer.times_min=[0.02] --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(text_of(out / "readings_hydrometer.csv").find(",on_scale\n"), std::string::npos);
  EXPECT_TRUE(read_json(out / "run.json")["results"]["hydrometer"].contains("off_scale_readings"));
}

// 3. A checkpoint proves which run it belongs to.
TEST(Faults, ACheckpointOfAnotherRunIsRefused) {
  const fs::path dir = fresh("identity");
  run_and_kill_after_checkpoint(dir);
  // run.json edited to another seed: the checkpoint is not that run's.
  const std::string original = text_of(dir / "run.json");
  auto record = read_json(dir / "run.json");
  record["scene"]["sample.seed"] = 8;
  write_text(dir / "run.json", record.dump(2));
  expect_refused(test::run_sedem("run --resume " + dir.string()), {"another run"});
  write_text(dir / "run.json", original);

  // Another run into the folder, killed before its first checkpoint: the old checkpoint is
  // gone with the old run, nothing is mixed: --resume starts the new run again from its
  // beginning (stopped here by SIGTERM a moment later).
  auto other = test::run_sedem(
      "run " + kDemo + kSlow +
      " --set sample.seed=2 --set run.checkpoint_interval_s=0 --overwrite --out " + dir.string() +
      " & pid=$!; for i in $(seq 400); do grep -qs '\"sample.seed\": 2' " + dir.string() +
      "/run.json && break; sleep 0.05; done; kill -KILL $pid; wait $pid");
  ASSERT_EQ(other.status, 137) << other.output;
  auto again =
      test::run_sedem("run --resume " + dir.string() + " 2>&1 & pid=$!; " +
                      test::until_sigterm_caught() + "sleep 1.5; kill -TERM $pid; wait $pid");
  EXPECT_EQ(again.status, 130) << again.output;
  EXPECT_NE(again.output.find("starting it again from the beginning"), std::string::npos)
      << again.output;
  const auto restarted = read_json(dir / "run.json");
  EXPECT_EQ(restarted["scene"]["sample.seed"], 2);
  EXPECT_EQ(restarted["status"], "interrupted");
  EXPECT_EQ(restarted["legs"], 1);
}

// 4. A run killed before its first checkpoint leaves nothing to resume, and no folder that
// needs --overwrite: a plain run into it takes it over (its lock is free, its run.json still
// says "running").
TEST(Faults, AFolderOfARunKilledBeforeItsFirstCheckpointIsTakenOver) {
  const fs::path dir = fresh("killed_early");
  auto killed =
      test::run_sedem("run " + kDemo + kSlow + " --set run.checkpoint_interval_s=0 --out " +
                      dir.string() + " & pid=$!; for i in $(seq 400); do [ -f " + dir.string() +
                      "/run.json ] && break; sleep 0.05; done; kill -KILL $pid; wait $pid");
  ASSERT_EQ(killed.status, 137) << killed.output;
  ASSERT_EQ(read_json(dir / "run.json")["status"], "running");
  auto r = test::run_sedem("run " + kDemo + kShort + " --out " + dir.string());
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(read_json(dir / "run.json")["status"], "complete");
  // One that was stopped cleanly (interrupted, with a checkpoint) is kept: resume or
  // --overwrite.
  auto stopped = test::run_sedem("run " + kDemo + kSlow + " --overwrite --out " + dir.string() +
                                 " & pid=$!; " + test::until_sigterm_caught() +
                                 "sleep 1.5; kill -TERM $pid; wait $pid");
  ASSERT_EQ(stopped.status, 130) << stopped.output;
  auto refused = test::run_sedem("run " + kDemo + kShort + " --out " + dir.string());
  EXPECT_EQ(refused.status, 3) << refused.output;
  EXPECT_NE(refused.output.find("holds an interrupted run"), std::string::npos) << refused.output;
}

// 4. The first periodic checkpoint comes after about 10 s of wall time, whatever
// run.checkpoint_interval_s (here its default, 3 min): a SIGKILL a moment after it loses only
// that moment, and --resume ends exactly as the same run never stopped (run beside it).
// Its run is long enough (400 s simulated, about 20 s of wall time on an idle machine) that the
// kill always comes after the first checkpoint: a shorter one ended first and the test skipped.
TEST(Faults, AKillAfterTheFirstTenSecondsResumesFromAnEarlyCheckpoint) {
  const fs::path whole = fresh("early_whole"), parts = fresh("early_parts");
  const std::string scene = killable_demo("400") + " --set integrator.threads=1";
  const std::string w = whole.string(), p = parts.string();
  auto r = test::run_sedem(
      "run " + scene + " --out " + w + " & whole=$!; " + SEDEM_EXE + " run " + scene + " --out " +
      p + " & parts=$!; start=$(date +%s); for i in $(seq 900); do [ -f " + p +
      "/checkpoint.json ] && break; sleep 0.05; done; echo \"first checkpoint after " +
      "$(( $(date +%s) - start )) s\"; sleep 1; kill -KILL $parts; wait $parts; echo " +
      "\"killed: $?\"; " + SEDEM_EXE + " run --resume " + p + " --quiet; echo \"resumed: $?\"; " +
      "wait $whole; echo \"whole: $?\"");
  if (r.output.find("killed: 0") != std::string::npos)
    GTEST_SKIP() << "the run ended within 11 s, before it could be killed: " << r.output;
  EXPECT_NE(r.output.find("killed: 137"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("resumed: 0"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("whole: 0"), std::string::npos) << r.output;
  const auto record = read_json(parts / "run.json");
  EXPECT_EQ(record["status"], "complete");
  EXPECT_EQ(record["legs"], 2);
  for (const char* file : {"readings_hydrometer.csv", "readings_buoyancy.csv",
                           "readings_pipette.csv", "granulometry.csv", "particles.pvd"})
    EXPECT_EQ(text_of(parts / file), text_of(whole / file)) << file;
  EXPECT_EQ(text_of(parts / "particles/particles_000002.vtp"),
            text_of(whole / "particles/particles_000002.vtp"));
}

// 5. `render --partial` of a run that did not complete says so in every output: a "# partial"
// first line in each CSV, " (partial)" in each figure's title, " (partial run)" on each frame,
// "partial": true in run.json.
TEST(Faults, RenderPartialMarksEveryOutput) {
  const fs::path dir = fresh("render_partial");
  auto stopped =
      test::run_sedem("run " + kDemo + kSlow +
                      " --set output.frames=true --set output.figure_formats=png,svg --out " +
                      dir.string() + " & pid=$!; sleep 3; kill -TERM $pid; wait $pid");
  ASSERT_EQ(stopped.status, 130) << stopped.output;
  expect_refused(test::run_sedem("render --quiet " + dir.string()), {"--partial"});
  // The frames too: redrawn from the same snapshot, the first differs from the run's own by its
  // label, which now says "(partial run)".
  const fs::path frame = dir / "frames/column_000000.png";
  ASSERT_TRUE(fs::exists(frame));
  const std::string run_frame = text_of(frame);
  auto r = test::run_sedem("render --partial --quiet " + dir.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(text_of(frame), run_frame);
  int csvs = 0, svgs = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const auto ext = e.path().extension();
    if (ext == ".csv") {
      ++csvs;
      EXPECT_EQ(text_of(e.path()).rfind("# partial: ", 0), 0u) << e.path();
    } else if (ext == ".svg") {
      ++svgs;
      EXPECT_NE(text_of(e.path()).find("(partial)"), std::string::npos) << e.path();
    }
  }
  EXPECT_GE(csvs, 4);  // readings, granulometry, a figure's
  EXPECT_GE(svgs, 1);
  const auto record = read_json(dir / "run.json");
  EXPECT_EQ(record["partial"], true);
  EXPECT_EQ(record["status"], "interrupted");
}

// Runs `sedem run ARGS`, sends SIGTERM after 4 s and expects a clean stop within 3 s: exit
// 130, "interrupted" and a checkpoint.
void expect_prompt_stop(const fs::path& dir, const std::string& args) {
  auto r = test::run_sedem("run " + args + " --out " + dir.string() +
                           " & pid=$!; sleep 4; start=$(date +%s%N); kill -TERM $pid; wait $pid;" +
                           " status=$?; echo \"stopped in $(( ($(date +%s%N) - start) / " +
                           "1000000 )) ms\"; exit $status");
  EXPECT_EQ(r.status, 130) << r.output;
  const auto at = r.output.find("stopped in ");
  ASSERT_NE(at, std::string::npos) << r.output;
  EXPECT_LT(std::stoi(r.output.substr(at + 11)), 3000) << r.output;
  EXPECT_EQ(read_json(dir / "run.json")["status"], "interrupted");
  EXPECT_TRUE(fs::exists(dir / "checkpoint.bin"));
}

// 4. A long loop checks for a stop: 10 000 profile times (each a snapshot, a profile of every
// layer) stop within about a second of SIGTERM, with a checkpoint and "interrupted".
TEST(Faults, ManyProfileTimesStopPromptly) {
  std::string times = "[";
  for (int i = 0; i < 10000; ++i) {
    if (i) times += ',';
    times += std::to_string(i * 0.0002);
  }
  times += "]";
  // (Many particles: with the instruments' readings kept in the checkpoint instead of a
  // snapshot file at every profile time, the demo's count ends the run before the stop.)
  expect_prompt_stop(
      fresh("many_profiles"),
      kDemo + " --set output.frames=false --quiet --set " +
          "sample.simulated_count=100000 --set 'instruments.profile_times_min=" + times + "'");
}

// 4. Coasting on windows far shorter than a step (integrator.max_coast_s near the least the
// scene check allows) keeps a stop prompt: a step with no member moving takes a bounded number
// of syncs, where one max_step_s once held about 1e8 of them and a minute and a half of work.
TEST(Faults, ShortCoastingWindowsStopPromptly) {
  expect_prompt_stop(fresh("short_coasting"),
                     kDemo + " --set output.frames=false --quiet --set run.end_time_s=60 --set " +
                         "integrator.local_steps=true --set integrator.max_coast_s=2e-5 --set " +
                         "sample.simulated_count=3000");
}

// 2. Doubts on a run: too few particles in an instrument's volume, counted, in run.json.
TEST(Faults, FewParticlesInAnInstrumentsVolumeAreAWarningInRunJson) {
  const fs::path dir = fresh("few_particles");
  auto r = test::run_sedem("run " + kDemo + kShort + " --set sample.simulated_count=200 --out " +
                           dir.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("sedem: warning: pipette: its sampled volume holds about 4.8 of the 200"),
            std::string::npos)
      << r.output;
  const auto warnings = read_json(dir / "run.json")["warnings"];
  bool pipette = false;
  for (const auto& w : warnings)
    if (w["code"] == "few_particles" &&
        w["message"].get<std::string>().find("pipette: its sampled volume holds about 4.8 of "
                                             "the 200 simulated particles") != std::string::npos)
      pipette = true;
  EXPECT_TRUE(pipette) << warnings.dump(2);
}

// 4. Every value read back from a checkpoint is checked.
TEST(Faults, ADamagedCheckpointIsRefusedFieldByField) {
  const fs::path dir = fresh("damaged_checkpoint");
  // The global step: every grain's state is in the engine's arrays, whose layout this test
  // reads (local steps keep coasting grains in arrays of their own, checked on load too).
  run_and_kill_after_checkpoint(dir, " --set integrator.local_steps=false");
  const std::string good = text_of(dir / "checkpoint.bin");
  const std::string good_record = text_of(dir / "checkpoint.json");

  // A byte changed, the record left as it was: the bytes do not match.
  std::string flipped = good;
  flipped[flipped.size() / 2] ^= 0x40;
  write_text(dir / "checkpoint.bin", flipped);
  expect_refused(test::run_sedem("run --resume " + dir.string()), {"does not match"});

  // Written by an older sedem (the magic's last byte is the format's version).
  std::string older = good;
  older[7] = '1';
  forge_checkpoint(dir, older);
  expect_refused(test::run_sedem("run --resume " + dir.string()),
                 {"written by another version of sedem", "run it again from the start"});

  // The time (after the 8-byte magic and the count of particles the state holds): NaN,
  // negative, past the end.
  for (double t : {std::nan(""), -1.0, 1e9}) {
    write_text(dir / "checkpoint.json", good_record);
    std::string bytes = good;
    std::memcpy(bytes.data() + 16, &t, sizeof t);
    forge_checkpoint(dir, bytes);
    expect_refused(test::run_sedem("run --resume " + dir.string()), {"damaged checkpoint", "time"});
  }

  // One entry of the particle order (a length, then distinct sample indices below n as
  // uint32: all of them, or with local steps those of the m grains on the common step).
  const auto n = read_json(dir / "run.json")["particle_count"].get<std::uint64_t>();
  std::uint64_t m = 0;
  std::memcpy(&m, good.data() + 8, 8);
  ASSERT_GT(m, 0u) << "no grain on the common step when the checkpoint was written";
  std::size_t at = std::string::npos;
  for (std::size_t i = 16; i + 8 + 4 * m <= good.size() && at == std::string::npos; ++i) {
    std::uint64_t len;
    std::memcpy(&len, good.data() + i, 8);
    if (len != m) continue;
    std::vector<std::uint8_t> seen(n, 0);
    bool permutation = true;
    for (std::size_t k = 0; k < m && permutation; ++k) {
      std::uint32_t v;
      std::memcpy(&v, good.data() + i + 8 + 4 * k, 4);
      permutation = v < n && !seen[v];
      if (permutation) seen[v] = 1;
    }
    if (permutation) at = i + 8;
  }
  ASSERT_NE(at, std::string::npos) << "no particle order found in the checkpoint";
  std::string bytes = good;
  const std::uint32_t huge = 2147483647u;
  std::memcpy(bytes.data() + at, &huge, 4);
  write_text(dir / "checkpoint.json", good_record);
  forge_checkpoint(dir, bytes);
  expect_refused(test::run_sedem("run --resume " + dir.string()), {"damaged checkpoint"});

  // Cut short.
  write_text(dir / "checkpoint.json", good_record);
  forge_checkpoint(dir, good.substr(0, good.size() / 3));
  expect_refused(test::run_sedem("run --resume " + dir.string()), {"checkpoint"});
}

// 5 and 13. A damaged or missing .pvd or .vtp is refused by `render` and `--resume`, naming
// the file, and nothing is rewritten from it.
TEST(Faults, ADamagedSeriesIsRefusedNamingTheFile) {
  const fs::path dir = fresh("damaged_series");
  ASSERT_EQ(test::run_sedem("run " + kDemo + " --set run.end_time_s=20" +
                            " --set output.frames=false --quiet --out " + dir.string())
                .status,
            0);
  const std::string pvd = text_of(dir / "particles.pvd");
  const std::string readings = text_of(dir / "readings_buoyancy.csv");
  write_text(dir / "particles.pvd", pvd.substr(0, 300));
  expect_refused(test::run_sedem("render " + dir.string()), {"particles.pvd"});
  EXPECT_EQ(text_of(dir / "readings_buoyancy.csv"), readings);
  write_text(dir / "particles.pvd", pvd);

  const fs::path vtp = dir / "particles/particles_000001.vtp";
  const std::string data = text_of(vtp);
  write_text(vtp, data.substr(0, data.size() / 2));
  expect_refused(test::run_sedem("render " + dir.string()), {"particles_000001.vtp", "damaged"});
  // Cut at its very end, or bytes of its compressed data changed: damaged too, never "no
  // point array" alone.
  write_text(vtp, data.substr(0, data.size() - 20));
  expect_refused(test::run_sedem("render " + dir.string()), {"particles_000001.vtp", "damaged"});
  std::string changed = data;
  for (std::size_t i = changed.size() / 2; i < changed.size() / 2 + 300; ++i)
    changed[i] = char(changed[i] * 7 + 3);
  write_text(vtp, changed);
  expect_refused(test::run_sedem("render " + dir.string()),
                 {"particles_000001.vtp", "damaged", "corrupted"});
  // A compressed array's block count made huge (8 bytes of the raw appended data): VTK sizes
  // the array from it and throws bad_alloc, which once ended as a write failure (exit 4).
  {
    std::string huge = data;
    const auto appended = huge.find('_', huge.find("<AppendedData encoding=\"raw\">")) + 1;
    const auto second = huge.find("offset=\"", huge.find("Name=\"radius\"")) + 8;
    const std::size_t at = appended + std::stoul(huge.substr(second));
    huge.replace(at, 8, std::string("\xff\xff\xff\xff\xff\xff\xff\x0f", 8));
    write_text(vtp, huge);
    expect_refused(test::run_sedem("render " + dir.string()),
                   {"particles_000001.vtp", "damaged", "does not read back"});
  }
  fs::remove(vtp);
  expect_refused(test::run_sedem("render " + dir.string()), {"particles_000001.vtp"});
  write_text(vtp, data);
  EXPECT_EQ(test::run_sedem("render --quiet " + dir.string()).status, 0);

  const fs::path resumed = fresh("damaged_series_resume");
  run_and_kill_after_checkpoint(resumed);
  write_text(resumed / "particles.pvd", text_of(resumed / "particles.pvd").substr(0, 150));
  expect_refused(test::run_sedem("run --resume " + resumed.string()), {"particles.pvd"});
}

// 6. `reduce`: results that cannot be right are refused; spreadsheet CSVs are read; a write
// error is an error.
TEST(Faults, ReduceRefusesWhatItCannotComputeAndReadsSpreadsheetCsv) {
  const fs::path dir = fresh("reduce");
  fs::create_directories(dir);
  const std::string rows = "2,42,22,5\n5,35,22,5\n15,28,22,5\n";
  write_text(dir / "plain.csv",
             "time_min,reading_g_per_l,temperature_c,composite_correction_g_per_l\n" + rows);
  write_text(dir / "excel.csv",
             "\xEF\xBB\xBF\"time_min\",\"reading_g_per_l\",\"temperature_c\","
             "\"composite_correction_g_per_l\"\r\n" +
                 rows);
  write_text(
      dir / "huge.csv",
      "time_min,reading_g_per_l,temperature_c,composite_correction_g_per_l\n2,42,22,1e308\n");
  auto plain = test::run_sedem("reduce " + (dir / "plain.csv").string());
  auto excel = test::run_sedem("reduce " + (dir / "excel.csv").string());
  ASSERT_EQ(plain.status, 0) << plain.output;
  ASSERT_EQ(excel.status, 0) << excel.output;
  EXPECT_EQ(excel.output, plain.output);
  expect_refused(test::run_sedem("reduce " + (dir / "huge.csv").string()),
                 {"composite_correction_g_per_l"});
  expect_refused(test::run_sedem("reduce " + (dir / "plain.csv").string() + " --mass-g 0.001"),
                 {"percent_finer", "--mass-g"});
  // stderr to the pipe, stdout to a full disk.
  auto full = test::run_sedem("--version > /dev/null; ( exec " SEDEM_EXE " reduce " +
                              (dir / "plain.csv").string() + " 2>&1 > /dev/full )");
  EXPECT_EQ(full.status, 4) << full.output;
  EXPECT_NE(full.output.find("No space left"), std::string::npos) << full.output;
}

// 6. Laboratory files (issue 26, item 6): times, readings and corrections range-checked with
// the line and column named; any line end; no readings, too many rows and flags out of range
// refused; --out only a regular file or a new path; a full disk is exit 4 with no half file.
TEST(Faults, LabFilesAreCheckedReadWithAnyLineEndAndWrittenWhole) {
  const fs::path dir = fresh("lab_files");
  fs::create_directories(dir);
  const std::string header = "time_min,reading_g_per_l,temperature_c,composite_correction_g_per_l";
  const auto file = [&](const std::string& name, const std::string& text) {
    write_text(dir / name, text);
    return (dir / name).string();
  };
  const std::string plain = file("plain.csv", header + "\n2,42,22,5\n5,35,22,5\n15,28,22,5\n");
  auto ok = test::run_sedem("reduce " + plain);
  ASSERT_EQ(ok.status, 0) << ok.output;
  // CR only (old spreadsheets) and CRLF: the same three rows.
  for (const char* eol : {"\r", "\r\n"}) {
    auto r =
        test::run_sedem("reduce " + file("eol.csv", header + eol + "2,42,22,5" + eol + "5,35,22,5" +
                                                        eol + "15,28,22,5" + eol));
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(r.output, ok.output);
  }
  expect_refused(test::run_sedem("reduce " + file("header.csv", header + "\n")), {"no readings"});
  expect_refused(test::run_sedem("reduce " + file("inf.csv", header + "\n1e308,42,22,5\n")),
                 {"line 2", "time_min", "out of range"});
  expect_refused(test::run_sedem("reduce " + file("tiny.csv", header + "\n1e-300,42,22,5\n")),
                 {"diameter_m", "time_min", "line 2"});
  expect_refused(test::run_sedem("reduce " + file("nan.csv", header + "\n2,42,22,nan\n")),
                 {"line 2", "composite_correction_g_per_l", "not a finite number"});
  expect_refused(test::run_sedem("reduce " + file("nan_reading.csv", header + "\n2,NaN,22,5\n")),
                 {"line 2", "reading_g_per_l"});
  std::string many = header + "\n";
  for (int i = 1; i <= 10001; ++i) many += std::to_string(i) + ",20,20,1\n";
  expect_refused(test::run_sedem("reduce " + file("many.csv", many)), {"more than 10000"});
  // A long bad value is cut in the message.
  auto long_value = test::run_sedem(
      "reduce " + file("long.csv", header + "\n2," + std::string(5000, 'x') + ",22,5\n"));
  EXPECT_EQ(long_value.status, 2);
  EXPECT_LT(long_value.output.size(), 1000u) << long_value.output.size();
  EXPECT_NE(long_value.output.find("5000 characters"), std::string::npos) << long_value.output;
  // Flags out of range are named.
  const std::string pipette = file("pipette.csv", "time_min,dry_mass_g\n1,1.4\n4,1.1\n16,0.9\n");
  for (const char* t : {"nan", "200", "-5"})
    expect_refused(test::run_sedem("invert " + pipette + " --test pipette --temperature-c " + t +
                                   " --out " + (dir / "inv").string()),
                   {"--temperature-c", "out of range"});
  // --out: a folder, a pipe, a device are refused before anything is written.
  fs::create_directories(dir / "a_folder");
  ASSERT_EQ(std::system(("mkfifo " + (dir / "a_fifo").string()).c_str()), 0);
  for (const auto& out :
       {(dir / "a_folder").string(), (dir / "a_fifo").string(), std::string("/dev/full")}) {
    auto r = test::run_sedem("reduce " + plain + " --out " + out);
    EXPECT_EQ(r.status, 3) << out << "\n" << r.output;
    EXPECT_NE(r.output.find("regular file or a new path"), std::string::npos) << r.output;
  }
  EXPECT_TRUE(fs::is_character_file("/dev/full"));
  EXPECT_TRUE(fs::is_fifo(dir / "a_fifo"));
  // A full disk (no file may grow: ulimit -f 0, SIGXFSZ ignored so that writes fail with
  // EFBIG): exit 4, and no empty or temporary file left.
  const fs::path full = dir / "full";
  auto r = test::run_sedem(
      "--version > /dev/null; ( trap '' XFSZ; ulimit -f 0; exec " SEDEM_EXE " invert " + pipette +
      " --test pipette --replicas 0 -q --out " + full.string() + " )");
  EXPECT_EQ(r.status, 4) << r.output;
  for (const auto& e : fs::directory_iterator(full)) {
    EXPECT_GT(fs::file_size(e.path()), 0u) << e.path();
    EXPECT_NE(e.path().extension(), ".tmp") << e.path();
  }
  r = test::run_sedem("--version > /dev/null; ( trap '' XFSZ; ulimit -f 0; exec " SEDEM_EXE
                      " reduce " +
                      plain + " --out " + (dir / "reduced.csv").string() + " )");
  EXPECT_EQ(r.status, 4) << r.output;
  EXPECT_FALSE(fs::exists(dir / "reduced.csv"));
  EXPECT_FALSE(fs::exists(dir / "reduced.csv.tmp"));
}

// 7. Values the instruments cannot use are refused at the scene check: exit 2, key, value.
TEST(Faults, ValuesTheInstrumentsCannotUseAreRefusedAtTheSceneCheck) {
  const fs::path out = fresh("late");
  for (const char* set :
       {"instruments.pipette.depth_fraction=0", "instruments.pipette.depth_fraction=1",
        "instruments.buoyancy.depth_fraction=0", "instruments.buoyancy.depth_fraction=1",
        "instruments.pipette.volume_ml=1000", "fluid.density=500", "cylinder.height_m=1e-4",
        "forces.drag=off"}) {
    auto r = test::run_sedem("run " + kDemo + kShort + " --set " + set + " --out " + out.string());
    EXPECT_EQ(r.status, 2) << set << "\n" << r.output;
    const std::string key = std::string(set).substr(0, std::string(set).find('='));
    EXPECT_NE(r.output.find(" = "), std::string::npos) << r.output;
    EXPECT_TRUE(r.output.find(key) != std::string::npos ||
                r.output.find("cylinder.height_m") != std::string::npos)
        << set << "\n"
        << r.output;
    EXPECT_FALSE(fs::exists(out / "run.json")) << set << ": refused after it started";
  }
}

TEST(Faults, EveryShippedSceneRuns) {
  for (const auto& e : fs::directory_iterator(kScenes)) {
    if (e.path().extension() != ".toml") continue;
    const fs::path out = fresh("shipped_" + e.path().stem().string());
    auto r = test::run_sedem("run " + e.path().string() + " --out " + out.string() +
                             " --set run.end_time_s=0.5 --set output.frames=false"
                             " --set output.particles=false --set output.fields=false --quiet");
    EXPECT_EQ(r.status, 0) << e.path() << "\n" << r.output;
  }
}

// 8. A folder or a device is no scene.
TEST(Faults, ARunOfAFolderOrADeviceIsRefused) {
  const fs::path out = fresh("not_a_file");
  expect_refused(test::run_sedem("run /tmp --out " + out.string()), {"/tmp", "not a scene file"});
  expect_refused(test::run_sedem("run /dev/zero --out " + out.string()),
                 {"/dev/zero", "not a scene file"});
  EXPECT_FALSE(fs::exists(out));
}

// 9. A run that cannot fit in memory is refused before it starts, with the estimate and the
// memory there is (here an address-space limit stands for a small machine).
TEST(Faults, ARunThatCannotFitInMemoryIsRefusedBeforeItStarts) {
  const fs::path out = fresh("memory");
  auto r = test::run_sedem("--version > /dev/null; ( ulimit -v 3000000; exec " SEDEM_EXE " run " +
                           kDemo + kShort + " --set forces.voidage_cell_mm=0.01 --out " +
                           out.string() + " )");
  expect_refused(r, {"needs about", "GB of memory", "forces.voidage_cell_mm"});
}

// 10 and 13. SIGKILL at seeded random moments: the run goes on from its last periodic
// checkpoint and ends bit-identical to one never stopped; run.json covers every leg.
TEST(Faults, AKilledRunResumesFromItsLastCheckpointBitForBit) {
  const fs::path whole = fresh("kill_whole"), parts = fresh("kill_parts");
  const std::string scene = killable_demo("20") + " --set run.checkpoint_interval_s=0.2";
  ASSERT_EQ(test::run_sedem("run " + scene + " --out " + whole.string()).status, 0);
  std::mt19937 rng(16);
  std::string command = "run " + scene + " --out " + parts.string();
  int kills = 0;
  for (int leg = 0; leg < 3; ++leg) {
    // Killed at a random moment after the first checkpoint exists (the first leg waits for
    // it, however loaded the machine): a resumed leg may be killed before it writes its own.
    const double delay = 0.2 + std::uniform_real_distribution<double>(0, 1)(rng);
    auto r = test::run_sedem(command + " & pid=$!; for i in $(seq 600); do [ -f " + parts.string() +
                             "/checkpoint.json ] && break; sleep 0.05; done; " + "sleep " +
                             std::to_string(delay) + "; kill -KILL $pid; wait $pid");
    if (r.status != 137 && read_json(parts / "run.json")["status"] == "complete")
      break;  // it ended before the kill
    ASSERT_EQ(r.status, 137) << r.output;
    ASSERT_TRUE(fs::exists(parts / "checkpoint.bin"));
    ++kills;
    command = "run --resume " + parts.string() + " --quiet";
  }
  ASSERT_GT(kills, 0);
  if (fs::exists(parts / "checkpoint.bin")) {
    auto r = test::run_sedem("run --resume " + parts.string() + " --quiet");
    ASSERT_EQ(r.status, 0) << r.output;
  }
  auto record = read_json(parts / "run.json");
  EXPECT_EQ(record["status"], "complete");
  EXPECT_EQ(record["scene_file"], kDemo);
  EXPECT_GE(record["legs"].get<int>(), 2);
  EXPECT_FALSE(fs::exists(parts / "checkpoint.bin"));
  for (const char* file : {"readings_buoyancy.csv", "readings_pipette.csv", "granulometry.csv",
                           "particles.pvd", "fields.pvd"})
    EXPECT_EQ(text_of(parts / file), text_of(whole / file)) << file;
  EXPECT_EQ(text_of(parts / "particles/particles_000002.vtp"),
            text_of(whole / "particles/particles_000002.vtp"));
}

// 11. Every place a run writes to is checked before it simulates; a failure keeps its first
// cause, leaves no temporary file and finishes run.json as "failed".
TEST(Faults, UnwritableOutputsAreFoundBeforeSimulating) {
  const fs::path out = fresh("blocked");
  fs::create_directories(out);
  write_text(out / "figures", "a file where the figures folder goes");
  // Since a run folder holds one run only, a folder holding anything else is refused first.
  auto r = test::run_sedem("run " + kDemo + kShort + " --out " + out.string());
  EXPECT_EQ(r.status, 3) << r.output;
  EXPECT_TRUE(r.output.find("figures") != std::string::npos ||
              r.output.find("not empty") != std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(out / "run.json"));
}

// 13. A huge name is refused by its length.
TEST(Faults, AHugeNameIsRefused) {
  const fs::path out = fresh("name");
  expect_refused(test::run_sedem("run " + kDemo + kShort + " --set name=\\\"" +
                                 std::string(5000, 'n') + "\\\" --out " + out.string()),
                 {"name is 5000 characters long"});
}

}  // namespace
}  // namespace sedem
