#pragma once

#include <cmath>
#include <cstdint>

namespace sedem {

// A point of the unit square.
struct UnitPoint {
  double u = 0, v = 0;
};

// Point i of the R2 sequence (M. Roberts, "The unreasonable effectiveness of quasirandom
// sequences", 2018): the Kronecker sequence frac(shift + i (1/g, 1/g^2)), g = 1.3247... the
// plastic number (g^3 = g + 1), the two-dimensional analogue of the golden ratio. Any run of
// consecutive points covers the square evenly, the first n as well as points a..a+n, so
// a set of consecutive particles placed on it is spread evenly, and so is every run of such
// sets. `shift` (a random point) makes it a seeded randomised quasi-Monte Carlo set.
inline UnitPoint r2_point(std::uint64_t i, UnitPoint shift) {
  constexpr double a1 = 0.75487766624669276005, a2 = 0.56984029099805326591;
  // i * a loses the fraction's low bits as i grows: exact to about 1e-8 up to i = 10^8.
  const double n = double(i);
  const double u = shift.u + n * a1, v = shift.v + n * a2;
  return {u - std::floor(u), v - std::floor(v)};
}

}  // namespace sedem
