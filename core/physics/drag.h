#pragma once

#include "core/model/fluid.h"

namespace sedem::drag {

// Di Felice (1994) drag on one sphere, Eqs. 7-9 (docs/physics.md, "Drag (Eqs. 7-9)"):
//   F = 1/2 C_d rho_f (pi phi^2 / 4) eps^2 |u_r| u_r eps^(-chi),
//   Re = rho_f eps |u_r| phi / mu, C_d = (0.63 + 4.8 / sqrt(Re))^2,
//   chi = 3.7 - 0.65 exp(-(1.5 - log10 Re)^2 / 2),
// with eps the local voidage (fluid fraction). Returns the magnitude of F for a relative
// speed `speed` >= 0. As Re -> 0 and eps -> 1 it tends to 0.96 x Stokes drag.
double di_felice_force(double diameter, double speed, double voidage, const Fluid& fluid);

// F / speed: the drag as a linear coefficient (finite as speed -> 0), N s/m.
double di_felice_coefficient(double diameter, double speed, double voidage, const Fluid& fluid);

// The exponent chi of Eq. 9 at Reynolds number `re`.
double di_felice_exponent(double re);

// Terminal settling speed of one sphere in clear fluid (eps = 1) under weight and buoyancy
// with the Di Felice drag: the root of F(u) = (rho_p - rho_f) g pi phi^3 / 6.
double di_felice_terminal_velocity(double diameter, double particle_density, const Fluid& fluid,
                                   double voidage = 1.0);

}  // namespace sedem::drag
