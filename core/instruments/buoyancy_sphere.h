#pragma once

#include "core/fields/layer_fields.h"
#include "core/instruments/suspension.h"

namespace sedem {

// The buoyancy test of Sect. 4.5.2: a sphere held at a fixed depth on a line to a scale.
struct BuoyancySphere {
  double diameter = 0.025;  // m
  double mass = 20e-3;      // m_sp|a, kg in air
  double centre_depth = 0;  // y_bt, m below the free surface
  double volume() const;
};

struct BuoyancyReading {
  double time = 0;
  double depth = 0;                      // y_bt, m
  double mean_density = 0;               // suspension over the sphere's volume, kg/m^3
  double apparent_mass = 0;              // m_sp, kg
  double clear_water_apparent_mass = 0;  // m_sp|w, kg
  double diameter = 0;                   // phi_o, Eq. 16 at y_bt
  double percent_finer = 0;              // w_o, Eq. 22
};

// The suspension mass the sphere displaces, layer by layer: the density weighted by the
// sphere's horizontal cross-section pi (R^2 - (d - y_bt)^2) at each depth.
double displaced_mass(const BuoyancySphere& sphere, const LayerFields& fields);

BuoyancyReading read_buoyancy(const BuoyancySphere& sphere, const LayerFields& fields, double time,
                              const Suspension& suspension);

// Eq. 22: w_o = 100 (rho_f / c_0) (m_w - m_sp) / ((rho_f / rho_p - 1) (m_w - m_a)).
double buoyancy_percent_finer(double apparent_mass, double clear_water_apparent_mass,
                              double mass_in_air, const Suspension& suspension);

}  // namespace sedem
