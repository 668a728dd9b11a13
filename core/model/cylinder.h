#pragma once

#include <numbers>

namespace sedem {

// The sedimentation cylinder and the 2D section that stands for it (Sect. 4.4).
// Coordinates used everywhere in sedem: x across the section, axis at x = 0, walls at
// x = +-B/2; y up, bottom at y = 0, free surface at y = H. Depth below the surface is H - y.
struct Cylinder {
  double height = 0.457;     // H, m
  double diameter = 0.0635;  // B, m
  // Share of the cylinder's volume the section stands for: two opposing 1-degree wedges.
  double section_fraction = 1.0 / 180.0;

  // h_z: the slab thickness that gives the B x H rectangle the wedges' volume
  // (pi/4 B^2 H * fraction = B H h_z). For 1/180 this is pi B / 720 (Eq. 20).
  double slab_thickness() const { return std::numbers::pi / 4.0 * diameter * section_fraction; }
  double section_volume() const { return diameter * height * slab_thickness(); }
  double half_width() const { return 0.5 * diameter; }
  double depth_of(double y) const { return height - y; }
};

}  // namespace sedem
