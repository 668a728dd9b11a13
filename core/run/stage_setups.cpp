#include "core/run/stage_setups.h"

namespace sedem {

EngineSetup engine_setup(const Scene& scene) {
  EngineSetup s;
  s.fluid = scene.fluid;
  s.cylinder = scene.cylinder;
  s.forces = scene.forces;
  s.integrator = scene.integrator;
  s.lowest_measured_height = lowest_measured_height(scene.instruments, scene.cylinder.height);
  s.instruments_read = any_instrument(scene.instruments);
  s.end_time = scene.end_time;
  return s;
}

SampleSetup sample_setup(const Scene& scene) {
  return SampleSetup{scene.sample, scene.cylinder};
}

TestSetup test_setup(const Scene& scene) {
  TestSetup s;
  s.fluid = scene.fluid;
  s.cylinder = scene.cylinder;
  s.instruments = scene.instruments;
  s.drag = scene.forces.drag;
  s.particle_density = scene.sample.particle_density;
  s.total_mass = scene.sample.total_mass;
  s.end_time = scene.end_time;
  return s;
}

}  // namespace sedem
