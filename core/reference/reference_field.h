#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "core/fields/layer_fields.h"
#include "core/instruments/test_setup.h"
#include "core/model/sample.h"

namespace sedem {

// How the continuum reference settles each size class:
//  - free: at its terminal velocity in clear fluid;
//  - richardson_zaki: slowed by (1 - phi_0)^n, phi_0 the initial solid fraction, everywhere;
//  - local_voidage: at the terminal velocity the setup's drag law gives at the voidage of the
//    suspension around it, which changes as the coarser sizes leave (see voidage_fronts).
enum class ReferenceSettling { free, richardson_zaki, local_voidage };

struct ReferenceOptions {
  ReferenceSettling settling = ReferenceSettling::local_voidage;
  double richardson_zaki_exponent = 4.65;  // n in the Stokes regime
  double bed_packing = 0.6;                // solid fraction of the bed at the bottom
};

// "free", "richardson_zaki", "local_voidage" -> the enum; throws for anything else.
ReferenceSettling reference_settling(const std::string& name);

// One size class of the continuum: its concentration at time zero and settling speed.
struct SettlingClass {
  double diameter = 0;       // m
  double concentration = 0;  // kg/m^3 of solids at time zero, uniform
  double velocity = 0;       // m/s, downwards
};

// The terminal velocity the engine uses for the drag law `drag` (forces.drag): "stokes" -> Eq. 13,
// "di_felice" -> Di Felice at voidage 1. Throws for "off" (no terminal velocity).
double reference_terminal_velocity(const std::string& drag, double diameter,
                                   double particle_density, const Fluid& fluid);

// The classes of a sample with their velocities: c_0 f_n each, u_n from the drag law,
// slowed by Richardson-Zaki at the initial solid fraction phi_0 = c_0 / rho_p if asked (the
// local_voidage option keeps the clear-fluid velocities here; voidage_fronts hinders them).
std::vector<SettlingClass> settling_classes(const std::vector<SizeClass>& classes,
                                            double initial_concentration, double particle_density,
                                            const Fluid& fluid, const std::string& drag,
                                            const ReferenceOptions& options);

// A falling front of the continuum: the upper end of one size class, at depth speed * t.
// Crossing it downwards the concentration of solids rises by `jump` (kg/m^3).
struct SettlingFront {
  double diameter = 0;  // m, the class that ends there
  double speed = 0;     // m/s, downwards
  double jump = 0;      // kg/m^3
};

// The fronts of classes that settle at a speed set by the voidage around them (the Di Felice
// drag's eps^(1 - chi) at low Re), from a uniform start below clear fluid. This is a Riemann
// problem whose solution is self-similar: the fronts fall at constant speeds, fastest class
// lowest, and between two fronts every class present has a constant concentration. Crossing
// the front of class k upwards class k vanishes and, since the voidage rises, every finer class
// m speeds up from v_m to v_m'; its flux through the front is continuous,
//   c_m' (s_k - v_m') = c_m (s_k - v_m),  s_k = v_k(below),
// so it is slightly denser above. Solved from the deepest region (the initial suspension)
// upwards, one bracketed root in the voidage per front. `velocity(n, voidage)` is class n's
// terminal velocity at that voidage; classes are given in any order.
//
// With `held`, it also records what the solution did with the speeds: the order of the classes,
// each front's speed and the factor by which each finer class's concentration changed across it.
// fronts_with_held_speeds then gives the fronts of other concentrations with those speeds held,
// which are linear in the concentrations: what an inversion linearises (readings affine in the
// class masses, the voidage taken anew between two of its steps).
struct HeldFronts {
  std::vector<std::size_t> order;          // the classes, slowest first
  std::vector<double> speed;               // of the front of order[k]
  std::vector<std::vector<double>> scale;  // scale[k][m], m < k: c_m above / below front k
};
std::vector<SettlingFront> voidage_fronts(
    const std::vector<SettlingClass>& classes, double particle_density,
    const std::function<double(std::size_t, double)>& velocity, HeldFronts* held = nullptr);
std::vector<SettlingFront> fronts_with_held_speeds(const std::vector<SettlingClass>& classes,
                                                   const HeldFronts& held);

// voidage_fronts for the setup's drag law: Di Felice's terminal velocity at voidage eps is
// u_n(1) eps^(a_n), a_n fitted exactly at the initial voidage (chi hardly changes over the few
// per cent of solids); Stokes drag does not see the voidage, so its fronts are the classes'.
std::vector<SettlingFront> local_voidage_fronts(const std::vector<SettlingClass>& classes,
                                                double particle_density, const Fluid& fluid,
                                                const std::string& drag,
                                                HeldFronts* held = nullptr);

// The dilute continuum (docs/instruments.md): from a uniform start every grain of class n
// moves down by u_n t, so the class is gone above its falling upper front at depth u_n t,
// keeps its initial concentration below it, and whatever has reached the bottom lies in a
// bed of solid fraction `bed_packing`, whose top rises as it fills. Built from fronts, the
// concentration is piecewise constant between them instead (local_voidage).
class ReferenceSolution {
 public:
  ReferenceSolution(const std::vector<SettlingClass>& classes, const Cylinder& cylinder,
                    double particle_density, double bed_packing);
  static ReferenceSolution from_fronts(std::vector<SettlingFront> fronts, const Cylinder& cylinder,
                                       double particle_density, double bed_packing);

  // Depth of the top of the bed at `time`, m.
  double bed_top(double time) const;
  // Concentration of solids at `depth` and `time`, kg/m^3.
  double concentration(double depth, double time) const;
  // Fig. 12 for the continuum: the largest class diameter present anywhere above `depth`
  // (classes whose upper front u_n t is above it); 0 if none.
  double largest_diameter_above(double depth, double time) const;
  // Solid volume in each of `layers` layers of the section (exact overlaps).
  std::vector<double> layer_solid_volume(double time, std::size_t layers) const;
  LayerFields layer_fields(double time, std::size_t layers, const Fluid& fluid) const;

  const std::vector<SettlingFront>& fronts() const { return fronts_; }

 private:
  ReferenceSolution(std::vector<SettlingFront> fronts, const Cylinder& cylinder,
                    double particle_density, double bed_packing, int);
  std::vector<SettlingFront> fronts_;  // sorted by speed
  Cylinder cylinder_;
  double particle_density_;
  double bed_packing_;
};

// The reference for a setup and its sample.
ReferenceSolution make_reference(const TestSetup& setup, const Sample& sample,
                                 const ReferenceOptions& options);

}  // namespace sedem
