#pragma once

#include <cstddef>

#include "core/engine/engine.h"
#include "core/observe/instrument_observer.h"
#include "core/scene/scene.h"

namespace sedem {

// A whole test with no files and no pictures: the engine advanced through the instruments'
// times on the calling thread. What benchmarks and accuracy studies need.
struct SimulationRun {
  TestResults results;
  EngineStats stats;
  std::size_t particles = 0;
  Particles last;  // the particles at the last reading, in sample order (if asked for)
  double wall_seconds = 0;
  double simulated_seconds = 0;       // the engine's time at the end (the last reading)
  std::size_t peak_engine_bytes = 0;  // largest Engine::bytes() seen at the readings
  int threads = 1;                    // threads the engine ran with
};

// The instruments read the engine's particles in place, with no copy: at a million particles a
// copy is 64 MB. `keep_last` copies them into SimulationRun::last at the end.
SimulationRun simulate(const Scene& scene, Sample sample, bool keep_last = false);

}  // namespace sedem
