#pragma once

#include "core/model/cylinder.h"
#include "core/model/fluid.h"

namespace sedem {

// What every instrument needs to turn a reading into (phi_o, w_o): the liquid, the grains'
// density and c_0 = m_tt / v_0, the concentration at time zero (Eq. 17), kg/m^3.
struct Suspension {
  Fluid fluid;
  Cylinder cylinder;
  double particle_density = 2500.0;
  double initial_concentration = 0;
};

// Eq. 17 with c_o from the suspension density (Sect. 4.5.1): 100 c_o / c_0 where
// c_o = rho_p (rho_s - rho_f) / (rho_p - rho_f).
double percent_finer_from_density(double suspension_density, const Suspension& s);

}  // namespace sedem
