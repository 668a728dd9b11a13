#pragma once

#include <chrono>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

namespace sedem::app {

// Progress of a long run on stderr. On a terminal, one line redrawn in place: a bar, the
// simulated time, wall time, ETA and particle-steps per second, never wider than the
// terminal (at most 80 columns), so it does not wrap. In a log (not a terminal), a plain line
// at most every `log_interval`. Quiet prints nothing.
//
// The ETA comes from the recent rate (simulated seconds per wall second over the last part of
// the run), not from the average since the start: a run's speed changes (the early steps are
// short while the grains accelerate; settled grains later cost nothing).
class Progress {
 public:
  Progress(double end_time, bool quiet, double log_interval_s = 10.0);
  // For tests: where to print, whether it is a terminal and how wide.
  Progress(double end_time, bool quiet, std::FILE* out, bool tty, int columns,
           double log_interval_s = 10.0);
  void update(double simulated_time, double particle_steps);
  void done();
  double wall_seconds() const;

  // The line shown at `wall` seconds into the run (no "\r" nor newline); records the sample
  // for the rate. What update() prints.
  std::string line(double wall, double simulated_time, double particle_steps);
  // Seconds left at the recent rate; negative while unknown.
  double eta(double wall, double simulated_time) const;

 private:
  void print(double simulated_time, double particle_steps);
  void note(double wall, double simulated_time);  // a sample for the rate
  double end_time_;
  bool quiet_;
  std::FILE* out_;
  bool tty_;
  int columns_;
  double log_interval_;
  std::chrono::steady_clock::time_point start_, last_print_;
  std::deque<std::pair<double, double>> samples_;  // (wall, simulated time), recent ones
  bool printed_ = false;
};

// Progress of a computation with stages but no simulated time (an inversion: the fit, the
// bounds, the band), on stderr once it has run `after_s` seconds: quick ones print nothing.
// On a terminal one line redrawn in place; in a log a plain line at most every
// `log_interval`, and one at each new stage. Quiet prints nothing.
class StageProgress {
 public:
  StageProgress(std::string what, bool quiet, double after_s = 2.0, double log_interval_s = 10.0);
  // For tests: where to print and whether it is a terminal.
  StageProgress(std::string what, bool quiet, std::FILE* out, bool tty, double after_s = 2.0,
                double log_interval_s = 10.0);
  // `fraction` of `stage` done (0-1).
  void update(const std::string& stage, double fraction);
  // The same at `wall` seconds since the start (what update() calls).
  void update_at(double wall, const std::string& stage, double fraction);
  void done();
  // "sedem: invert: band 42% (wall 0:05)"
  std::string line(double wall, const std::string& stage, double fraction) const;

 private:
  std::string what_;
  bool quiet_;
  std::FILE* out_;
  bool tty_;
  double after_, log_interval_;
  std::chrono::steady_clock::time_point start_;
  double last_print_ = -1;
  std::string last_stage_;
  bool printed_ = false;
};

// "h:mm:ss" or "m:ss"; "--:--" when unknown.
std::string clock_text(double seconds);

// What a finished run prints: each test's error and bias (from run.json's "results"), the
// wall time and where the figures, frames and ParaView series are.
std::string run_summary(const nlohmann::json& results, double wall_time,
                        const std::filesystem::path& out);

}  // namespace sedem::app
