#include "core/instruments/instruments_config.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sedem {

double lowest_measured_height(const InstrumentsConfig& in, double height) {
  double depth = 0;
  if (in.hydrometer) depth = std::max(depth, 0.1629 + 0.07);
  if (in.buoyancy)
    depth = std::max(depth, in.buoyancy_depth_fraction * height + 0.5 * in.sphere_diameter);
  if (in.pipette) {
    const double r = std::cbrt(3 * in.pipette_volume / (4 * std::numbers::pi));
    depth = std::max(depth, in.pipette_depth_fraction * height + r);
  }
  return height - depth - 0.01;
}

bool any_instrument(const InstrumentsConfig& in) {
  return in.hydrometer || in.buoyancy || in.pipette;
}

}  // namespace sedem
