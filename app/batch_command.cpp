#include "app/batch_command.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>
#include <thread>

#include "app/exit_codes.h"
#include "app/run_command.h"
#include "app/run_folder.h"
#include "app/stop_signals.h"
#include "render/plot.h"

extern char** environ;

namespace sedem::app {
namespace fs = std::filesystem;

namespace {

const std::vector<std::string> kTests{"hydrometer", "buoyancy", "pipette"};

nlohmann::json read_record(const fs::path& dir) {
  std::ifstream in(dir / "run.json");
  if (!in) return nullptr;
  auto j = nlohmann::json::parse(in, nullptr, false);
  return j.is_discarded() ? nullptr : j;
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + '"';
}

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

bool has_override(const std::vector<std::string>& overrides, const std::string& key) {
  return std::any_of(overrides.begin(), overrides.end(),
                     [&](const std::string& o) { return o.rfind(key + "=", 0) == 0; });
}

// Each test's error against the swept value, one series per test. Values that are not
// numbers are placed at 1, 2, 3...
void write_error_figure(const std::vector<BatchRun>& runs, const std::string& key,
                        const fs::path& out_dir) {
  std::vector<double> xs;
  bool numeric = true;
  for (const auto& r : runs) {
    try {
      std::size_t used = 0;
      xs.push_back(std::stod(r.value, &used));
      numeric = numeric && used == r.value.size();
    } catch (const std::exception&) {
      xs.push_back(0);
      numeric = false;
    }
  }
  if (!numeric)
    for (std::size_t i = 0; i < xs.size(); ++i) xs[i] = double(i + 1);
  const bool log =
      numeric && !xs.empty() && *std::min_element(xs.begin(), xs.end()) > 0 &&
      *std::max_element(xs.begin(), xs.end()) >= 10 * *std::min_element(xs.begin(), xs.end());
  render::Plot plot;
  plot.title = "error against " + key;
  plot.x = render::axis(numeric ? key : key + " (run number)", "", log);
  plot.y = render::axis("error", "pp");
  std::set<std::string> scenes;
  for (const auto& r : runs) scenes.insert(fs::path(r.scene).stem().string());
  for (const auto& scene : scenes)
    for (const auto& test : kTests) {
      render::PlotSeries series;
      series.name = scenes.size() > 1 ? scene + " " + test : test;
      series.style = render::SeriesStyle::line_and_points;
      for (std::size_t i = 0; i < runs.size(); ++i) {
        if (fs::path(runs[i].scene).stem().string() != scene) continue;
        const auto record = read_record(out_dir / runs[i].folder);
        if (record.is_null() || !record.contains("results") || !record["results"].contains(test))
          continue;
        series.x.push_back(xs[i]);
        series.y.push_back(record["results"][test].value("error_pp", 0.0));
      }
      if (!series.x.empty()) plot.series.push_back(std::move(series));
    }
  if (plot.series.empty()) return;
  render::write_figure(render::single_plot(plot), out_dir / "summary_error");
}

// The runs, `jobs` at a time, each a `sedem run` process of its own with 1/jobs of the cores.
int run_in_processes(const std::vector<BatchRun>& runs, const BatchOptions& options) {
  const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
  const int share = std::max(1, cores / options.jobs);
  install_stop_handlers();
  int worst = exit_code::ok;
  std::map<pid_t, std::size_t> running;
  std::size_t next = 0, finished = 0;
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
    int raw = 0;
    const pid_t pid = ::waitpid(-1, &raw, 0);
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
  std::set<std::string> used;
  for (const auto& scene : options.scenes) {
    // Two scene files with one stem (a/demo.toml, b/demo.toml): demo, demo_2, ...
    std::string stem = safe_folder_name(fs::path(scene).stem().string());
    for (int k = 2; used.count(stem); ++k)
      stem = safe_folder_name(fs::path(scene).stem().string()) + "_" + std::to_string(k);
    used.insert(stem);
    for (const auto& variant : variants) {
      BatchRun run;
      run.scene = scene;
      run.overrides = options.overrides;
      run.folder = stem;
      if (!variant.empty()) {
        run.overrides.push_back(variant);
        run.value = variant.substr(variant.find('=') + 1);
        // Two values may give one folder name once made safe ("a/b" and "a_b").
        const std::string base = safe_folder_name(stem + "__" + variant);
        run.folder = base;
        for (int k = 2; used.count(run.folder); ++k) run.folder = base + "_" + std::to_string(k);
        used.insert(run.folder);
      }
      runs.push_back(std::move(run));
    }
  }
  return runs;
}

void write_summary_csv(const std::vector<BatchRun>& runs, const std::string& sweep_key,
                       const fs::path& out_dir) {
  std::ofstream out(out_dir / "summary.csv");
  out << "run,scene";
  if (!sweep_key.empty()) out << ',' << csv_field(sweep_key);
  for (const auto& t : kTests) out << ',' << t << "_error_pp," << t << "_bias_pp";
  out << ",wall_time_s,particle_count,status\n";
  for (const auto& r : runs) {
    const auto record = read_record(out_dir / r.folder);
    out << csv_field(r.folder) << ',' << csv_field(r.scene);
    if (!sweep_key.empty()) out << ',' << csv_field(r.value);
    for (const auto& t : kTests) {
      if (!record.is_null() && record.contains("results") && record["results"].contains(t))
        out << ',' << number(record["results"][t].value("error_pp", 0.0)) << ','
            << number(record["results"][t].value("bias_pp", 0.0));
      else
        out << ",,";
    }
    if (record.is_null())
      out << ",,,missing\n";
    else
      out << ',' << number(record.value("wall_time_s", 0.0)) << ','
          << record.value("particle_count", 0) << ',' << record.value("status", "") << '\n';
  }
  out.flush();
  if (!out) throw std::runtime_error("cannot write " + (out_dir / "summary.csv").string());
}

int batch(const BatchOptions& options) {
  std::vector<BatchRun> runs;
  try {
    runs = plan_batch(options);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "sedem: %s\n", e.what());
    return exit_code::usage;
  }
  int worst = exit_code::ok;
  if (options.jobs > 1) {
    worst = run_in_processes(runs, options);
  } else {
    for (const auto& r : runs) {
      RunOptions run_options;
      run_options.scene = r.scene;
      run_options.quiet = options.quiet;
      run_options.overwrite = options.overwrite;
      run_options.overrides = r.overrides;
      run_options.out_dir = (fs::path(options.out_dir) / r.folder).string();
      const int status = run(run_options);
      if (status != exit_code::ok) worst = status;
      if (stop_requested()) {
        worst = exit_code::interrupted;
        break;
      }
    }
  }
  const std::string key =
      options.sweep.empty() ? std::string() : options.sweep.substr(0, options.sweep.find('='));
  try {
    fs::create_directories(options.out_dir);
    write_summary_csv(runs, key, options.out_dir);
    if (!key.empty()) write_error_figure(runs, key, options.out_dir);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sedem: the batch summary could not be written: %s\n", e.what());
    if (worst == exit_code::ok) worst = exit_code::io_failure;
  }
  if (!options.quiet)
    std::printf("sedem: batch of %zu runs: %s\n", runs.size(),
                (fs::path(options.out_dir) / "summary.csv").c_str());
  return worst;
}

}  // namespace sedem::app
