#pragma once

#include <vector>

#include "core/model/particles.h"

namespace sedem {

// One of the n_phi discrete sizes of Sect. 4.4 (Eq. 15).
struct SizeClass {
  double diameter = 0;       // phi_n, m
  double mass_fraction = 0;  // (w_n - w_{n-1}) / 100: share of the sample's mass
  double real_count = 0;     // grains of this size in the simulated section (Eq. 15)
  long simulated_count = 0;  // particles the engine moves
  double weight = 0;         // real grains per simulated particle
};

// What the engine starts from: the discretised grading curve and the placed particles.
struct Sample {
  std::vector<SizeClass> classes;
  Particles particles;
  double particle_density = 2500.0;  // kg/m^3
  double section_mass = 0;           // kg of soil in the simulated section (60 g / 180)
  double area_fraction = 0;          // share of the section's plane covered by particles
};

}  // namespace sedem
