#include "core/scene/stage_keys.h"

#include "core/scene/schema.h"

namespace sedem {

void describe(InstrumentsConfig& c, Schema& s) {
  s.integer("instruments.layers", &c.layers, 10, 1000000,
            "n_ly: horizontal layers the suspension density is computed in (paper: 4000).");
  s.list("instruments.profile_times_min", &c.profile_times, "min", 60, 0, 1e6,
         "Times of the largest-diameter-above-depth profiles (Fig. 12; paper: 1, 2, 5, 15 min).");
  s.list("instruments.bulb_profile_times_min", &c.bulb_profile_times, "min", 60, 0, 1e6,
         "Times of the density profiles along the hydrometer's bulb (Fig. 13; paper: 0, 1, 3, "
         "5, 15 min).");
  s.flag("instruments.hydrometer.enabled", &c.hydrometer, "Simulate the ASTM 152H hydrometer.");
  s.list("instruments.hydrometer.times_min", &c.hydrometer_times, "min", 60, 1e-6, 1e6,
         "Reading times (ASTM D422: 2, 5, 15, 30, 60, 250, 1440 min).");
  s.flag("instruments.buoyancy.enabled", &c.buoyancy, "Simulate the buoyancy-sphere test.");
  s.number("instruments.buoyancy.depth_fraction", &c.buoyancy_depth_fraction, "", 1, 0, 1,
           "Depth of the sphere's centre as a fraction of H (paper: 0.3).");
  s.number("instruments.buoyancy.sphere_diameter_cm", &c.sphere_diameter, "cm", 1e-2, 0.01, 6,
           "Sphere diameter (paper: 2.5 cm).");
  s.number("instruments.buoyancy.sphere_mass_g", &c.sphere_mass, "g", 1e-3, 0.01, 1000,
           "Sphere mass in air (paper: 20 g).");
  s.list("instruments.buoyancy.times_min", &c.buoyancy_times, "min", 60, 1e-6, 1e6,
         "Reading times (paper: 0.5, 1, 2, 4, 15, 30, 60, 120, 240, 480 min).");
  s.flag("instruments.pipette.enabled", &c.pipette, "Simulate the pipette test.");
  s.number("instruments.pipette.depth_fraction", &c.pipette_depth_fraction, "", 1, 0, 1,
           "Depth of the pipette tip as a fraction of H (paper: 0.3).");
  s.number("instruments.pipette.volume_ml", &c.pipette_volume, "mL", 1e-6, 0.01, 1000,
           "Volume drawn from the whole cylinder (paper: 35 mL).");
  s.list("instruments.pipette.times_min", &c.pipette_times, "min", 60, 1e-6, 1e6,
         "Sampling times (the paper gives none; default: the buoyancy test's).");
  s.number("instruments.hydrometer.tip_length_cm", &c.hydrometer_tip_length, "cm", 1e-2, 0, 7,
           "Length of the bulb's bottom cone (shape only; length and volume are the 152H's).");
  s.number("instruments.hydrometer.shoulder_length_cm", &c.hydrometer_shoulder_length, "cm", 1e-2,
           0, 7, "Length of the cone from the bulb to the stem.");
  s.choice("instruments.reference.settling", &c.reference_settling,
           {"free", "richardson_zaki", "local_voidage"},
           "Reference solution: each size at its clear-fluid terminal velocity (free), slowed by "
           "Richardson-Zaki at the initial solids, or at the drag law's speed at the local "
           "voidage, as the DEM's Di Felice drag hinders it (local_voidage).");
  s.number("instruments.reference.richardson_zaki_exponent", &c.reference_richardson_zaki_exponent,
           "", 1, 0, 10, "Richardson-Zaki exponent n (4.65 in the Stokes regime).");
  s.number("instruments.reference.bed_packing", &c.reference_bed_packing, "", 1, 0.05, 1,
           "Solid fraction of the reference's bed at the bottom.");
}

}  // namespace sedem
