#include "core/lab/water.h"

#include <cmath>

namespace sedem::water {

double viscosity(double temperature_c) {
  // Vogel equation mu = A 10^(B / (T - C)), A = 2.414e-5 Pa*s, B = 247.8 K, C = 140 K
  // (T in K), as tabulated in Viswanath & Natarajan, "Data Book on the Viscosity of
  // Liquids" (1989). Within 0.5 % of the IAPWS values from 10 to 40 C (1.00175e-3 against
  // 1.0016e-3 at 20 C), 2 % low at 0 C.
  const double kelvin = temperature_c + 273.15;
  return 2.414e-5 * std::pow(10.0, 247.8 / (kelvin - 140.0));
}

double density(double temperature_c) {
  // Tanaka, Girard, Davis, Peuto & Bignell, "Recommended table for the density of water
  // between 0 C and 40 C based on recent experimental reports", Metrologia 38 (2001) 301,
  // Eq. 1 with its air-free coefficients (998.2067 kg/m^3 at 20 C).
  const double t = temperature_c;
  constexpr double a1 = -3.983035, a2 = 301.797, a3 = 522528.9, a4 = 69.34881, a5 = 999.974950;
  return a5 * (1.0 - (t + a1) * (t + a1) * (t + a2) / (a3 * (t + a4)));
}

}  // namespace sedem::water
