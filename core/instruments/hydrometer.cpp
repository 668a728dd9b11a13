#include "core/instruments/hydrometer.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/physics/stokes.h"

namespace sedem {

namespace {

constexpr double kPi = std::numbers::pi;

// Volume of the frustum of `length` between radii r0 and r1.
double frustum(double length, double r0, double r1) {
  return kPi * length * (r0 * r0 + r0 * r1 + r1 * r1) / 3.0;
}

}  // namespace

double HydrometerGeometry::stem_area() const {
  return kPi * stem_radius * stem_radius;
}

double HydrometerGeometry::volume_below(double z) const {
  double v = 0;
  for (std::size_t k = 0; k + 1 < heights.size(); ++k) {
    const double z0 = heights[k], z1 = heights[k + 1];
    if (z <= z0) break;
    if (z1 <= z0) continue;
    const double top = std::min(z, z1);
    const double r_top = radii[k] + (radii[k + 1] - radii[k]) * (top - z0) / (z1 - z0);
    v += frustum(top - z0, radii[k], r_top);
  }
  return v;
}

double HydrometerGeometry::reading_at(double stem_submerged) const {
  return reading_low + (mark_low - stem_submerged) / mark_per_reading;
}

double HydrometerGeometry::mark_of(double reading) const {
  return mark_low - (reading - reading_low) * mark_per_reading;
}

HydrometerGeometry make_hydrometer(const HydrometerDesign& d) {
  // The scale reads R g/L of soil of specific gravity Gs in the calibration water: such a
  // suspension has density rho(R) = rho_w + R (1 - 1/Gs) (R in g/L = kg/m^3; each kg of soil
  // displaces 1/Gs kg of water).
  const double per_reading = 1.0 - 1.0 / d.calibration_specific_gravity;
  const double rho_lo = d.calibration_water_density + d.reading_low * per_reading;
  const double rho_hi = d.calibration_water_density + d.reading_high * per_reading;
  // Floating at either mark, the same mass M displaces rho (V_B + A l):
  //   rho_lo (V_B + A l_lo) = rho_hi (V_B + A l_hi)
  //   => A = V_B (rho_hi - rho_lo) / (rho_lo l_lo - rho_hi l_hi).
  const double area =
      d.bulb_volume * (rho_hi - rho_lo) / (rho_lo * d.mark_low - rho_hi * d.mark_high);
  if (!(area > 0)) throw std::invalid_argument("hydrometer design: marks give no stem area");
  const double stem_radius = std::sqrt(area / kPi);
  // The bulb: a tip cone, a cylinder of radius r_b, a shoulder cone from r_b to the stem:
  //   V_B = pi [r_b^2 l_c + r_b^2 l_t / 3 + l_s (r_b^2 + r_b r_s + r_s^2) / 3]
  // a quadratic a r_b^2 + b r_b + c = 0 with the positive root taken.
  const double body = d.bulb_length - d.tip_length - d.shoulder_length;
  if (body < 0) throw std::invalid_argument("hydrometer design: cones longer than the bulb");
  const double a = kPi * (body + d.tip_length / 3.0 + d.shoulder_length / 3.0);
  const double b = kPi * d.shoulder_length * stem_radius / 3.0;
  const double c = kPi * d.shoulder_length * stem_radius * stem_radius / 3.0 - d.bulb_volume;
  const double bulb_radius = (-b + std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);

  HydrometerGeometry h;
  h.heights = {0.0, d.tip_length, d.tip_length + body, d.bulb_length,
               d.bulb_length + d.stem_length};
  h.radii = {0.0, bulb_radius, bulb_radius, stem_radius, stem_radius};
  h.bulb_length = d.bulb_length;
  h.bulb_volume = d.bulb_volume;
  h.stem_radius = stem_radius;
  // Floating at mark_low in the liquid of reading_low.
  h.mass = rho_lo * (d.bulb_volume + area * d.mark_low);
  h.mark_low = d.mark_low;
  h.mark_per_reading = (d.mark_low - d.mark_high) / (d.reading_high - d.reading_low);
  h.reading_low = d.reading_low;
  h.scale_min = d.scale_min;
  h.scale_max = d.scale_max;
  return h;
}

double hydrostatic_force(const HydrometerGeometry& h, const LayerFields& fields, double tip_depth) {
  // Sect. 4.5.1 sums the layer pressures on the horizontal projections of the surface,
  // sum p^n pi [(b^{n+1})^2 - (b^n)^2]. Integrated by parts (p = 0 at the free surface,
  // dp/dd = rho_s g) that is g times the suspension mass displaced layer by layer,
  // sum_n rho_s^n V^n: what is summed here, exactly for the conical pieces, instead of
  // sampling the radius at layer boundaries. The stem is included the same way.
  double mass = 0;
  for (std::size_t k = 0; k + 1 < h.heights.size(); ++k) {
    const double z0 = h.heights[k], z1 = h.heights[k + 1];
    if (z1 <= z0) continue;
    const double top = std::max(0.0, tip_depth - z1), bottom = tip_depth - z0;
    if (bottom <= top) continue;
    // Radius at depth d: r = u - s d, with u = r0 + s (tip - z0).
    const double s = (h.radii[k + 1] - h.radii[k]) / (z1 - z0);
    const double u = h.radii[k] + s * (tip_depth - z0);
    mass += kPi * fields.density_integral(top, bottom, u * u, -2.0 * u * s, s * s);
  }
  return mass * fields.gravity();
}

double hydrometer_radius(const HydrometerGeometry& h, double z) {
  if (z < 0 || z > h.length()) return 0.0;
  for (std::size_t k = 0; k + 1 < h.heights.size(); ++k) {
    const double z0 = h.heights[k], z1 = h.heights[k + 1];
    if (z <= z1 && z1 > z0)
      return h.radii[k] + (h.radii[k + 1] - h.radii[k]) * (z - z0) / (z1 - z0);
  }
  return h.radii.back();
}

double hydrostatic_force_pressure_sum(const HydrometerGeometry& h, const LayerFields& fields,
                                      std::size_t tip_layers) {
  const double dh = fields.layer_height();
  double force = 0;
  // Layer m spans depths [m h, (m + 1) h]; the tip is at the bottom of layer tip_layers - 1.
  for (std::size_t m = 0; m < tip_layers; ++m) {
    const double z_bottom = static_cast<double>(tip_layers - m - 1) * dh;
    const double z_top = z_bottom + dh;
    // At the tip the radius is 0 (the cone's apex, or the bottom face of a cylinder).
    const double b_bottom = m + 1 == tip_layers ? 0.0 : hydrometer_radius(h, z_bottom);
    const double b_top = hydrometer_radius(h, std::min(z_top, h.length()));
    if (z_bottom >= h.length()) continue;
    force += fields.pressure()[m] * std::numbers::pi * (b_top * b_top - b_bottom * b_bottom);
  }
  return force;
}

double tip_depth_in_uniform(const HydrometerGeometry& h, double density) {
  const double volume = h.mass / density;
  if (volume > h.volume_below(h.length()))
    throw std::runtime_error("hydrometer sinks: liquid lighter than " +
                             std::to_string(h.mass / h.volume_below(h.length())) + " kg/m^3");
  double lo = 0, hi = h.length();
  for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
    const double mid = 0.5 * (lo + hi);
    (h.volume_below(mid) < volume ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double equilibrium_tip_depth(const HydrometerGeometry& h, const LayerFields& fields) {
  const double weight = h.mass * fields.gravity();
  const std::size_t n = fields.count();
  const double dh = fields.layer_height();
  auto force_at = [&](std::size_t j) {
    return hydrostatic_force(h, fields, static_cast<double>(j) * dh);
  };
  if (force_at(n) < weight)
    throw std::runtime_error("hydrometer reaches the bottom of the cylinder");
  // The force grows with depth: the first boundary j with f^j >= w_hd.
  std::size_t lo = 0, hi = n;
  while (hi - lo > 1) {
    const std::size_t mid = (lo + hi) / 2;
    (force_at(mid) < weight ? lo : hi) = mid;
  }
  const double f_hi = force_at(hi), f_lo = force_at(hi - 1);
  // Eq. 21 as printed starts from j h_ly; the tip lies between (j - 1) h_ly and j h_ly, so
  // the interpolation starts from (j - 1) h_ly.
  return static_cast<double>(hi - 1) * dh + dh * (weight - f_lo) / (f_hi - f_lo);
}

double astm_152h_effective_depth(double reading) {
  return (16.29 - 0.164 * reading) * 1e-2;
}

HydrometerReading read_hydrometer(const HydrometerGeometry& h, const LayerFields& fields,
                                  double time, const Suspension& s) {
  HydrometerReading r;
  r.time = time;
  r.tip_depth = equilibrium_tip_depth(h, fields);
  const double bulb_top = r.tip_depth - h.bulb_length;
  r.centre_depth = r.tip_depth - 0.5 * h.bulb_length;
  r.reading = h.reading_at(bulb_top);
  r.on_scale = bulb_top >= 0 && r.reading >= h.scale_min && r.reading <= h.scale_max;
  r.standard_effective_depth = astm_152h_effective_depth(r.reading);
  r.clear_water_tip_depth = tip_depth_in_uniform(h, s.fluid.density);
  // Eq. 19: r_s = M / (M - A (y_ow - y_o) rho_f).
  const double rho_f = s.fluid.density;
  const double ratio =
      h.mass / (h.mass - h.stem_area() * (r.clear_water_tip_depth - r.tip_depth) * rho_f);
  r.density_eq19 = ratio * rho_f;
  const double top = std::max(0.0, bulb_top);
  r.bulb_mean_density = fields.mean_density(top, r.tip_depth);
  r.diameter =
      time > 0 ? stokes::limiting_diameter(r.centre_depth, time, s.particle_density, s.fluid) : 0.0;
  r.percent_finer = percent_finer_from_density(r.density_eq19, s);
  r.percent_finer_bulb_density = percent_finer_from_density(r.bulb_mean_density, s);
  for (std::size_t j = fields.layer_at(top); j <= fields.layer_at(r.tip_depth); ++j) {
    const double mid = fields.layer_top(j) + 0.5 * fields.layer_height();
    r.profile_offset.push_back(std::clamp(mid, top, r.tip_depth) - bulb_top);
    r.profile_density.push_back(fields.density()[j]);
  }
  return r;
}

}  // namespace sedem
