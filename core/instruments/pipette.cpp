#include "core/instruments/pipette.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/physics/stokes.h"

namespace sedem {

namespace {

// Area of the part of a circle of radius r centred at 0 below the chord at offset y.
double circle_area_below(double y, double r) {
  y = std::clamp(y, -r, r);
  return y * std::sqrt(r * r - y * y) + r * r * std::asin(y / r) + 0.5 * std::numbers::pi * r * r;
}

PipetteReading finish(const Pipette& p, double radius, double concentration, double time,
                      const Suspension& s) {
  PipetteReading r;
  r.time = time;
  r.depth = p.depth;
  r.radius = radius;
  r.concentration = concentration;
  r.dry_mass = concentration * p.volume;
  r.diameter =
      time > 0 ? stokes::limiting_diameter(p.depth, time, s.particle_density, s.fluid) : 0.0;
  r.percent_finer = 100.0 * concentration / s.initial_concentration;
  return r;
}

void check_inside(const Pipette& p, double radius, const Cylinder& c) {
  if (p.depth - radius < 0 || p.depth + radius > c.height || radius > c.half_width())
    throw std::invalid_argument("pipette sampling circle leaves the section");
}

}  // namespace

double Pipette::radius(const Cylinder& c) const {
  return std::sqrt(volume * c.section_fraction / (std::numbers::pi * c.slab_thickness()));
}

PipetteReading read_pipette(const Pipette& p, const Particles& particles, double time,
                            const Suspension& s) {
  const double radius = p.radius(s.cylinder);
  check_inside(p, radius, s.cylinder);
  const double yc = s.cylinder.height - p.depth;
  double mass = 0;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const double dx = particles.x[i], dy = particles.y[i] - yc;
    if (dx * dx + dy * dy <= radius * radius)
      mass += grain_mass(particles.diameter[i], s.particle_density) * particles.weight[i];
  }
  const double volume = std::numbers::pi * radius * radius * s.cylinder.slab_thickness();
  return finish(p, radius, mass / volume, time, s);
}

PipetteReading read_pipette(const Pipette& p, const LayerFields& fields, double time,
                            const Suspension& s) {
  const double radius = p.radius(s.cylinder);
  check_inside(p, radius, s.cylinder);
  double weighted = 0;
  const std::size_t first = fields.layer_at(p.depth - radius);
  const std::size_t last = fields.layer_at(p.depth + radius);
  for (std::size_t j = first; j <= last; ++j) {
    const double a = fields.layer_top(j) - p.depth;
    const double b = a + fields.layer_height();
    weighted +=
        fields.concentration()[j] * (circle_area_below(b, radius) - circle_area_below(a, radius));
  }
  return finish(p, radius, weighted / (std::numbers::pi * radius * radius), time, s);
}

}  // namespace sedem
