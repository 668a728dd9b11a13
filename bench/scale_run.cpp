#include "bench/scale_run.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <fstream>
#include <map>
#include <sstream>

#include "bench/bench_support.h"
#include "core/run/simulation.h"
#include "core/run/stage_setups.h"
#include "core/sample/sample_builder.h"
#include "core/scene/scene_loader.h"
#include "render/plot.h"

namespace sedem::bench {

namespace fs = std::filesystem;

namespace {

// A field of /proc/self/status in bytes ("VmHWM:   1234 kB"); 0 when absent.
std::size_t status_bytes(const std::string& field) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind(field + ":", 0) == 0)
      return std::size_t(std::stoull(line.substr(field.size() + 1))) * 1024;
  return 0;
}

// CPU time of the process so far, user and system, s.
double cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  auto s = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
  return s(usage.ru_utime) + s(usage.ru_stime);
}

// Resets the process's peak resident memory (VmHWM) to its current value. False when the
// kernel does not allow it.
bool reset_peak_rss() {
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
  clear.flush();
  return bool(clear);
}

std::string format_count(double n) {
  char s[32];
  std::snprintf(s, sizeof s, "%.0f", n);
  return s;
}

void print_header(std::FILE* table) {
  std::fprintf(table, "%-10s %-10s %9s %9s %10s %11s %9s %10s %8s %8s %8s %8s %10s\n", "label",
               "sample", "particles", "wall_s", "steps", "p-steps/s", "sim_s", "merit", "eng_B/p",
               "rss_MB", "hyd_pp", "sph_pp", "pip_pp");
  std::fflush(table);
}

void print_row(std::FILE* table, const ScaleRow& r) {
  if (r.status != "ok") {
    std::fprintf(table, "%-10s %-10s %9s failed: %s\n", r.label.c_str(), r.sample.c_str(),
                 format_count(r.requested).c_str(), r.message.c_str());
  } else {
    std::fprintf(
        table, "%-10s %-10s %9zu %9.1f %10lld %11.3g %9.0f %10.3g %8.0f %8.1f %8.3f %8.3f %10.3f\n",
        r.label.c_str(), r.sample.c_str(), r.particles, r.wall_s, static_cast<long long>(r.steps),
        r.particle_steps / std::max(r.wall_s, 1e-9), r.simulated_s, r.merit(),
        double(r.engine_peak_bytes) / double(std::max<std::size_t>(r.particles, 1)),
        double(r.rss_peak_bytes) / 1e6, r.error_hydrometer, r.error_buoyancy, r.error_pipette);
  }
  std::fflush(table);
}

// A CSV field: quoted when it holds a comma or a quote.
std::string field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  return q + "\"";
}

std::string join(const std::vector<std::string>& parts) {
  std::string s;
  for (const auto& p : parts) s += (s.empty() ? "" : " ") + p;
  return s;
}

}  // namespace

double ScaleRow::merit() const {
  return wall_s > 0 ? double(particles) * simulated_s / wall_s : 0.0;
}

std::vector<ScaleRow> run_scale_bench(const ScaleOptions& options, std::FILE* table) {
  std::vector<std::string> sets = no_output_keys();
  sets.insert(sets.end(), options.sets.begin(), options.sets.end());
  if (options.end_time_s) sets.push_back("run.end_time_s=" + std::to_string(*options.end_time_s));
  if (options.threads > 0) sets.push_back("integrator.threads=" + std::to_string(options.threads));

  fs::create_directories(options.out);
  const fs::path csv = options.out / "bench_scale.csv";
  if (table) print_header(table);
  std::vector<ScaleRow> rows;
  for (const auto& file : options.scenes) {
    for (double count : options.counts) {
      std::vector<std::string> overrides = sets;
      overrides.push_back("sample.simulated_count=" + format_count(count));
      ScaleRow r;
      r.label = options.label;
      r.sets = join(options.sets);
      r.requested = count;
      r.sample = fs::path(file).stem().string();
      r.rss_peak_per_run = reset_peak_rss();
      r.rss_start_bytes = status_bytes("VmRSS");
      const double cpu_start = cpu_seconds();
      try {
        const Scene scene = load_scene(file, overrides);
        r.sample = scene.name;
        r.end_time_s = scene.end_time;
        const auto start = std::chrono::steady_clock::now();
        Sample sample = build_sample(sample_setup(scene));
        r.sample_build_s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const SimulationRun run = simulate(scene, std::move(sample));
        r.wall_s = run.wall_seconds;
        r.particles = run.particles;
        r.threads = run.threads;
        r.simulated_s = run.simulated_seconds;
        r.steps = run.stats.steps;
        r.list_builds = run.stats.list_builds;
        r.particle_steps = run.stats.particle_steps;
        r.engine_peak_bytes = run.peak_engine_bytes;
        r.error_hydrometer = test_error(run.results, "hydrometer");
        r.error_buoyancy = test_error(run.results, "buoyancy");
        r.error_pipette = test_error(run.results, "pipette");
      } catch (const std::exception& e) {
        r.status = "failed";
        r.message = e.what();
      }
      r.cpu_s = cpu_seconds() - cpu_start;
      r.rss_peak_bytes = status_bytes("VmHWM");
      rows.push_back(r);
      if (table) print_row(table, r);
      write_scale_csv(rows, csv);
    }
  }
  if (options.plot && !rows.empty()) plot_scale(rows, options.out / "bench_scale_plot");
  return rows;
}

