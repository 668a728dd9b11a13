#include "core/fields/layer_fields.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/physics/stokes.h"

namespace sedem {

namespace {

// Index of the layer (or row) holding the centre at depth `depth`. Centres above the free
// surface or below the bottom (contact overlaps) are kept in the end layers so that no mass
// is lost.
std::size_t clamp_index(double depth, double thickness, std::size_t count) {
  const double k = std::floor(depth / thickness);
  if (!(k > 0)) return 0;  // also NaN
  if (k >= static_cast<double>(count - 1)) return count - 1;
  return static_cast<std::size_t>(k);
}

}  // namespace

LayerFields::LayerFields(std::vector<double> solid_volume, const Cylinder& cylinder,
                         const Fluid& fluid, double particle_density)
    : height_(cylinder.height),
      fluid_density_(fluid.density),
      particle_density_(particle_density),
      gravity_(fluid.gravity),
      solid_volume_(std::move(solid_volume)) {
  const std::size_t n = solid_volume_.size();
  if (n == 0) throw std::invalid_argument("LayerFields: no layers");
  layer_height_ = height_ / static_cast<double>(n);
  layer_volume_ = cylinder.diameter * layer_height_ * cylinder.slab_thickness();
  density_.resize(n);
  concentration_.resize(n);
  pressure_.resize(n);
  for (auto& m : moments_) m.assign(n + 1, 0.0);
  double p = 0;
  for (std::size_t j = 0; j < n; ++j) {
    // Eq. 20: (rho_p v_p + rho_f v_f) / v_t with v_f = v_t - v_p.
    const double vp = solid_volume_[j];
    density_[j] = (particle_density_ * vp + fluid_density_ * (layer_volume_ - vp)) / layer_volume_;
    concentration_[j] = particle_density_ * vp / layer_volume_;
    p += density_[j] * layer_height_ * gravity_;
    pressure_[j] = p;
    const double a = layer_top(j), b = a + layer_height_;
    moments_[0][j + 1] = moments_[0][j] + density_[j] * (b - a);
    moments_[1][j + 1] = moments_[1][j] + density_[j] * (b * b - a * a) / 2.0;
    moments_[2][j + 1] = moments_[2][j] + density_[j] * (b * b * b - a * a * a) / 3.0;
  }
}

std::size_t LayerFields::layer_at(double depth) const {
  return clamp_index(depth, layer_height_, count());
}

double LayerFields::moment(int k, double depth) const {
  depth = std::clamp(depth, 0.0, height_);
  const std::size_t j = layer_at(depth);
  const double a = layer_top(j);
  const double rho = density_[j];
  const int e = k + 1;
  return moments_[k][j] + rho * (std::pow(depth, e) - std::pow(a, e)) / e;
}

double LayerFields::pressure_at(double depth) const {
  return moment(0, depth) * gravity_;
}

double LayerFields::density_integral(double a, double b, double c0, double c1, double c2) const {
  if (b <= a) return 0;
  return c0 * (moment(0, b) - moment(0, a)) + c1 * (moment(1, b) - moment(1, a)) +
         c2 * (moment(2, b) - moment(2, a));
}

double LayerFields::mean_density(double a, double b) const {
  if (b <= a) return density_at(a);
  return density_integral(a, b, 1.0) / (b - a);
}

std::vector<double> layer_solid_volume(const Particles& particles, double height,
                                       std::size_t layers) {
  if (layers == 0) throw std::invalid_argument("layer_solid_volume: zero layers");
  std::vector<double> volume(layers, 0.0);
  const double thickness = height / static_cast<double>(layers);
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const double v = grain_volume(particles.diameter[i]) * particles.weight[i];
    volume[clamp_index(height - particles.y[i], thickness, layers)] += v;
  }
  return volume;
}

LayerFields compute_layer_fields(const Particles& particles, const Cylinder& cylinder,
                                 const Fluid& fluid, double particle_density, std::size_t layers) {
  return LayerFields(layer_solid_volume(particles, cylinder.height, layers), cylinder, fluid,
                     particle_density);
}

ConcentrationGrid concentration_grid(const Particles& particles, const Cylinder& cylinder,
                                     double particle_density, std::size_t rows, std::size_t cols) {
  if (rows == 0 || cols == 0) throw std::invalid_argument("concentration_grid: empty grid");
  ConcentrationGrid g;
  g.rows = rows;
  g.cols = cols;
  g.cell_height = cylinder.height / static_cast<double>(rows);
  g.cell_width = cylinder.diameter / static_cast<double>(cols);
  g.values.assign(rows * cols, 0.0);
  const double cell_volume = g.cell_height * g.cell_width * cylinder.slab_thickness();
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const std::size_t r = clamp_index(cylinder.depth_of(particles.y[i]), g.cell_height, rows);
    const std::size_t c = clamp_index(particles.x[i] + cylinder.half_width(), g.cell_width, cols);
    g.values[r * cols + c] +=
        grain_mass(particles.diameter[i], particle_density) * particles.weight[i] / cell_volume;
  }
  return g;
}

LargestDiameterProfile largest_diameter_profile(const Particles& particles,
                                                const Cylinder& cylinder, const Fluid& fluid,
                                                double particle_density, std::size_t layers,
                                                double time) {
  if (layers == 0) throw std::invalid_argument("largest_diameter_profile: zero layers");
  LargestDiameterProfile out;
  out.time = time;
  const double thickness = cylinder.height / static_cast<double>(layers);
  out.largest.assign(layers, 0.0);
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const std::size_t j = clamp_index(cylinder.depth_of(particles.y[i]), thickness, layers);
    out.largest[j] = std::max(out.largest[j], particles.diameter[i]);
  }
  out.depth.resize(layers);
  out.limiting.resize(layers);
  for (std::size_t j = 0; j < layers; ++j) {
    if (j > 0) out.largest[j] = std::max(out.largest[j], out.largest[j - 1]);
    out.depth[j] = static_cast<double>(j + 1) * thickness;
    out.limiting[j] =
        time > 0 ? stokes::limiting_diameter(out.depth[j], time, particle_density, fluid) : 0.0;
  }
  return out;
}

}  // namespace sedem
