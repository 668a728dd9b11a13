#pragma once

#include <cstdint>

#include "core/model/particles.h"
#include "core/model/sample.h"
#include "core/scene/scene.h"

namespace sedem {

// An immutable copy of the particle state at one time, handed to observers.
struct Snapshot {
  double time = 0;
  Particles particles;
};

struct EngineStats {
  std::int64_t steps = 0;
  double particle_steps = 0;
};

// Advances the particles of a sample in time (Eq. 5).
class Engine {
 public:
  Engine(const Scene& scene, Sample sample);

  double time() const { return time_; }
  const Particles& particles() const { return sample_.particles; }
  const Sample& sample() const { return sample_; }
  const EngineStats& stats() const { return stats_; }

  // Advances to exactly `t` (no-op if t <= time()).
  void advance_to(double t);
  Snapshot snapshot() const { return Snapshot{time_, sample_.particles}; }

 private:
  Scene scene_;
  Sample sample_;
  double time_ = 0;
  double step_ = 0;
  EngineStats stats_;
};

}  // namespace sedem
