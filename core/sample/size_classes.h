#pragma once

#include "core/model/grain.h"

#include <cstdint>
#include <string>
#include <vector>

#include "core/model/sample.h"
#include "core/sample/grading_curve.h"

namespace sedem {

// The n_phi sizes of Sect. 4.4: phi_1 .. phi_n spaced evenly in log d from the curve's
// smallest to its largest diameter (one size: their geometric mean, or the single size).
std::vector<double> discrete_diameters(const GradingCurve& curve, std::int64_t size_count);

// Sect. 4.4 and Eq. 15: size phi_n takes the mass w_n - w_{n-1}, with w_n the curve at the
// midpoint (phi_n + phi_{n+1}) / 2 (w_0 = 0, w_last = 100), and its real grain count in a
// section holding `section_mass` of soil is n = 6 m (w_n - w_{n-1}) / (100 rho_p pi phi_n^3).
// Sizes the curve gives no mass (a plateau) are left out: a particle there would stand for
// no soil. Counts and weights are not set yet.
std::vector<SizeClass> discretise(const GradingCurve& curve, std::int64_t size_count,
                                  double section_mass, double particle_density);

// How simulated particles share the real grains: each size's share of the simulated count.
// equal_mass: in proportion to the size's mass (each particle stands for the same mass);
// uniform_count: to its real grain count (each stands for the same number of grains);
// equal_per_size: the same count for every size.
std::vector<double> simulated_shares(const std::vector<SizeClass>& classes,
                                     const std::string& weighting);

// The simulated count that simulates `mass_fraction` of the section's mass grain for grain:
// N such that sum_k N share_k (grain mass)_k = mass_fraction * section_mass (rounded).
std::int64_t count_for_mass_fraction(const std::vector<SizeClass>& classes,
                                     const std::vector<double>& shares, double mass_fraction,
                                     double particle_density);

// Splits `total` simulated particles over the sizes in proportion to `shares`, at least one
// per size (largest remainders, so the counts add up to max(total, sizes)), and sets each
// size's weight = real grains / simulated particles: sum of weight x grain mass over a size
// is then that size's real mass in the section.
void assign_counts(std::vector<SizeClass>& classes, const std::vector<double>& shares,
                   std::int64_t total);

}  // namespace sedem
