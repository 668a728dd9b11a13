#pragma once

#include <cstddef>

#include "core/engine/engine.h"
#include "core/observe/instrument_observer.h"

namespace sedem {

// A whole test with no files and no pictures: the engine advanced through the instruments'
// times on the calling thread. What benchmarks and accuracy studies need.
struct SimulationRun {
  TestResults results;
  EngineStats stats;
  std::size_t particles = 0;
  Particles last;  // the particles at the last reading, in sample order
  double wall_seconds = 0;
};

SimulationRun simulate(const Scene& scene, Sample sample);

}  // namespace sedem
