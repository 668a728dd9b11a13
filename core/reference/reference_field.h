#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/fields/layer_fields.h"
#include "core/model/sample.h"

namespace sedem {

struct Scene;

// How the continuum reference settles each size class.
struct ReferenceOptions {
  bool hindered = false;                   // Richardson-Zaki: u = u_0 (1 - phi_0)^n
  double richardson_zaki_exponent = 4.65;  // n in the Stokes regime
  double bed_packing = 0.6;                // solid fraction of the bed at the bottom
};

// One size class of the continuum: its concentration at time zero and settling speed.
struct SettlingClass {
  double diameter = 0;       // m
  double concentration = 0;  // kg/m^3 of solids at time zero, uniform
  double velocity = 0;       // m/s, downwards
};

// The terminal velocity the engine uses for the scene's forces.drag: "stokes" -> Eq. 13,
// "di_felice" -> Di Felice at voidage 1. Throws for "off" (no terminal velocity).
double reference_terminal_velocity(const std::string& drag, double diameter,
                                   double particle_density, const Fluid& fluid);

// The classes of a sample with their velocities: c_0 f_n each, u_n from the drag law,
// hindered by the initial solid fraction phi_0 = c_0 / rho_p if asked.
std::vector<SettlingClass> settling_classes(const std::vector<SizeClass>& classes,
                                            double initial_concentration, double particle_density,
                                            const Fluid& fluid, const std::string& drag,
                                            const ReferenceOptions& options);

// The dilute continuum (docs/instruments.md): from a uniform start every grain of class n
// moves down by u_n t, so the class is gone above its falling upper front at depth u_n t,
// keeps its initial concentration below it, and whatever has reached the bottom lies in a
// bed of solid fraction `bed_packing`, whose top rises as it fills.
class ReferenceSolution {
 public:
  ReferenceSolution(std::vector<SettlingClass> classes, const Cylinder& cylinder,
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

  const std::vector<SettlingClass>& classes() const { return classes_; }

 private:
  std::vector<SettlingClass> classes_;
  Cylinder cylinder_;
  double particle_density_;
  double bed_packing_;
};

// The reference for a scene and its sample.
ReferenceSolution make_reference(const Scene& scene, const Sample& sample,
                                 const ReferenceOptions& options);

}  // namespace sedem
