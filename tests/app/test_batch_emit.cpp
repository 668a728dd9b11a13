// `sedem batch --emit slurm|parallel` and `sedem batch --gather`: a batch handed to a
// scheduler gives the summary the same batch gives run here. Ten seeds of a tiny demo run
// here once; then the same batch by hand from the Slurm script (each task with its
// SLURM_ARRAY_TASK_ID), through GNU parallel (on this machine and over --sshlogin), and
// through a real Slurm of one node started by the test: each summary.csv is the local one
// (but the wall times), and summary_stats.csv and summary_granulometry.csv are the local
// ones byte for byte.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/file.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "csv_rows.h"

namespace sedem {
namespace {

namespace fs = std::filesystem;
using test::read_rows;
using test::run_command;
using test::run_sedem;

const fs::path kOut = fs::path(SEDEM_TEST_OUTPUT) / "batch_emit";
const std::string kDemo = std::string(SEDEM_SOURCE_DIR) + "/scenes/demo.toml";
const std::string kScripts = std::string(SEDEM_SOURCE_DIR) + "/tests/app/";
constexpr int kSeeds = 10;
// Under a second a run: 200 particles, 20 s, each test read once.
const std::string kTiny =
    " --seeds 10 --set sample.simulated_count=200 --set output.frames=false"
    " --set output.particles=false --set run.end_time_s=20"
    " --set instruments.hydrometer.times_min=[0.25] --set instruments.buoyancy.times_min=[0.25]"
    " --set instruments.pipette.times_min=[0.25] --quiet";

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path fresh(const std::string& name) {
  fs::remove_all(kOut / name);
  fs::create_directories(kOut);
  return kOut / name;
}

std::string seed_folder(int k) {
  return "demo__seed=" + std::to_string(k);
}

// Whether `dir` holds a local batch of the ten seeds from this sedem and this scene.
bool holds_local_batch(const fs::path& dir) {
  std::error_code ec;
  const auto written = fs::last_write_time(dir / "summary_stats.csv", ec);
  if (ec || written < fs::last_write_time(SEDEM_EXE) || written < fs::last_write_time(kDemo))
    return false;
  const auto rows = read_rows(dir / "summary.csv");
  return rows.size() == std::size_t(kSeeds) &&
         std::all_of(rows.begin(), rows.end(),
                     [](const test::Row& r) { return r.at("status") == "complete"; });
}

// The ten seeds run here, once for all the tests that compare with them (each test is a
// process of its own under ctest, and ctest -j runs several at once: a lock keeps them from
// running it twice or reading it half written).
const fs::path& local_batch() {
  static const fs::path out = [] {
    const fs::path dir = kOut / "local";
    fs::create_directories(kOut);
    const int lock = ::open((kOut / "local.lock").c_str(), O_CREAT | O_RDWR, 0644);
    ::flock(lock, LOCK_EX);
    if (!holds_local_batch(dir)) {
      fs::remove_all(dir);
      const auto r = run_sedem("batch " + kDemo + " --out " + dir.string() + " --jobs 2" + kTiny);
      EXPECT_EQ(r.status, 0) << r.output;
    }
    ::flock(lock, LOCK_UN);
    ::close(lock);
    return dir;
  }();
  return out;
}

// `dir`'s summary is the local batch's: every row and column of summary.csv but the wall time
// (each run its own), and the statistics and the mean curve over the seeds byte for byte.
void expect_local_summary(const fs::path& dir) {
  const auto local = read_rows(local_batch() / "summary.csv");
  const auto here = read_rows(dir / "summary.csv");
  ASSERT_EQ(local.size(), std::size_t(kSeeds));
  ASSERT_EQ(here.size(), local.size());
  for (std::size_t i = 0; i < local.size(); ++i) {
    EXPECT_EQ(here[i].at("status"), "complete") << here[i].at("run");
    for (const auto& [column, value] : local[i]) {
      if (column == "wall_time_s") continue;
      EXPECT_EQ(here[i].at(column), value) << "row " << i << ", " << column;
    }
  }
  for (const char* file : {"summary_stats.csv", "summary_granulometry.csv"}) {
    ASSERT_TRUE(fs::exists(dir / file)) << dir / file;
    EXPECT_EQ(read_text(dir / file), read_text(local_batch() / file)) << file;
  }
  EXPECT_TRUE(fs::exists(dir / "index.html"));
  EXPECT_TRUE(fs::exists(dir / "summary_granulometry.png"));
}

// The script's #SBATCH options, as sbatch reads them: the lines of the first comment block
// that start with #SBATCH, up to the first command.
std::map<std::string, std::string> sbatch_options(const fs::path& script) {
  std::ifstream in(script);
  std::string line;
  std::map<std::string, std::string> options;
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] != '#') break;
    if (line.rfind("#SBATCH ", 0) != 0) continue;
    const std::string option = line.substr(8);
    const auto eq = option.find('=');
    options[option.substr(0, eq)] = eq == std::string::npos ? "" : option.substr(eq + 1);
  }
  return options;
}

