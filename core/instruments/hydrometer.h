#pragma once

#include <cstddef>
#include <vector>

#include "core/fields/layer_fields.h"
#include "core/instruments/suspension.h"

namespace sedem {

// The published data of a hydrometer, from which its geometry is derived
// (docs/instruments.md): defaults are the ASTM E100 152H (docs/physics.md, "The 152H hydrometer").
struct HydrometerDesign {
  double bulb_length = 0.140;  // L2, m: tip to the top of the bulb (where the stem starts)
  double bulb_volume = 67e-6;  // V_B, m^3
  double mark_low = 0.105;     // top of bulb to the mark of reading_low, m
  double mark_high = 0.023;    // top of bulb to the mark of reading_high, m
  double reading_low = 0;      // g/L
  double reading_high = 50;    // g/L
  double scale_min = -5, scale_max = 60;        // the printed scale, g/L
  double calibration_specific_gravity = 2.65;   // the scale reads g/L of soil of this Gs
  double calibration_water_density = 998.2067;  // water at 20 C, kg/m^3 (Tanaka et al. 2001)
  double tip_length = 0.020;                    // bottom cone of the bulb, m (a shape parameter)
  double shoulder_length = 0.020;  // top cone from the bulb to the stem, m (a shape parameter)
  double stem_length = 0.130;      // stem above the bulb, m
};

// A body of revolution: radius piecewise linear in the height z above the tip.
struct HydrometerGeometry {
  std::vector<double> heights;  // z, m, ascending from 0 (tip) to the top of the stem
  std::vector<double> radii;    // m, at each height
  double bulb_length = 0;
  double bulb_volume = 0;
  double stem_radius = 0;
  double mass = 0;              // kg
  double mark_low = 0;          // top of bulb to the mark of reading_low, m
  double mark_per_reading = 0;  // m of stem per g/L
  double reading_low = 0;
  double scale_min = -5, scale_max = 60;

  double stem_area() const;
  double length() const { return heights.back(); }
  // Volume of the part below height z.
  double volume_below(double z) const;
  // The reading whose mark is `stem_submerged` above the top of the bulb.
  double reading_at(double stem_submerged) const;
  // Distance from the top of the bulb to the mark of `reading`.
  double mark_of(double reading) const;
};

// Stem area from the two calibration marks, hydrometer mass from floating at mark_low in
// the calibration water, bulb radius from the bulb volume (derivations in the .cpp).
HydrometerGeometry make_hydrometer(const HydrometerDesign& design = {});

// The vertical hydrostatic force on the hydrometer with its tip at `tip_depth`.
double hydrostatic_force(const HydrometerGeometry& h, const LayerFields& fields, double tip_depth);

// The same force summed as printed in Sect. 4.5.1 for a tip on a layer boundary
// (tip_layers h_ly deep): sum_n p^(j-n+1) pi [(b^(n+1))^2 - (b^n)^2], the pressure at each
// layer's bottom on the change of the horizontal projection across the layer. It differs
// from hydrostatic_force by O(h_ly) (one-sided pressures); kept to show the two agree.
double hydrostatic_force_pressure_sum(const HydrometerGeometry& h, const LayerFields& fields,
                                      std::size_t tip_layers);

// Radius at height z above the tip (0 outside the body).
double hydrometer_radius(const HydrometerGeometry& h, double z);

// Tip depth in a uniform liquid of `density` (closed form: V_sub = M / rho).
double tip_depth_in_uniform(const HydrometerGeometry& h, double density);

// Equilibrium depth of the tip (Sect. 4.5.1): the first layer boundary j h_ly at which the
// force exceeds the weight, then Eq. 21 between (j - 1) h_ly and j h_ly.
double equilibrium_tip_depth(const HydrometerGeometry& h, const LayerFields& fields);

struct HydrometerReading {
  double time = 0;                        // s
  double tip_depth = 0;                   // m
  double centre_depth = 0;                // y_go: bulb mid-length, m
  double reading = 0;                     // R, g/L, at the free surface on the stem
  double standard_effective_depth = 0;    // ASTM D422: L = 16.29 - 0.164 R cm, in m
  double clear_water_tip_depth = 0;       // y_ow: tip depth in the scene's clear liquid
  double density_eq19 = 0;                // rho_s from Eq. 19
  double bulb_mean_density = 0;           // length average of the layers along the bulb (Fig. 14)
  double diameter = 0;                    // phi_o, Eq. 16 at y_go
  double percent_finer = 0;               // w_o, Eq. 18 with Eq. 19's r_s
  double percent_finer_bulb_density = 0;  // Eq. 17 with the bulb-mean density
  bool on_scale = true;                   // the reading lies on the printed scale (-5 to 60)
  std::vector<double> profile_offset;     // Fig. 13: distance below the top of the bulb, m
  std::vector<double> profile_density;    // rho_s of the layer there, kg/m^3
};

HydrometerReading read_hydrometer(const HydrometerGeometry& h, const LayerFields& fields,
                                  double time, const Suspension& suspension);

// ASTM D422's effective depth of the 152H, L = 16.29 - 0.164 R (cm), in m.
double astm_152h_effective_depth(double reading);

}  // namespace sedem
