#pragma once

namespace sedem::water {

// Dynamic viscosity of pure water at `temperature_c` (deg C), Pa*s (0.5 % from 10 to 40 C).
double viscosity(double temperature_c);

// Density of air-free pure water at `temperature_c` (deg C), kg/m^3. Valid 0-40 C.
double density(double temperature_c);

}  // namespace sedem::water
