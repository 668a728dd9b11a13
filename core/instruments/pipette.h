#pragma once

#include "core/fields/layer_fields.h"
#include "core/instruments/suspension.h"
#include "core/model/particles.h"

namespace sedem {

// The pipette test of Sect. 4.5.3: a circle of the section around the axis at the tip's
// depth whose volume (area x h_z) stands for the pipette's volume of the whole cylinder,
// i.e. pi r^2 h_z = V_pipette x section_fraction.
struct Pipette {
  double volume = 35e-6;  // m^3 drawn from the whole cylinder
  double depth = 0;       // y_pt, m below the free surface
  double radius(const Cylinder& cylinder) const;
};

struct PipetteReading {
  double time = 0;
  double depth = 0;          // m
  double radius = 0;         // m, of the sampling circle
  double concentration = 0;  // c_o, kg/m^3 of solids
  double dry_mass = 0;       // what the pipette's volume would hold, kg
  double diameter = 0;       // phi_o, Eq. 16 at y_pt
  double percent_finer = 0;  // w_o, Eq. 17
};

// From the weighted particles whose centres are in the circle.
PipetteReading read_pipette(const Pipette& pipette, const Particles& particles, double time,
                            const Suspension& suspension);

// From a field uniform across the section (the reference solution): the layer
// concentrations weighted by the circle's area in each layer.
PipetteReading read_pipette(const Pipette& pipette, const LayerFields& fields, double time,
                            const Suspension& suspension);

}  // namespace sedem
