#include "core/instruments/suspension.h"

namespace sedem {

double percent_finer_from_density(double suspension_density, const Suspension& s) {
  const double rho_p = s.particle_density, rho_f = s.fluid.density;
  const double c_o = rho_p * (suspension_density - rho_f) / (rho_p - rho_f);
  return 100.0 * c_o / s.initial_concentration;
}

}  // namespace sedem
