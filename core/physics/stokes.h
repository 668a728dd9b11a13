#pragma once

#include "core/model/fluid.h"

namespace sedem::stokes {

// The simple sedimentation model of Sect. 4.3 (Eqs. 11-14, 16): one sphere, Stokes drag,
// weight and buoyancy, no neighbours. It is what the laboratory tests assume, what sets the
// explicit integrator's step, and the Re -> 0, dilute limit the engine must reproduce.

// Eq. 13 right: u_tr = (rho_p - rho_f) g phi^2 / (18 mu), m/s (downwards).
double terminal_velocity(double diameter, double particle_density, const Fluid& fluid);

// The time constant of Eq. 13 left, rho_p phi^2 / (18 mu): u(t) = u_tr (1 - exp(-t / tau)).
// Eq. 13 ignores added mass; so does sedem's reference, to match the paper's Table 1.
double relaxation_time(double diameter, double particle_density, const Fluid& fluid);

// Time to reach `fraction` of the terminal velocity from rest: -tau ln(1 - fraction).
// Table 1 of the paper uses 0.99 for its 70 um row and 0.95 for the others.
double response_time(double diameter, double particle_density, const Fluid& fluid, double fraction);

// Eq. 14: the diameter whose terminal velocity is `velocity`.
double diameter_from_velocity(double velocity, double particle_density, const Fluid& fluid);

// Eq. 16: the largest diameter still above `depth` after `time` (a bottomless cylinder).
double limiting_diameter(double depth, double time, double particle_density, const Fluid& fluid);

// Stokes drag magnitude 3 pi mu phi |u| (Eq. 11).
double drag_force(double diameter, double speed, const Fluid& fluid);

}  // namespace sedem::stokes
