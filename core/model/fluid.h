#pragma once

namespace sedem {

// The suspending liquid. SI units: kg/m^3, Pa*s (dynamic viscosity), m/s^2.
// The paper's nu_f in Eqs. 11-14 is this dynamic viscosity once multiplied out.
struct Fluid {
  double density = 1000.0;
  double viscosity = 1.0e-3;
  double gravity = 9.81;
};

}  // namespace sedem
