#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "core/fields/layer_fields.h"

namespace sedem::testing {

// Layer fields whose density at the middle of each layer is rho(depth): the solid volume
// per layer is v_t (rho - rho_f) / (rho_p - rho_f).
inline LayerFields fields_with_density(const std::function<double(double)>& rho,
                                       const Cylinder& cylinder, const Fluid& fluid,
                                       double particle_density, std::size_t layers) {
  const double h = cylinder.height / static_cast<double>(layers);
  const double vt = cylinder.diameter * h * cylinder.slab_thickness();
  std::vector<double> v(layers);
  for (std::size_t j = 0; j < layers; ++j)
    v[j] = vt * (rho((static_cast<double>(j) + 0.5) * h) - fluid.density) /
           (particle_density - fluid.density);
  return LayerFields(std::move(v), cylinder, fluid, particle_density);
}

}  // namespace sedem::testing