std::vector<std::string> lines_of(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// Task `k` of the Slurm script run by hand, as slurmd would: the script with the array's
// variables set, from another folder.
test::CommandResult run_task_by_hand(const fs::path& dir, int k) {
  return run_command("cd / && SLURM_ARRAY_TASK_ID=" + std::to_string(k) +
                     " SLURM_ARRAY_JOB_ID=1 SLURM_CPUS_PER_TASK=1 bash " +
                     (dir / "sedem.sbatch").string());
}

TEST(BatchEmit, TheSlurmScriptAsksForWhatTheOptionsSay) {
  const fs::path dir = fresh("script");
  const auto r = run_sedem("batch " + kDemo + " --out " + dir.string() + kTiny +
                           " --emit slurm --slurm-time 1-02:30:00 --slurm-mem 700M"
                           " --slurm-cpus 2 --slurm-partition short --slurm-account geo");
  ASSERT_EQ(r.status, 0) << r.output;
  const auto options = sbatch_options(dir / "sedem.sbatch");
  EXPECT_EQ(options.at("--array"), "0-9");
  EXPECT_EQ(options.at("--time"), "1-02:30:00");
  EXPECT_EQ(options.at("--mem"), "700M");
  EXPECT_EQ(options.at("--cpus-per-task"), "2");
  EXPECT_EQ(options.at("--partition"), "short");
  EXPECT_EQ(options.at("--account"), "geo");
  EXPECT_EQ(options.at("--chdir"), dir.string());
  // One output file per task, in a folder that exists before the job starts.
  EXPECT_EQ(options.at("--output"), (dir / "tasks/logs/%A_%a.out").string());
  EXPECT_TRUE(fs::is_directory(dir / "tasks/logs"));
  // Asked to stop two minutes before the limit, so that the run writes its checkpoint.
  EXPECT_EQ(options.at("--signal"), "B:TERM@120");

  // Task k runs line k + 1 of runs.txt; each has its resolved scene; batch.json lists them
  // in the same order.
  const auto runs = lines_of(dir / "tasks/runs.txt");
  ASSERT_EQ(runs.size(), std::size_t(kSeeds));
  const auto plan = nlohmann::json::parse(read_text(dir / "batch.json"));
  ASSERT_EQ(plan["runs"].size(), std::size_t(kSeeds));
  for (int k = 0; k < kSeeds; ++k) {
    EXPECT_EQ(runs[k], seed_folder(k + 1));
    EXPECT_EQ(plan["runs"][k]["folder"], runs[k]);
    EXPECT_EQ(plan["runs"][k]["seed"], k + 1);
    const std::string scene = read_text(dir / "tasks" / (runs[k] + ".toml"));
    EXPECT_NE(scene.find("\nsample.seed = " + std::to_string(k + 1) + "\n"), std::string::npos);
    EXPECT_NE(scene.find("\nsample.simulated_count = 200\n"), std::string::npos);
  }
  // The default memory is the runs' estimate with a margin, in megabytes.
  const fs::path other = fresh("script_default");
  ASSERT_EQ(
      run_sedem("batch " + kDemo + " --out " + other.string() + kTiny + " --emit slurm").status, 0);
  const auto defaults = sbatch_options(other / "sedem.sbatch");
  EXPECT_EQ(defaults.at("--time"), "01:00:00");
  EXPECT_EQ(defaults.at("--cpus-per-task"), "1");
  ASSERT_FALSE(defaults.at("--mem").empty());
  EXPECT_EQ(defaults.at("--mem").back(), 'M');
  EXPECT_GE(std::stoi(defaults.at("--mem")), 256);
  EXPECT_EQ(defaults.count("--partition"), 0u);
}

// The Slurm path where no Slurm runs: each task's command line by hand with its
// SLURM_ARRAY_TASK_ID. A gather before every task ended lists the missing runs and says so in
// its exit status; once all ended it gives the local summary.
TEST(BatchEmit, TasksRunByHandThenGatheredGiveTheLocalSummary) {
  const fs::path dir = fresh("by_hand");
  ASSERT_EQ(run_sedem("batch " + kDemo + " --out " + dir.string() + kTiny + " --emit slurm").status,
            0);
  // Nothing ran: the plan and the tasks only.
  EXPECT_FALSE(fs::exists(dir / seed_folder(1)));
  for (int k = 0; k < kSeeds - 2; ++k) {
    const auto r = run_task_by_hand(dir, k);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("task " + std::to_string(k) + " of job 1: run " + seed_folder(k + 1)),
              std::string::npos)
        << r.output;
  }
  auto r = run_sedem("batch --gather " + dir.string() + " --quiet");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("2 of 10 runs did not complete"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(seed_folder(9) + ": missing"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(seed_folder(10) + ": missing"), std::string::npos) << r.output;
  const auto partial = read_rows(dir / "summary.csv");
  ASSERT_EQ(partial.size(), std::size_t(kSeeds));
  EXPECT_EQ(partial[7].at("status"), "complete");
  EXPECT_EQ(partial[8].at("status"), "missing");
  EXPECT_EQ(partial[9].at("status"), "missing");
  EXPECT_NE(read_text(dir / "index.html").find("2 did not complete"), std::string::npos);

  for (int k = kSeeds - 2; k < kSeeds; ++k) ASSERT_EQ(run_task_by_hand(dir, k).status, 0);
  // A task run again leaves its complete run as it is.
  const std::string record = read_text(dir / seed_folder(1) / "run.json");
  r = run_task_by_hand(dir, 0);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("holds a complete run"), std::string::npos) << r.output;
  EXPECT_EQ(read_text(dir / seed_folder(1) / "run.json"), record);

  r = run_sedem("batch --gather " + dir.string() + " --quiet");
  EXPECT_EQ(r.status, 0) << r.output;
  expect_local_summary(dir);
  // Emitting again over the finished runs keeps them, and says so.
  r = run_sedem("batch " + kDemo + " --out " + dir.string() + kTiny + " --emit slurm");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("10 of the 10 run folders hold a run already"), std::string::npos)
      << r.output;
  EXPECT_EQ(read_text(dir / seed_folder(1) / "run.json"), record);
}

