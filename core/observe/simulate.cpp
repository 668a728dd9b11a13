#include "core/observe/simulate.h"

#include <chrono>

namespace sedem {

SimulationRun simulate(const Scene& scene, Sample sample) {
  const auto start = std::chrono::steady_clock::now();
  InstrumentObserver instruments(scene, sample);
  SimulationRun run;
  run.particles = sample.particles.size();
  Engine engine(scene, std::move(sample));
  for (double t : instruments.wanted_times()) {
    engine.advance_to(t);
    instruments.observe(engine.snapshot());
  }
  run.results = instruments.results();
  run.stats = engine.stats();
  run.last = engine.particles();
  run.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace sedem
