#include "core/observe/simulate.h"
#include "core/run/stage_setups.h"

#include <algorithm>
#include <chrono>

namespace sedem {

SimulationRun simulate(const Scene& scene, Sample sample, bool keep_last) {
  const auto start = std::chrono::steady_clock::now();
  InstrumentObserver instruments(test_setup(scene), sample);
  SimulationRun run;
  run.particles = sample.particles.size();
  Engine engine(engine_setup(scene), std::move(sample));
  for (double t : instruments.wanted_times()) {
    engine.advance_to(t);
    instruments.observe(engine.time(), engine.particles());
    run.peak_engine_bytes = std::max(run.peak_engine_bytes, engine.bytes());
  }
  run.results = instruments.results();
  run.stats = engine.stats();
  if (keep_last) run.last = engine.particles();
  run.simulated_seconds = engine.time();
  run.peak_engine_bytes = std::max(run.peak_engine_bytes, engine.bytes());
  run.threads = engine.threads();
  run.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace sedem
