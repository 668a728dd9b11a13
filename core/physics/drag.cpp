#include "core/physics/drag.h"

#include <cmath>
#include <numbers>

#include "core/physics/stokes.h"

namespace sedem::drag {

double di_felice_exponent(double re) {
  const double l = 1.5 - std::log10(re);
  return 3.7 - 0.65 * std::exp(-0.5 * l * l);
}

double di_felice_coefficient(double diameter, double speed, double voidage, const Fluid& fluid) {
  // Written as F/u so that the Re -> 0 limit is exact: C_d u = (0.63 sqrt(u) + 4.8 sqrt(k))^2/k
  // with k = rho_f eps phi / mu, i.e. C_d Re = (0.63 sqrt(Re) + 4.8)^2.
  const double re = fluid.density * voidage * speed * diameter / fluid.viscosity;
  const double cd_re = std::pow(0.63 * std::sqrt(re) + 4.8, 2);
  // F = 1/2 C_d rho_f A eps^(2 - chi) u^2 = 1/2 (C_d Re) mu / (eps phi) A eps^(2 - chi) u.
  const double area = std::numbers::pi * diameter * diameter / 4.0;
  const double chi = re > 0 ? di_felice_exponent(re) : 3.7;
  return 0.5 * cd_re * fluid.viscosity / (voidage * diameter) * area * std::pow(voidage, 2.0 - chi);
}

double di_felice_force(double diameter, double speed, double voidage, const Fluid& fluid) {
  return di_felice_coefficient(diameter, speed, voidage, fluid) * speed;
}

double di_felice_terminal_velocity(double diameter, double particle_density, const Fluid& fluid,
                                   double voidage) {
  const double net_weight = (particle_density - fluid.density) * fluid.gravity * std::numbers::pi /
                            6.0 * diameter * diameter * diameter;
  // F(u) grows monotonically with u; bracket from the Stokes speed and bisect.
  double lo = 0, hi = 2.0 * stokes::terminal_velocity(diameter, particle_density, fluid) / 0.96;
  while (di_felice_force(diameter, hi, voidage, fluid) < net_weight) hi *= 2;
  for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (di_felice_force(diameter, mid, voidage, fluid) < net_weight ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace sedem::drag
