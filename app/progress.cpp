#include "app/progress.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace sedem::app {
namespace {

// The rate is measured over the last kWindow seconds of wall time.
constexpr double kWindow = 30.0;

int terminal_columns() {
  winsize w{};
  if (ioctl(STDERR_FILENO, TIOCGWINSZ, &w) == 0 && w.ws_col > 0) return w.ws_col;
  return 80;
}

std::string format(const char* fmt, auto... args) {
  char text[256];
  std::snprintf(text, sizeof text, fmt, args...);
  return text;
}

// One progress line: redrawn in place on a terminal (padded to `width` with spaces, so that no
// character of a longer line before it stays), a line of its own in a log.
void print_line(std::FILE* out, bool tty, int width, const std::string& text) {
  if (tty)
    std::fprintf(out, "\r%-*s", width, text.c_str());
  else
    std::fprintf(out, "%s\n", text.c_str());
  std::fflush(out);
}

}  // namespace

std::string clock_text(double seconds) {
  if (!(seconds >= 0) || seconds > 1e8) return "--:--";
  const long s = long(seconds + 0.5);
  if (s >= 3600) return format("%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  return format("%ld:%02ld", s / 60, s % 60);
}

Progress::Progress(double end_time, bool quiet, double log_interval_s)
    : Progress(end_time, quiet, stderr, isatty(STDERR_FILENO) != 0,
               isatty(STDERR_FILENO) != 0 ? terminal_columns() : 80, log_interval_s) {}

Progress::Progress(double end_time, bool quiet, std::FILE* out, bool tty, int columns,
                   double log_interval_s)
    : end_time_(end_time),
      quiet_(quiet),
      out_(out),
      tty_(tty),
      columns_(std::clamp(columns, 20, 80)),
      log_interval_(log_interval_s),
      start_(std::chrono::steady_clock::now()),
      last_print_(start_) {}

double Progress::wall_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::update(double simulated_time, double particle_steps) {
  if (quiet_) return;
  const auto now = std::chrono::steady_clock::now();
  // The rate's samples are taken more often than a log's lines, so that its first line
  // has an ETA already.
  const double wall = std::chrono::duration<double>(now - start_).count();
  if (samples_.empty() || wall - samples_.back().first >= 0.5) note(wall, simulated_time);
  const double since = std::chrono::duration<double>(now - last_print_).count();
  if (since < (tty_ ? 0.2 : log_interval_)) return;
  last_print_ = now;
  print(simulated_time, particle_steps);
}

double Progress::eta(double wall, double simulated_time) const {
  if (samples_.empty()) return -1;
  const auto& [wall0, sim0] = samples_.front();
  if (wall - wall0 <= 0 || simulated_time <= sim0) return -1;
  const double rate = (simulated_time - sim0) / (wall - wall0);
  return std::max(0.0, end_time_ - simulated_time) / rate;
}

void Progress::note(double wall, double simulated_time) {
  samples_.emplace_back(wall, simulated_time);
  // Keep the samples of the last kWindow seconds, and always two to measure a rate with.
  while (samples_.size() > 2 && wall - samples_[1].first >= kWindow) samples_.pop_front();
}

std::string Progress::line(double wall, double simulated_time, double particle_steps) {
  note(wall, simulated_time);
  const double fraction = end_time_ > 0 ? std::clamp(simulated_time / end_time_, 0.0, 1.0) : 1.0;
  const double rate = wall > 0 ? particle_steps / wall : 0;
  const std::string eta_text = clock_text(eta(wall, simulated_time));
  if (!tty_)
    return format("t = %.1f of %.1f s (%.0f%%), wall %s, ETA %s, %.3g particle-steps/s",
                  simulated_time, end_time_, 100 * fraction, clock_text(wall).c_str(),
                  eta_text.c_str(), rate);
  const std::string tail = format(" %3.0f%% t %s/%s wall %s ETA %s %.2g p-steps/s", 100 * fraction,
                                  clock_text(simulated_time).c_str(), clock_text(end_time_).c_str(),
                                  clock_text(wall).c_str(), eta_text.c_str(), rate);
  // The bar takes what the numbers leave of the line, one column short of the edge (a
  // character in the last column makes some terminals wrap).
  // Its width is set by the simulated time at its widest (the end time), so that the bar
  // keeps its width as the run goes on.
  const int widest =
      int(tail.size() - clock_text(simulated_time).size() + clock_text(end_time_).size());
  const int bar = std::min(30, columns_ - 1 - 2 - std::max(widest, int(tail.size())));
  if (bar < 5) return tail.substr(1, std::size_t(columns_ - 1));
  const int filled = int(std::floor(fraction * bar));
  std::string text(std::size_t(bar + 2), '.');
  text.front() = '[';
  text.back() = ']';
  std::fill_n(text.begin() + 1, filled, '#');
  text.append(tail);
  return text;
}

void Progress::print(double simulated_time, double particle_steps) {
  print_line(out_, tty_, columns_ - 1, line(wall_seconds(), simulated_time, particle_steps));
  printed_ = true;
}

void Progress::done() {
  if (!quiet_ && printed_ && tty_) std::fputc('\n', out_);
}

StageProgress::StageProgress(std::string what, bool quiet, double after_s, double log_interval_s)
    : StageProgress(std::move(what), quiet, stderr, isatty(STDERR_FILENO) != 0, after_s,
                    log_interval_s) {}

StageProgress::StageProgress(std::string what, bool quiet, std::FILE* out, bool tty, double after_s,
                             double log_interval_s)
    : what_(std::move(what)),
      quiet_(quiet),
      out_(out),
      tty_(tty),
      after_(after_s),
      log_interval_(log_interval_s),
      start_(std::chrono::steady_clock::now()) {}

void StageProgress::update(const std::string& stage, double fraction) {
  update_at(std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(), stage,
            fraction);
}

void StageProgress::update_at(double wall, const std::string& stage, double fraction) {
  if (quiet_ || wall < after_) return;
  const bool new_stage = stage != last_stage_;
  last_stage_ = stage;
  if (last_print_ >= 0 && !new_stage && wall - last_print_ < (tty_ ? 0.2 : log_interval_)) return;
  last_print_ = wall;
  print_line(out_, tty_, 79, line(wall, stage, fraction));
  printed_ = true;
}

void StageProgress::done() {
  if (!quiet_ && printed_ && tty_) std::fputc('\n', out_);
}

std::string StageProgress::line(double wall, const std::string& stage, double fraction) const {
  const std::string text = format("sedem: %s: %s %.0f%% (wall %s)", what_.c_str(), stage.c_str(),
                                  100 * std::clamp(fraction, 0.0, 1.0), clock_text(wall).c_str());
  return text.substr(0, 79);
}

std::string run_summary(const nlohmann::json& results, double wall_time,
                        const std::filesystem::path& out) {
  std::string text =
      "sedem: done in " + format("%.1f", wall_time) + " s (" + clock_text(wall_time) + " wall)\n";
  if (!results.empty()) {
    text += format("  %-12s %12s %12s %9s\n", "test", "error (pp)", "bias (pp)", "readings");
    for (const char* test : {"hydrometer", "buoyancy", "pipette"}) {
      if (!results.contains(test)) continue;
      const auto& r = results[test];
      const int readings = r.value("readings", 0);
      // A figure that is absent (no reading; null: a reading that is no number) shows as "-".
      auto shown = [&](const char* key) {
        const auto v = r.value(key, nlohmann::json());
        return readings > 0 && v.is_number() ? format("%12.2f", v.get<double>())
                                             : format("%12s", "-");
      };
      text += format("  %-12s %s %s %9d\n", test, shown("error_pp").c_str(),
                     shown("bias_pp").c_str(), readings);
    }
    text +=
        "  (percentage points of percent finer; error: the test from the DEM against the\n"
        "  reference solution; bias: the reference solution against the true curve)\n";
  }
  namespace fs = std::filesystem;
  if (fs::exists(out / "figures")) text += "  figures:  " + (out / "figures/").string() + '\n';
  if (fs::exists(out / "frames")) text += "  frames:   " + (out / "frames/").string() + '\n';
  if (fs::exists(out / "particles.pvd"))
    text += "  ParaView: " + (out / "particles.pvd").string() + '\n';
  if (fs::exists(out / "report.html"))
    text += "  report:   " + (out / "report.html").string() + '\n';
  text += "  record:   " + (out / "run.json").string() + '\n';
  return text;
}

}  // namespace sedem::app
