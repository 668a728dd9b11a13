#pragma once

// The laboratory test as the lab sets it up: the column, the liquid, the instruments, and what
// the reference solution needs of the soil and of the run. The instruments, the reference
// solution, the inversion and the schedule design read it; core/run makes it from a scene.

#include <string>

#include "core/instruments/instruments_config.h"
#include "core/model/cylinder.h"
#include "core/model/fluid.h"

namespace sedem {

struct TestSetup {
  Fluid fluid;
  Cylinder cylinder;
  InstrumentsConfig instruments;
  std::string drag = "di_felice";  // the settling law of the reference solution (forces.drag)
  double particle_density = 2500;  // kg/m^3 (sample.particle_density)
  double total_mass = 60e-3;       // kg poured into the whole cylinder (sample.total_mass)
  double end_time = 60;            // s of simulated time: no reading after it (run.end_time)
};

}  // namespace sedem
