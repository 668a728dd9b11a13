#pragma once

#include <string>
#include <vector>

#include "core/model/snapshot.h"
#include "core/observe/observer.h"

namespace sedem::python {

// Keeps copies of the particles at some of the times a run stops at anyway, for Python to
// read as arrays. Its times are snapped onto the run's own (snap_to) before it watches: a
// time of its own would stop the engine elsewhere and the run would no longer be the one
// `sedem run` gives.
class ParticleKeeper : public Observer {
 public:
  // Which times: `wanted` (s), the run's last, the scene's output times, or every one.
  enum class Which { wanted, last, output, all };
  ParticleKeeper(std::vector<double> wanted, Which which)
      : wanted_(std::move(wanted)), which_(which) {}
  // Each wanted time becomes the nearest of the run's times (`output`: the output times,
  // every output.interval_s, which the run stops at already).
  void snap_to(const std::vector<double>& run_times, double output_interval, double end_time);
  std::string name() const override { return "python particles"; }
  std::vector<double> wanted_times() const override { return times_; }
  void observe(double time, const Particles& particles) override {
    kept_.push_back(Snapshot{time, particles});
  }
  const std::vector<Snapshot>& kept() const { return kept_; }

 private:
  std::vector<double> wanted_, times_;
  Which which_;
  std::vector<Snapshot> kept_;
};

}  // namespace sedem::python
