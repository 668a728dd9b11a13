#include "python/bindings/particle_keeper.h"

#include <algorithm>
#include <cmath>

namespace sedem::python {

void ParticleKeeper::snap_to(const std::vector<double>& run_times, double output_interval,
                             double end_time) {
  times_.clear();
  if (which_ == Which::all || run_times.empty()) {
    times_ = run_times;
    return;
  }
  std::vector<double> wanted = wanted_;
  if (which_ == Which::last) wanted = {run_times.back()};
  if (which_ == Which::output) wanted = every(output_interval, end_time);
  for (double t : wanted) {
    const auto nearest =
        std::min_element(run_times.begin(), run_times.end(),
                         [t](double a, double b) { return std::abs(a - t) < std::abs(b - t); });
    if (nearest != run_times.end()) times_.push_back(*nearest);
  }
  std::sort(times_.begin(), times_.end());
  times_.erase(std::unique(times_.begin(), times_.end()), times_.end());
}

}  // namespace sedem::python