TEST(BatchEmit, RefusesWhatCannotBecomeTasks) {
  const fs::path dir = fresh("refused");
  const std::string batch = "batch " + kDemo + " --out " + dir.string() + kTiny;
  auto r = run_sedem(batch + " --emit slurm --slurm-time 3h");
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("--slurm-time 3h is not a Slurm time limit"), std::string::npos)
      << r.output;
  r = run_sedem(batch + " --emit slurm --slurm-mem 4Q");
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("--slurm-mem 4Q is not a memory size"), std::string::npos) << r.output;
  r = run_sedem(batch + " --emit slurm --jobs 2");
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("--slurm-cpus"), std::string::npos) << r.output;
  r = run_sedem(batch + " --slurm-time 10");
  EXPECT_EQ(r.status, 1) << r.output;
  r = run_sedem(batch + " --emit parallel --slurm-mem 2G");
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("go with --emit slurm"), std::string::npos) << r.output;
  r = run_sedem(batch + " --emit pbs");
  EXPECT_EQ(r.status, 1) << r.output;
  // A scene that cannot run stops the whole batch before anything is written.
  r = run_sedem(batch + " --emit parallel --set fluid.viscosity=-1");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("fluid.viscosity"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir));
  // A folder with no plan is not a batch to gather.
  fs::create_directories(dir);
  r = run_sedem("batch --gather " + dir.string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("batch.json: cannot read it"), std::string::npos) << r.output;
  r = run_sedem("batch " + kDemo + " --gather " + dir.string());
  EXPECT_EQ(r.status, 1) << r.output;
  r = run_sedem("batch --gather " + dir.string() + " --seeds 3");
  EXPECT_EQ(r.status, 1) << r.output;
}

bool have(const std::string& program) {
  return run_command("command -v " + program + " >/dev/null").status == 0;
}

// GNU parallel on this machine, two at once, through the emitted parallel.sh from another
// folder.
TEST(BatchEmit, GnuParallelGivesTheLocalSummary) {
  if (!have("parallel")) GTEST_SKIP() << "no GNU parallel (apt-get install parallel)";
  const fs::path dir = fresh("parallel");
  ASSERT_EQ(
      run_sedem("batch " + kDemo + " --out " + dir.string() + kTiny + " --emit parallel --jobs 2")
          .status,
      0);
  EXPECT_EQ(lines_of(dir / "parallel.txt").size(), std::size_t(kSeeds));
  const auto r = run_command("cd / && " + (dir / "parallel.sh").string());
  ASSERT_EQ(r.status, 0) << r.output;
  // parallel's job log: every line ran, and ended well.
  const auto joblog = lines_of(dir / "tasks/parallel.joblog");
  ASSERT_EQ(joblog.size(), std::size_t(kSeeds) + 1);
  for (std::size_t i = 1; i < joblog.size(); ++i) {
    // Seq, Host, Starttime, JobRuntime, Send, Receive, Exitval, Signal, Command
    std::vector<std::string> cells;
    std::istringstream line(joblog[i]);
    for (std::string c; std::getline(line, c, '\t');) cells.push_back(c);
    ASSERT_GE(cells.size(), 9u) << joblog[i];
    EXPECT_EQ(cells[6], "0") << joblog[i];
    EXPECT_EQ(cells[7], "0") << joblog[i];
  }
  EXPECT_NE(read_text(dir / "tasks/logs" / (seed_folder(3) + ".log")).find("sedem: done"),
            std::string::npos);
  expect_local_summary(dir);
}

