#pragma once

#include <chrono>
#include <cstdio>

namespace sedem::app {

// Progress of a long run on stderr: simulated time, wall time, ETA, particle-steps per
// second. On a terminal one line is redrawn; in a log a line is added at most every
// `log_interval`. Quiet prints nothing.
class Progress {
 public:
  Progress(double end_time, bool quiet, double log_interval_s = 10.0);
  void update(double simulated_time, double particle_steps);
  void done();
  double wall_seconds() const;

 private:
  void print(double simulated_time, double particle_steps);
  double end_time_;
  bool quiet_;
  bool tty_;
  double log_interval_;
  std::chrono::steady_clock::time_point start_, last_print_;
  bool printed_ = false;
};

}  // namespace sedem::app
