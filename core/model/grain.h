#pragma once

#include <numbers>

namespace sedem {

// One spherical grain of diameter d (m).
inline double grain_volume(double diameter) {
  return std::numbers::pi / 6.0 * diameter * diameter * diameter;
}

inline double grain_mass(double diameter, double particle_density) {
  return particle_density * grain_volume(diameter);
}

}  // namespace sedem