void write_scale_csv(const std::vector<ScaleRow>& rows, const fs::path& file) {
  std::ofstream out(file);
  out.precision(10);
  out << "label,sample,status,requested_count,particles,threads,end_time_s,simulated_s,wall_s,"
         "sample_build_s,cpu_s,steps,particle_steps,particle_steps_per_s,list_builds,engine_peak_"
         "bytes,"
         "engine_bytes_per_particle,process_rss_start_bytes,process_peak_rss_bytes,"
         "process_peak_rss_per_run,error_hydrometer_pp,error_buoyancy_pp,error_pipette_pp,"
         "merit_particle_s_per_wall_s,sets,message\n";
  for (const auto& r : rows) {
    const double n = double(std::max<std::size_t>(r.particles, 1));
    out << field(r.label) << ',' << field(r.sample) << ',' << r.status << ','
        << format_count(r.requested) << ',' << r.particles << ',' << r.threads << ','
        << r.end_time_s << ',' << r.simulated_s << ',' << r.wall_s << ',' << r.sample_build_s << ','
        << r.cpu_s << ',' << r.steps << ',' << r.particle_steps << ','
        << r.particle_steps / std::max(r.wall_s, 1e-9) << ',' << r.list_builds << ','
        << r.engine_peak_bytes << ',' << double(r.engine_peak_bytes) / n << ',' << r.rss_start_bytes
        << ',' << r.rss_peak_bytes << ',' << (r.rss_peak_per_run ? 1 : 0) << ','
        << r.error_hydrometer << ',' << r.error_buoyancy << ',' << r.error_pipette << ','
        << r.merit() << ',' << field(r.sets) << ',' << field(r.message) << '\n';
  }
  if (!out.flush()) throw std::runtime_error("cannot write " + file.string());
}

void plot_scale(const std::vector<ScaleRow>& rows, const fs::path& base) {
  render::Figure fig;
  fig.title = "Whole test against particle count";
  // Wall time, every sample (and label) on one panel.
  render::Plot wall;
  wall.title = "wall time";
  wall.x = render::axis("particles", "", true);
  wall.y = render::axis("wall time", "s", true);
  std::map<std::string, render::PlotSeries> by_sample;
  std::map<std::string, std::vector<const ScaleRow*>> per_sample;
  for (const auto& r : rows) {
    if (r.status != "ok") continue;
    const std::string name = r.label.empty() ? r.sample : r.label + " " + r.sample;
    auto& s = by_sample[name];
    s.name = name;
    s.style = render::SeriesStyle::line_and_points;
    s.x.push_back(double(r.particles));
    s.y.push_back(std::max(r.wall_s, 1e-3));
    per_sample[r.sample].push_back(&r);
  }
  for (auto& [name, s] : by_sample) wall.series.push_back(s);
  fig.panels.push_back(wall);
  // Each sample's errors against the reference.
  for (const auto& [sample, list] : per_sample) {
    render::Plot p;
    p.title = sample + ": error against the reference";
    p.x = render::axis("particles", "", true);
    p.y = render::axis("error", "pp", true);
    const std::pair<const char*, double ScaleRow::*> tests[] = {
        {"hydrometer", &ScaleRow::error_hydrometer},
        {"buoyancy", &ScaleRow::error_buoyancy},
        {"pipette", &ScaleRow::error_pipette}};
    for (const auto& [test, member] : tests) {
      for (const auto* r : list) {
        if (!std::isfinite(r->*member)) continue;
        const std::string name = r->label.empty() ? test : r->label + " " + test;
        auto it = std::find_if(p.series.begin(), p.series.end(),
                               [&](const render::PlotSeries& s) { return s.name == name; });
        if (it == p.series.end()) {
          p.series.emplace_back(name, std::vector<double>{}, std::vector<double>{},
                                render::SeriesStyle::line_and_points);
          it = p.series.end() - 1;
        }
        it->x.push_back(double(r->particles));
        it->y.push_back(std::max(r->*member, 1e-3));
      }
    }
    fig.panels.push_back(p);
  }
  fig.columns = std::min<int>(3, int(fig.panels.size()));
  render::write_figure(fig, base);
}

}  // namespace sedem::bench
