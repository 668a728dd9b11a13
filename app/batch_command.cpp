#include "app/batch_command.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <thread>

#include "app/batch_emit.h"
#include "app/batch_outputs.h"
#include "app/exit_codes.h"
#include "app/run_command.h"
#include "app/run_folder.h"
#include "app/stop_signals.h"

extern char** environ;

namespace sedem::app {
namespace fs = std::filesystem;

namespace {

// A bound on a batch that a typo (--seeds 1000000) would make run for days.
constexpr int kMostSeeds = 10000;

bool has_override(const std::vector<std::string>& overrides, const std::string& key) {
  return std::any_of(overrides.begin(), overrides.end(),
                     [&](const std::string& o) { return o.rfind(key + "=", 0) == 0; });
}

// The runs, `jobs` at a time, each a `sedem run` process of its own with 1/jobs of the cores.
int run_in_processes(const std::vector<BatchRun>& runs, const BatchOptions& options) {
  const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
  const int share = std::max(1, cores / options.jobs);
  install_stop_handlers();
  int worst = exit_code::ok;
  std::map<pid_t, std::size_t> running;
  std::size_t next = 0, finished = 0;
  bool passed_on = false;
  auto report = [&](std::size_t i, int status) {
    ++finished;
    if (status != exit_code::ok) worst = status;
    if (!options.quiet || status != exit_code::ok)
      std::fprintf(
          stderr, "sedem: [%zu/%zu] %s %s\n", finished, runs.size(), runs[i].folder.c_str(),
          status == exit_code::ok ? "done"
                                  : ("ended with status " + std::to_string(status)).c_str());
  };
  while (next < runs.size() || !running.empty()) {
    while (next < runs.size() && int(running.size()) < options.jobs && !stop_requested()) {
      const BatchRun& r = runs[next];
      std::vector<std::string> args{"/proc/self/exe",
                                    "run",
                                    r.scene,
                                    "--out",
                                    (fs::path(options.out_dir) / r.folder).string(),
                                    "--quiet"};
      if (options.overwrite) args.push_back("--overwrite");
      std::vector<std::string> sets = r.overrides;
      if (!has_override(sets, "integrator.threads"))
        sets.push_back("integrator.threads=" + std::to_string(share));
      for (const auto& s : sets) {
        args.push_back("--set");
        args.push_back(s);
      }
      std::vector<char*> argv;
      for (auto& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      pid_t pid = 0;
      if (posix_spawn(&pid, "/proc/self/exe", nullptr, nullptr, argv.data(), environ) != 0) {
        std::fprintf(stderr, "sedem: cannot start the run %s: %s\n", r.folder.c_str(),
                     std::strerror(errno));
        report(next++, exit_code::engine_failure);
        continue;
      }
      running[pid] = next++;
    }
    if (running.empty()) break;
    // A stop asked of the batch is passed on to its runs, once, as SIGTERM (which a run takes
    // any number of times; a second SIGINT would kill the runs a terminal's Ctrl-C already
    // reached): each stops cleanly with its checkpoint, and the summary lists what finished.
    if (stop_requested() && !passed_on) {
      for (const auto& [child, index] : running) ::kill(child, SIGTERM);
      passed_on = true;
    }
    int raw = 0;
    const pid_t pid = ::waitpid(-1, &raw, WNOHANG);
    if (pid == 0) {  // none ended yet: look again for a stop in a moment
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
      continue;
    }
    if (pid < 0) {
      if (errno == EINTR) continue;
      break;
    }
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    const int status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
    report(it->second, status);
    running.erase(it);
  }
  if (stop_requested()) return exit_code::interrupted;
  return worst;
}

// The runs one after another in this process.
int run_in_turn(const std::vector<BatchRun>& runs, const BatchOptions& options) {
  int worst = exit_code::ok;
  for (const auto& r : runs) {
    RunOptions run_options;
    run_options.scene = r.scene;
    run_options.quiet = options.quiet;
    run_options.overwrite = options.overwrite;
    run_options.overrides = r.overrides;
    run_options.out_dir = (fs::path(options.out_dir) / r.folder).string();
    const int status = run(run_options);
    if (status != exit_code::ok) worst = status;
    if (stop_requested()) return exit_code::interrupted;
  }
  return worst;
}

// `name` made one safe path component, with "_2", "_3"... until no other run has it.
std::string unique_folder(const std::string& name, std::set<std::string>& used) {
  const std::string base = safe_folder_name(name);
  std::string folder = base;
  for (int k = 2; used.count(folder); ++k) folder = base + "_" + std::to_string(k);
  used.insert(folder);
  return folder;
}

}  // namespace

std::vector<std::string> expand_sweep(const std::string& sweep) {
  const auto eq = sweep.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == sweep.size())
    throw std::invalid_argument("--sweep " + sweep + ": expected key=v1,v2,...");
  const std::string key = sweep.substr(0, eq);
  std::vector<std::string> sets;
  std::size_t start = eq + 1;
  while (start <= sweep.size()) {
    auto comma = sweep.find(',', start);
    if (comma == std::string::npos) comma = sweep.size();
    const std::string value = sweep.substr(start, comma - start);
    if (value.empty()) throw std::invalid_argument("--sweep " + sweep + ": an empty value");
    sets.push_back(key + "=" + value);
    start = comma + 1;
  }
  return sets;
}

std::vector<BatchRun> plan_batch(const BatchOptions& options) {
  std::vector<std::string> variants{""};
  if (!options.sweep.empty()) variants = expand_sweep(options.sweep);
  std::vector<BatchRun> runs;
  std::set<std::string> used{kBatchTasksFolder};
  for (const auto& scene : options.scenes) {
    // Two scene files with one stem (a/demo.toml, b/demo.toml): demo, demo_2, ...
    const std::string stem = unique_folder(fs::path(scene).stem().string(), used);
    for (const auto& variant : variants) {
      BatchRun run;
      run.scene = scene;
      run.overrides = options.overrides;
      run.group = stem;
      if (!variant.empty()) {
        run.overrides.push_back(variant);
        run.value = variant.substr(variant.find('=') + 1);
        // Two values may give one folder name once made safe ("a/b" and "a_b").
        run.group = unique_folder(stem + "__" + variant, used);
      }
      run.folder = run.group;
      if (!options.seeds) {
        runs.push_back(std::move(run));
        continue;
      }
      for (int k = 0; k < *options.seeds; ++k) {
        BatchRun seeded = run;
        seeded.seed = options.seed0.value_or(1) + k;
        seeded.overrides.push_back("sample.seed=" + std::to_string(*seeded.seed));
        seeded.folder = unique_folder(run.group + "__seed=" + std::to_string(*seeded.seed), used);
        runs.push_back(std::move(seeded));
      }
    }
  }
  return runs;
}

std::string seed_options_error(const BatchOptions& options) {
  if (!options.seeds) return options.seed0 ? "--seed0 needs --seeds N" : "";
  const int n = *options.seeds;
  if (n < 1 || n > kMostSeeds)
    return "--seeds " + std::to_string(n) + " is out of range; allowed: [1, " +
           std::to_string(kMostSeeds) + "]";
  const std::int64_t last = std::numeric_limits<std::int64_t>::max() - (n - 1);
  const std::int64_t seed0 = options.seed0.value_or(1);
  if (seed0 < 0 || seed0 > last)
    return "--seed0 " + std::to_string(seed0) + " is out of range with --seeds " +
           std::to_string(n) + "; allowed: [0, " + std::to_string(last) + "]";
  // The seed is the one thing that differs between the runs of a group.
  for (const auto& o : options.overrides)
    if (o.rfind("sample.seed=", 0) == 0)
      return "--set " + o + " cannot go with --seeds, which sets sample.seed (give --seed0)";
  if (options.sweep.rfind("sample.seed=", 0) == 0)
    return "--sweep " + options.sweep +
           " cannot go with --seeds, which sets sample.seed (give --seed0)";
  return "";
}

int batch(const BatchOptions& options) {
  if (const std::string error = seed_options_error(options); !error.empty()) {
    std::fprintf(stderr, "sedem: %s\n", error.c_str());
    return exit_code::invalid_scene;
  }
  std::vector<BatchRun> runs;
  try {
    runs = plan_batch(options);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "sedem: %s\n", e.what());
    return exit_code::usage;
  }
  if (!options.scheduler.empty()) return emit_batch(options, runs);
  int worst = options.jobs > 1 ? run_in_processes(runs, options) : run_in_turn(runs, options);
  try {
    fs::create_directories(options.out_dir);
    write_batch_outputs(runs, options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sedem: the batch summary could not be written: %s\n", e.what());
    if (worst == exit_code::ok) worst = exit_code::io_failure;
  }
  if (!options.quiet)
    std::printf("sedem: batch of %zu runs: %s, %s\n", runs.size(),
                (fs::path(options.out_dir) / "summary.csv").c_str(),
                (fs::path(options.out_dir) / "index.html").c_str());
  return worst;
}

}  // namespace sedem::app
