#pragma once

// The force laws as small evaluators, called from one neighbour loop (force_pass.cpp).
// Conventions: n points from particle a to particle b, t = (-n_y, n_x); a positive overlap is
// interpenetration. Each pair's contact is evaluated in a canonical order (a = the lower
// sample index), so the two particles of a pair, each summing its own force, see bitwise
// opposite forces: momentum is conserved exactly and no atomics are needed.

#include <cmath>
#include <numbers>

namespace sedem {

enum class DragLaw { off, stokes, di_felice };

// Constants of the force laws, taken from the scene once.
struct ForceModel {
  bool weight = true, buoyancy = true, contact = true, friction = true, lubrication = false;
  bool suspension_contacts = true;  // local steps: coasting grains see each other's boxes
  // false: the force pass only detects contacts; the integrator resolves them as constraints
  // (integrate/contact_projection.h), friction included.
  bool contact_forces = true;
  DragLaw drag = DragLaw::di_felice;
  bool voidage_excludes_self = true;  // Di Felice: see VoidageGrid::excluding
  double kn = 1e3, kt = 1e3, mu = 0.5;
  double lubrication_intensity = 10, lubrication_range = 10;
  double particle_density = 2500, fluid_density = 1000, viscosity = 1e-3, gravity = 9.81;
  double half_width = 0.03175;
  // Extra search distance, in radii, within which a pair counts as about to touch (the
  // explicit integrator shortens its step before contact rather than after).
  double skin = 0;

  double volume(double d) const { return std::numbers::pi / 6.0 * d * d * d; }
  double mass(double d) const { return particle_density * volume(d); }
  // Weight plus buoyancy along y (negative: downwards).
  double gravity_force(double d) const {
    return -((weight ? particle_density : 0.0) - (buoyancy ? fluid_density : 0.0)) * gravity *
           volume(d);
  }
  // F_s of Eq. 10 as read in docs/physics.md ("Contacts and lubrication (Eq. 10)"): the Stokes drag
  // at terminal velocity = net weight.
  double stokes_terminal_drag(double d) const {
    return (particle_density - fluid_density) * gravity * volume(d);
  }
  // Gap beyond which Eq. 10 is below 1e-6 of its contact value, in radii of the particle.
  double lubrication_reach() const { return lubrication ? 13.8 / lubrication_range : 0.0; }
};

// Normal and tangential contact between a and b (Eqs. 1-4), canonical order.
struct ContactResult {
  double fx = 0, fy = 0;              // on a; b gets the opposite
  double torque_a = 0, torque_b = 0;  // about each centre
  double spring = 0;                  // tangential spring after this step
  double overlap = 0;
};

// `spring` is the accumulated tangential displacement g_T; dt the step it is advanced over.
inline ContactResult contact_force(const ForceModel& m, double nx, double ny, double overlap,
                                   double ra, double rb, double vxa, double vya, double wa,
                                   double vxb, double vyb, double wb, double spring, double dt) {
  ContactResult c;
  c.overlap = overlap;
  const double fn = m.kn * overlap;
  c.fx = -fn * nx;
  c.fy = -fn * ny;
  if (m.friction) {
    const double tx = -ny, ty = nx;
    // Relative velocity of a's contact point against b's, along t (Eqs. 2, 6).
    const double vt = (vxa - vxb) * tx + (vya - vyb) * ty + wa * ra + wb * rb;
    double g = spring + vt * dt;
    double ft = -m.kt * g;
    const double limit = m.mu * fn;
    if (std::abs(ft) > limit) {  // Phi >= 0 of Eq. 4: sliding, the spring slips to the limit
      ft = ft > 0 ? limit : -limit;
      g = -ft / m.kt;
    }
    c.spring = g;
    c.fx += ft * tx;
    c.fy += ft * ty;
    c.torque_a = ra * ft;
    c.torque_b = rb * ft;
  }
  return c;
}

// Eq. 10 as read in docs/physics.md ("Contacts and lubrication (Eq. 10)"): the push on particle i
// (radius ri, diameters di, dk) at gap g.
inline double lubrication_force(const ForceModel& m, double di, double dk, double gap) {
  const double ri = 0.5 * di;
  const double r = 2 * di / (di + dk);
  return m.stokes_terminal_drag(di) * m.lubrication_intensity * r * r * r *
         std::exp(-m.lubrication_range * (gap > 0 ? gap : 0.0) / ri);
}

}  // namespace sedem
