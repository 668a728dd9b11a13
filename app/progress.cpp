#include "app/progress.h"

#include <unistd.h>

#include <algorithm>
#include <string>

namespace sedem::app {
namespace {

std::string clock_text(double seconds) {
  if (!(seconds >= 0) || seconds > 1e8) return "--:--";
  const long s = long(seconds + 0.5);
  char text[32];
  if (s >= 3600)
    std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  else
    std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
  return text;
}

}  // namespace

Progress::Progress(double end_time, bool quiet, double log_interval_s)
    : end_time_(end_time),
      quiet_(quiet),
      tty_(isatty(STDERR_FILENO) != 0),
      log_interval_(log_interval_s),
      start_(std::chrono::steady_clock::now()),
      last_print_(start_) {}

double Progress::wall_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::update(double simulated_time, double particle_steps) {
  if (quiet_) return;
  const auto now = std::chrono::steady_clock::now();
  const double since = std::chrono::duration<double>(now - last_print_).count();
  if (since < (tty_ ? 0.2 : log_interval_)) return;
  last_print_ = now;
  print(simulated_time, particle_steps);
}

void Progress::print(double simulated_time, double particle_steps) {
  const double wall = wall_seconds();
  const double fraction = end_time_ > 0 ? std::clamp(simulated_time / end_time_, 0.0, 1.0) : 1.0;
  const double eta = fraction > 0 ? wall * (1 - fraction) / fraction : -1;
  const double rate = wall > 0 ? particle_steps / wall : 0;
  std::fprintf(stderr, "%st = %.1f of %.1f s (%3.0f%%)  wall %s  ETA %s  %.3g particle-steps/s%s",
               tty_ ? "\r" : "", simulated_time, end_time_, 100 * fraction,
               clock_text(wall).c_str(), clock_text(eta).c_str(), rate, tty_ ? "   " : "\n");
  std::fflush(stderr);
  printed_ = true;
}

void Progress::done() {
  if (!quiet_ && printed_ && tty_) std::fputc('\n', stderr);
}

}  // namespace sedem::app
