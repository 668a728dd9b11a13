#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace sedem {

// Particle state as structure of arrays: the exchange format between the sample, the engine
// and the observers. SI units. Positions follow the Cylinder convention (y up, bottom y = 0).
// `weight` is the statistical weight: how many real grains of the 60 g sample one simulated
// particle stands for. Dynamics use one real grain; fields and instruments use the weights.
struct Particles {
  std::vector<double> x, y;    // m
  std::vector<double> vx, vy;  // m/s
  std::vector<double> omega;   // rad/s, rotation about the axis normal to the plane
  std::vector<double> diameter;
  std::vector<double> weight;
  std::vector<std::int32_t> size_class;
  std::vector<std::uint32_t> id;

  std::size_t size() const { return x.size(); }
  bool empty() const { return x.empty(); }

  void resize(std::size_t n) {
    x.resize(n);
    y.resize(n);
    vx.resize(n);
    vy.resize(n);
    omega.resize(n);
    diameter.resize(n);
    weight.resize(n);
    size_class.resize(n);
    id.resize(n);
  }
};

}  // namespace sedem
