#include "core/physics/stokes.h"

#include <cmath>
#include <numbers>

namespace sedem::stokes {

double terminal_velocity(double diameter, double particle_density, const Fluid& fluid) {
  return (particle_density - fluid.density) * fluid.gravity * diameter * diameter /
         (18.0 * fluid.viscosity);
}

double relaxation_time(double diameter, double particle_density, const Fluid& fluid) {
  return particle_density * diameter * diameter / (18.0 * fluid.viscosity);
}

double response_time(double diameter, double particle_density, const Fluid& fluid,
                     double fraction) {
  return -relaxation_time(diameter, particle_density, fluid) * std::log1p(-fraction);
}

double diameter_from_velocity(double velocity, double particle_density, const Fluid& fluid) {
  return std::sqrt(18.0 * fluid.viscosity * velocity /
                   ((particle_density - fluid.density) * fluid.gravity));
}

double limiting_diameter(double depth, double time, double particle_density, const Fluid& fluid) {
  return diameter_from_velocity(depth / time, particle_density, fluid);
}

double drag_force(double diameter, double speed, const Fluid& fluid) {
  return 3.0 * std::numbers::pi * fluid.viscosity * diameter * speed;
}

}  // namespace sedem::stokes
