#pragma once

// Everything the engine needs to know, and nothing more: the column, the fluid, the forces,
// the integrator and where the instruments stop looking. core/run makes it from a scene.

#include "core/engine/engine_config.h"
#include "core/model/cylinder.h"
#include "core/model/fluid.h"

namespace sedem {

struct EngineSetup {
  Fluid fluid;
  Cylinder cylinder;
  ForcesConfig forces;
  IntegratorConfig integrator;
  // Height (m above the bottom) below which no instrument reads: resting grains below it may
  // freeze, and with local steps falling ones may retire onto the coarse bed.
  double lowest_measured_height = 0;
  bool instruments_read = true;  // some instrument reads (without one, no grain retires)
  double end_time = 60.0;        // s: a checkpoint past it is damaged
};

// Whether the engine takes local steps: integrator.local_steps with the exponential integrator,
// and no lubrication (it needs the force pass). Their results are the same on any thread count.
inline bool takes_local_steps(const EngineSetup& setup) {
  return integrator_method(setup.integrator) == IntegratorMethod::exponential &&
         setup.integrator.local_steps && !setup.forces.lubrication;
}

}  // namespace sedem
