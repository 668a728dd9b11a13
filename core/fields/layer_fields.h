#pragma once

#include "core/model/grain.h"

#include <cstddef>
#include <vector>

#include "core/model/cylinder.h"
#include "core/model/fluid.h"
#include "core/model/particles.h"

namespace sedem {

// The suspension in n_ly horizontal layers of the section B x h_ly x h_z (Sect. 4.5.1).
// Layer j = 0 is the top one and spans depths [j h_ly, (j + 1) h_ly] below the free surface.
// Besides the per-layer values it keeps prefix moments of the density, so that the integral
// of rho_s(d) times any quadratic in the depth d over any depth interval is exact and O(1):
// that is what the hydrometer's and the sphere's hydrostatic forces need.
class LayerFields {
 public:
  LayerFields() = default;
  // From the solid (particle) volume in each layer, m^3, top layer first.
  LayerFields(std::vector<double> solid_volume, const Cylinder& cylinder, const Fluid& fluid,
              double particle_density);

  std::size_t count() const { return solid_volume_.size(); }
  double height() const { return height_; }
  double layer_height() const { return layer_height_; }
  double layer_volume() const { return layer_volume_; }  // v_t = B h_ly h_z
  double fluid_density() const { return fluid_density_; }
  double particle_density() const { return particle_density_; }
  double gravity() const { return gravity_; }

  const std::vector<double>& solid_volume() const { return solid_volume_; }  // v_p^j, m^3
  const std::vector<double>& density() const { return density_; }  // rho_s^j, Eq. 20, kg/m^3
  const std::vector<double>& concentration() const { return concentration_; }  // kg/m^3
  // p^j: gauge pressure at the bottom of layer j, the weight of the layers above per unit
  // area (Sect. 4.5.1): sum_{n <= j} rho_s^n h_ly g.
  const std::vector<double>& pressure() const { return pressure_; }

  double layer_top(std::size_t j) const { return static_cast<double>(j) * layer_height_; }
  // The layer holding `depth`, clamped to the column.
  std::size_t layer_at(double depth) const;
  double density_at(double depth) const { return density_[layer_at(depth)]; }
  // Gauge pressure at any depth in [0, H]: linear within a layer, exact for Eq. 20's
  // piecewise-constant density.
  double pressure_at(double depth) const;
  // Integral of rho_s(d) (c0 + c1 d + c2 d^2) over depths [a, b], 0 <= a <= b <= H.
  double density_integral(double a, double b, double c0, double c1 = 0, double c2 = 0) const;
  // Length-average of rho_s over depths [a, b].
  double mean_density(double a, double b) const;

 private:
  double moment(int k, double depth) const;

  double height_ = 0, layer_height_ = 0, layer_volume_ = 0;
  double fluid_density_ = 0, particle_density_ = 0, gravity_ = 0;
  std::vector<double> solid_volume_, density_, concentration_, pressure_;
  // moments_[k][j] = integral of rho_s d^k over depths [0, j h_ly], k = 0, 1, 2.
  std::vector<double> moments_[3];
};

// The real grains' volume in each of `layers` layers of a column `height` high, top layer
// first: each simulated particle puts the volume of its `weight` grains in the layer its
// centre is in.
std::vector<double> layer_solid_volume(const Particles& particles, double height,
                                       std::size_t layers);

// Eq. 20 from the weighted particles, O(N + n_ly). Each simulated particle puts the volume
// of its `weight` real grains in the layer its centre is in (see docs/instruments.md).
LayerFields compute_layer_fields(const Particles& particles, const Cylinder& cylinder,
                                 const Fluid& fluid, double particle_density, std::size_t layers);

// Concentration (kg/m^3 of solids) on a depth x width grid of the section, row 0 at the top,
// column 0 at the wall x = -B/2; each cell is (H / rows) x (B / cols) x h_z.
struct ConcentrationGrid {
  std::size_t rows = 0, cols = 0;
  double cell_height = 0, cell_width = 0;
  std::vector<double> values;  // row-major
  double at(std::size_t row, std::size_t col) const { return values[row * cols + col]; }
};

ConcentrationGrid concentration_grid(const Particles& particles, const Cylinder& cylinder,
                                     double particle_density, std::size_t rows, std::size_t cols);

// Fig. 12: the largest diameter of the particles whose centres are above each layer's bottom,
// against Eq. 16's limiting diameter at that depth and time.
struct LargestDiameterProfile {
  double time = 0;
  std::vector<double> depth;     // bottom of each layer, m
  std::vector<double> largest;   // m; 0 where no particle is above
  std::vector<double> limiting;  // Eq. 16, m (0 at time 0, where it is undefined)
};

LargestDiameterProfile largest_diameter_profile(const Particles& particles,
                                                const Cylinder& cylinder, const Fluid& fluid,
                                                double particle_density, std::size_t layers,
                                                double time);

}  // namespace sedem