// Over --sshlogin: two "machines" that fake_ssh.sh stands for (each command from / in a bare
// environment, as ssh gives it), so the lines must name everything they need.
TEST(BatchEmit, GnuParallelOverSshloginGivesTheLocalSummary) {
  if (!have("parallel")) GTEST_SKIP() << "no GNU parallel (apt-get install parallel)";
  const fs::path dir = fresh("sshlogin");
  ASSERT_EQ(
      run_sedem("batch " + kDemo + " --out " + dir.string() + kTiny + " --emit parallel").status,
      0);
  const fs::path hosts = kOut / "sshlogin_hosts.txt";
  fs::remove(hosts);
  const auto r =
      run_command("FAKE_SSH_LOG=" + hosts.string() + " " + (dir / "parallel.sh").string() +
                  " --ssh " + kScripts + "fake_ssh.sh --sshlogin 1/nodeA,1/nodeB");
  ASSERT_EQ(r.status, 0) << r.output;
  std::set<std::string> seen;
  for (const auto& host : lines_of(hosts)) seen.insert(host);
  EXPECT_EQ(seen, (std::set<std::string>{"nodeA", "nodeB"}));
  expect_local_summary(dir);
}

// A free TCP port on this machine (bound, read, released).
int free_port() {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t size = sizeof address;
  if (::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 ||
      ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &size) != 0) {
    ::close(fd);
    return 0;
  }
  ::close(fd);
  return ntohs(address.sin_port);
}

// munged, slurmctld and slurmd from `dir`, stopped by their pid files however the test ends.
struct SingleNodeSlurm {
  fs::path dir;
  test::CommandResult started;
  explicit SingleNodeSlurm(fs::path where) : dir(std::move(where)) {
    started = run_command(kScripts + "single_node_slurm.sh start " + dir.string() + " " +
                          std::to_string(free_port()) + " " + std::to_string(free_port()));
    ::setenv("SLURM_CONF", (dir / "slurm.conf").c_str(), 1);
  }
  ~SingleNodeSlurm() { run_command(kScripts + "single_node_slurm.sh stop " + dir.string()); }
};

// Whether any of the jobs is still in Slurm's queue.
bool queued(const std::string& jobs) {
  const auto r = run_command("squeue -h -j " + jobs);
  return r.status == 0 && !r.output.empty();
}

// The real thing: a Slurm of one node, the batch submitted with submit.sh (the array, then
// the gather as a job that waits for it), its summary the local one.
TEST(BatchEmit, ASingleNodeSlurmGivesTheLocalSummary) {
  local_batch();  // before the cluster takes the cores
  const fs::path dir = fresh("slurm");
  ASSERT_EQ(run_sedem("batch " + kDemo + " --out " + dir.string() + kTiny + " --emit slurm").status,
            0);
  SingleNodeSlurm slurm(kOut / "slurm_cluster");
  if (slurm.started.status == 77) GTEST_SKIP() << slurm.started.output;
  ASSERT_EQ(slurm.started.status, 0) << slurm.started.output;

  const auto submitted = run_command((dir / "submit.sh").string());
  ASSERT_EQ(submitted.status, 0) << submitted.output;
  std::istringstream ids(read_text(dir / "tasks/submitted"));
  std::string array, gather;
  ids >> array >> gather;
  ASSERT_FALSE(gather.empty()) << submitted.output;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(5);
  while (queued(array + "," + gather) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
  ASSERT_FALSE(queued(array + "," + gather)) << "the jobs did not end within 5 minutes";

  // One output file per task, and the gather's.
  for (int k = 0; k < kSeeds; ++k)
    EXPECT_TRUE(fs::exists(dir / "tasks/logs" / (array + "_" + std::to_string(k) + ".out"))) << k;
  const std::string gathered = read_text(dir / "tasks/logs" / ("gather_" + gather + ".out"));
  EXPECT_NE(gathered.find("10 complete"), std::string::npos) << gathered;
  expect_local_summary(dir);
}

}  // namespace
}  // namespace sedem
