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
#include "core/model/engine_stats.h"
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

// A time as short as it reads exactly enough (18, 0.5, 1440).
std::string format_time(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", s);
  return text;
}

// Watches every engine step of a run: wall time, steps, and the sums of members and contacts,
// closing a span at the first step that reaches its time.
class SpanTally {
 public:
  SpanTally() : start_(std::chrono::steady_clock::now()) {
    for (const double t : kScaleSpanEnds) spans_.push_back({t});
  }

  void after_step(double time, const EngineStats& stats) {
    ++steps_;
    members_ += double(stats.members);
    contacts_ += double(stats.contacts);
    pushed_ += double(stats.pushed);
    unpushed_steps_ += stats.unpushed_step > 0 ? stats.last_step / stats.unpushed_step : 1.0;
    fast_ += double(stats.fast_set);
    substeps_ += double(stats.substeps);
    split_steps_ += stats.substeps > 0;
    if (stats.own_step_share > 0) {  // a look, weighed by the members at the step's end
      own_share_ += stats.own_step_share * double(stats.members);
      largest_cluster_ += stats.largest_cluster * double(stats.members);
      own_members_ += double(stats.members);
    }
    while (next_ < spans_.size() && time >= spans_[next_].until_s) close(spans_[next_++], true);
  }

  // The spans, the last the whole run to `end_s` in `wall_s` (the run's own measure); those
  // the run did not reach stop at its end.
  std::vector<ScaleSpan> finish(double end_s, double wall_s) {
    for (; next_ < spans_.size(); ++next_) close(spans_[next_], false);
    spans_.push_back({end_s});
    close(spans_.back(), true);
    spans_.back().wall_s = wall_s;
    return spans_;
  }

 private:
  void close(ScaleSpan& span, bool reached) const {
    span.reached = reached;
    span.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    span.steps = steps_;
    span.members = steps_ > 0 ? members_ / double(steps_) : 0;
    span.contacts = steps_ > 0 ? contacts_ / double(steps_) : 0;
    span.pushed = steps_ > 0 ? pushed_ / double(steps_) : 0;
    span.unpushed_steps = unpushed_steps_;
    span.fast = steps_ > 0 ? fast_ / double(steps_) : 0;
    span.substeps = split_steps_ > 0 ? substeps_ / double(split_steps_) : 0;
    span.own_share = own_members_ > 0 ? own_share_ / own_members_ : 0;
    span.largest_cluster = own_members_ > 0 ? largest_cluster_ / own_members_ : 0;
  }

  std::chrono::steady_clock::time_point start_;
  std::vector<ScaleSpan> spans_;
  std::size_t next_ = 0;
  std::int64_t steps_ = 0;
  double members_ = 0, contacts_ = 0, pushed_ = 0, unpushed_steps_ = 0;
  double fast_ = 0, substeps_ = 0;
  std::int64_t split_steps_ = 0;
  double own_share_ = 0, largest_cluster_ = 0, own_members_ = 0;
};

// A span's wall time for the table: "-" where the run did not get that far.
std::string span_wall(const ScaleRow& r, std::size_t k) {
  if (k >= r.spans.size() || !r.spans[k].reached) return "-";
  char s[32];
  std::snprintf(s, sizeof s, "%.1f", r.spans[k].wall_s);
  return s;
}

// The first minute's steps over those the members not pushed would have needed: what stepping
// the pushed grains apart could save there ("-" where the run did not get that far).
std::string first_minute_push_ratio(const ScaleRow& r) {
  if (r.spans.empty() || !r.spans[0].reached || r.spans[0].unpushed_steps <= 0) return "-";
  char s[32];
  std::snprintf(s, sizeof s, "%.1f", double(r.spans[0].steps) / r.spans[0].unpushed_steps);
  return s;
}

// The first minute's members' particle-steps over those clusters of members on steps of their
// own would have taken ("-" where the run did not get that far or never looked).
std::string first_minute_own_ratio(const ScaleRow& r) {
  if (r.spans.empty() || !r.spans[0].reached || r.spans[0].own_share <= 0) return "-";
  char s[32];
  std::snprintf(s, sizeof s, "%.1f", 1.0 / r.spans[0].own_share);
  return s;
}

// Two values of every span, to 60 s and 600 s and then to the end (the last without a suffix):
// a group of columns written after the older ones, so that rows of older builds line up.
void span_pair_header(std::ostream& out, const std::string& first, const std::string& second) {
  for (const double until : kScaleSpanEnds) {
    const std::string name = format_count(until);
    out << ',' << first << "_to_" << name << ',' << second << "_to_" << name;
  }
  out << ',' << first << ',' << second;
}
void span_pair(std::ostream& out, const ScaleRow& r, double ScaleSpan::*first,
               double ScaleSpan::*second) {
  for (std::size_t k = 0; k < std::size(kScaleSpanEnds); ++k) {
    if (k + 1 < r.spans.size() && r.spans[k].reached)
      out << ',' << r.spans[k].*first << ',' << r.spans[k].*second;
    else
      out << ",,";  // a span the run did not reach, or a failed run
  }
  if (r.spans.empty())
    out << ",,";
  else
    out << ',' << r.spans.back().*first << ',' << r.spans.back().*second;
}

