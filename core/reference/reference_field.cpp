#include "core/reference/reference_field.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/physics/drag.h"
#include "core/physics/stokes.h"
#include "core/scene/scene.h"

namespace sedem {

double reference_terminal_velocity(const std::string& drag, double diameter,
                                   double particle_density, const Fluid& fluid) {
  if (drag == "stokes") return stokes::terminal_velocity(diameter, particle_density, fluid);
  if (drag == "di_felice")
    return drag::di_felice_terminal_velocity(diameter, particle_density, fluid, 1.0);
  throw std::invalid_argument("reference solution: no terminal velocity for drag '" + drag + "'");
}

std::vector<SettlingClass> settling_classes(const std::vector<SizeClass>& classes,
                                            double initial_concentration, double particle_density,
                                            const Fluid& fluid, const std::string& drag,
                                            const ReferenceOptions& options) {
  const double hindrance = options.hindered
                               ? std::pow(1.0 - initial_concentration / particle_density,
                                          options.richardson_zaki_exponent)
                               : 1.0;
  std::vector<SettlingClass> out;
  out.reserve(classes.size());
  for (const auto& c : classes) {
    SettlingClass s;
    s.diameter = c.diameter;
    s.concentration = initial_concentration * c.mass_fraction;
    s.velocity = hindrance * reference_terminal_velocity(drag, c.diameter, particle_density, fluid);
    out.push_back(s);
  }
  return out;
}

ReferenceSolution::ReferenceSolution(std::vector<SettlingClass> classes, const Cylinder& cylinder,
                                     double particle_density, double bed_packing)
    : classes_(std::move(classes)),
      cylinder_(cylinder),
      particle_density_(particle_density),
      bed_packing_(bed_packing) {
  if (!(bed_packing_ > 0 && bed_packing_ <= 1))
    throw std::invalid_argument("reference solution: bed packing must be in (0, 1]");
}

double ReferenceSolution::bed_top(double time) const {
  const double height = cylinder_.height;
  const double bed_density = particle_density_ * bed_packing_;
  double total = 0;
  for (const auto& c : classes_) total += c.concentration * height;
  // Class n, uniform at first, has translated down by u_n t: it fills [u_n t, bed top) and
  // the rest of it is in the bed. The bed's top and the suspended mass depend on each other;
  // the map is a contraction (its slope is at most c_0 / (rho_p packing) < 1), so iterate.
  double top = height;
  for (int it = 0; it < 200; ++it) {
    double suspended = 0;  // kg/m^2
    for (const auto& c : classes_)
      suspended += c.concentration * std::max(0.0, top - c.velocity * time);
    const double next = height - (total - suspended) / bed_density;
    if (std::abs(next - top) <= 1e-15 * height) return next;
    top = next;
  }
  return top;
}

double ReferenceSolution::concentration(double depth, double time) const {
  const double top = bed_top(time);
  if (depth >= top) return particle_density_ * bed_packing_;
  double c_sum = 0;
  for (const auto& c : classes_)
    if (depth >= c.velocity * time) c_sum += c.concentration;
  return c_sum;
}

double ReferenceSolution::largest_diameter_above(double depth, double time) const {
  const double limit = std::min(depth, bed_top(time));
  double largest = 0;
  for (const auto& c : classes_)
    if (c.velocity * time < limit && c.concentration > 0) largest = std::max(largest, c.diameter);
  return largest;
}

std::vector<double> ReferenceSolution::layer_solid_volume(double time, std::size_t layers) const {
  if (layers == 0) throw std::invalid_argument("reference solution: zero layers");
  const double top = bed_top(time);
  const double h = cylinder_.height / static_cast<double>(layers);
  const double area = cylinder_.diameter * cylinder_.slab_thickness();
  // The suspended mass above depth d (d <= bed top) is sum_{e_n <= d} c_n (d - e_n) with
  // e_n = u_n t the depth of class n's upper front: swept down the layer boundaries with
  // the fronts sorted once.
  std::vector<std::pair<double, double>> fronts;  // (e_n, c_n)
  for (const auto& c : classes_) fronts.emplace_back(c.velocity * time, c.concentration);
  std::sort(fronts.begin(), fronts.end());
  std::size_t k = 0;
  double present = 0, moment = 0;  // sum c_n and sum c_n e_n of the fronts above d
  auto cumulative = [&](double d) {
    const double in_suspension = std::min(d, top);
    while (k < fronts.size() && fronts[k].first <= in_suspension) {
      present += fronts[k].second;
      moment += fronts[k].second * fronts[k].first;
      ++k;
    }
    double m = present * in_suspension - moment;
    if (d > top) m += particle_density_ * bed_packing_ * (d - top);
    return m;
  };
  std::vector<double> volume(layers);
  double previous = cumulative(0.0);
  for (std::size_t j = 0; j < layers; ++j) {
    const double next = cumulative(static_cast<double>(j + 1) * h);
    volume[j] = (next - previous) * area / particle_density_;
    previous = next;
  }
  return volume;
}

LayerFields ReferenceSolution::layer_fields(double time, std::size_t layers,
                                            const Fluid& fluid) const {
  return LayerFields(layer_solid_volume(time, layers), cylinder_, fluid, particle_density_);
}

ReferenceSolution make_reference(const Scene& scene, const Sample& sample,
                                 const ReferenceOptions& options) {
  const double c0 = sample.section_mass / scene.cylinder.section_volume();
  return ReferenceSolution(settling_classes(sample.classes, c0, sample.particle_density,
                                            scene.fluid, scene.forces.drag, options),
                           scene.cylinder, sample.particle_density, options.bed_packing);
}

}  // namespace sedem
