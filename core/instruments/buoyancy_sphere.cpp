#include "core/instruments/buoyancy_sphere.h"

#include <algorithm>
#include <numbers>
#include <stdexcept>

#include "core/physics/stokes.h"

namespace sedem {

double BuoyancySphere::volume() const {
  return std::numbers::pi / 6.0 * diameter * diameter * diameter;
}

double displaced_mass(const BuoyancySphere& sphere, const LayerFields& fields) {
  const double r = 0.5 * sphere.diameter, c = sphere.centre_depth;
  if (c - r < 0 || c + r > fields.height())
    throw std::invalid_argument("buoyancy sphere not fully immersed in the column");
  // pi (r^2 - (d - c)^2) = pi [(r^2 - c^2) + 2 c d - d^2].
  return std::numbers::pi * fields.density_integral(c - r, c + r, r * r - c * c, 2.0 * c, -1.0);
}

double buoyancy_percent_finer(double apparent_mass, double clear_water_apparent_mass,
                              double mass_in_air, const Suspension& s) {
  const double rho_f = s.fluid.density;
  return 100.0 * rho_f / s.initial_concentration * (clear_water_apparent_mass - apparent_mass) /
         ((rho_f / s.particle_density - 1.0) * (clear_water_apparent_mass - mass_in_air));
}

BuoyancyReading read_buoyancy(const BuoyancySphere& sphere, const LayerFields& fields, double time,
                              const Suspension& s) {
  BuoyancyReading r;
  r.time = time;
  r.depth = sphere.centre_depth;
  const double displaced = displaced_mass(sphere, fields);
  r.mean_density = displaced / sphere.volume();
  // "Subtracting from the mass of the sphere the mass of the solution which occupies the
  // same volume as the sphere" (Sect. 4.5.2).
  r.apparent_mass = sphere.mass - displaced;
  r.clear_water_apparent_mass = sphere.mass - s.fluid.density * sphere.volume();
  r.diameter =
      time > 0 ? stokes::limiting_diameter(r.depth, time, s.particle_density, s.fluid) : 0.0;
  r.percent_finer =
      buoyancy_percent_finer(r.apparent_mass, r.clear_water_apparent_mass, sphere.mass, s);
  return r;
}

}  // namespace sedem