void print_header(std::FILE* table) {
  std::fprintf(table,
               "%-10s %-10s %9s %9s %8s %8s %10s %11s %9s %10s %8s %8s %8s %8s %10s %9s %9s %9s "
               "%8s\n",
               "label", "sample", "particles", "wall_s", "to60_s", "to600_s", "steps", "p-steps/s",
               "sim_s", "merit", "eng_B/p", "rss_MB", "hyd_pp", "sph_pp", "pip_pp", "members",
               "contacts", "push_x60", "own_x60");
  std::fflush(table);
}

void print_row(std::FILE* table, const ScaleRow& r) {
  if (r.status != "ok") {
    std::fprintf(table, "%-10s %-10s %9s failed: %s\n", r.label.c_str(), r.sample.c_str(),
                 format_count(r.requested).c_str(), r.message.c_str());
  } else {
    // Members and contacts: means per step over the whole run.
    const ScaleSpan whole = r.spans.empty() ? ScaleSpan{} : r.spans.back();
    std::fprintf(
        table,
        "%-10s %-10s %9zu %9.1f %8s %8s %10lld %11.3g %9.0f %10.3g %8.0f %8.1f %8.3f %8.3f "
        "%10.3f %9.1f %9.1f %9s %8s\n",
        r.label.c_str(), r.sample.c_str(), r.particles, r.wall_s, span_wall(r, 0).c_str(),
        span_wall(r, 1).c_str(), static_cast<long long>(r.steps),
        r.particle_steps / std::max(r.wall_s, 1e-9), r.simulated_s, r.merit(),
        double(r.engine_peak_bytes) / double(std::max<std::size_t>(r.particles, 1)),
        double(r.rss_peak_bytes) / 1e6, r.error_hydrometer, r.error_buoyancy, r.error_pipette,
        whole.members, whole.contacts, first_minute_push_ratio(r).c_str(),
        first_minute_own_ratio(r).c_str());
    if (!r.message.empty())
      std::fprintf(table, "%-10s %-10s note: %s\n", "", "", r.message.c_str());
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
        SpanTally tally;
        const SimulationRun run = simulate(
            scene, std::move(sample), false,
            [&](double t, const EngineStats& stats) { tally.after_step(t, stats); },
            options.to_end_time);
        r.spans = tally.finish(run.simulated_seconds, run.wall_seconds);
        r.wall_s = run.wall_seconds;
        r.particles = run.particles;
        r.threads = run.threads;
        r.simulated_s = run.simulated_seconds;
        r.steps = run.stats.steps;
        r.list_builds = run.stats.list_builds;
        r.widened_rows = run.stats.widened_rows;
        r.box_moves = run.stats.box_moves;
        r.particle_steps = run.stats.particle_steps;
        r.engine_peak_bytes = run.peak_engine_bytes;
        r.error_hydrometer = test_error(run.results, "hydrometer");
        r.error_buoyancy = test_error(run.results, "buoyancy");
        r.error_pipette = test_error(run.results, "pipette");
        // With the outputs off nothing needs the engine after the last reading.
        if (r.simulated_s < r.end_time_s)
          r.message =
              "stopped at the last reading before the end time, t = " + format_time(r.simulated_s) +
              " s (" + (r.simulated_s > 0 ? "nothing later is read" : "no reading at all") + ")";
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
         "merit_particle_s_per_wall_s,sets,message";
  // Where the time went, to 60 s, to 600 s and to the end: after the older columns, so that
  // rows of a build without them line up (scripts/compare_engines.sh).
  for (const double until : kScaleSpanEnds) {
    const std::string name = format_count(until);
    out << ",wall_to_" << name << "_s,steps_to_" << name << ",members_per_step_to_" << name
        << ",contacts_per_step_to_" << name;
  }
  out << ",members_per_step,contacts_per_step";
  span_pair_header(out, "pushed_per_step", "unpushed_steps");
  span_pair_header(out, "fast_per_step", "substeps_per_split_step");
  out << ",widened_rows,box_moves";
  span_pair_header(out, "own_step_share", "largest_cluster");
  out << '\n';
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
        << r.merit() << ',' << field(r.sets) << ',' << field(r.message);
    // A span the run did not reach (or a failed run) leaves its cells empty.
    for (std::size_t k = 0; k < std::size(kScaleSpanEnds); ++k) {
      if (k + 1 < r.spans.size() && r.spans[k].reached)
        out << ',' << r.spans[k].wall_s << ',' << r.spans[k].steps << ',' << r.spans[k].members
            << ',' << r.spans[k].contacts;
      else
        out << ",,,,";
    }
    if (r.spans.empty())
      out << ",,";
    else
      out << ',' << r.spans.back().members << ',' << r.spans.back().contacts;
    span_pair(out, r, &ScaleSpan::pushed, &ScaleSpan::unpushed_steps);
    span_pair(out, r, &ScaleSpan::fast, &ScaleSpan::substeps);
    out << ',' << r.widened_rows << ',' << r.box_moves;
    span_pair(out, r, &ScaleSpan::own_share, &ScaleSpan::largest_cluster);
    out << '\n';
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
