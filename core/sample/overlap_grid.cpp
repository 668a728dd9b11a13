#include "core/sample/overlap_grid.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/sample/placement.h"

namespace sedem {
namespace {

std::int64_t bin_index(double coordinate, double bin, std::int64_t n) {
  return std::clamp<std::int64_t>(std::int64_t(std::floor(coordinate / bin)), 0, n - 1);
}

}  // namespace

OverlapGrid::OverlapGrid(const Particles& p, const Cylinder& c) : p_(p), left_(-c.half_width()) {
  const std::size_t n = p.size();
  d_max_ = *std::max_element(p.diameter.begin(), p.diameter.end());
  std::vector<double> band_max(kBands, 0.0);
  std::vector<std::size_t> band_count(kBands, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t b = band_of(p.diameter[i]);
    band_max[b] = std::max(band_max[b], p.diameter[i]);
    band_count[b] += 1;
  }
  const double area = c.diameter * c.height;
  bands_.resize(kBands);
  for (std::size_t b = 0; b < kBands; ++b) {
    if (band_count[b] == 0) continue;
    Band& band = bands_[b];
    band.max_radius = 0.5 * band_max[b];
    // At least a diameter wide (a query reaches one bin each side), and no more bins than
    // about four per particle.
    band.bin = std::max(band_max[b], std::sqrt(area / (4.0 * double(band_count[b]))));
    band.nx = std::max<std::int64_t>(1, std::int64_t(std::ceil(c.diameter / band.bin)));
    band.ny = std::max<std::int64_t>(1, std::int64_t(std::ceil(c.height / band.bin)));
    band.head.assign(std::size_t(band.nx * band.ny), -1);
  }
  next_.assign(n, -1);
}

bool OverlapGrid::overlaps(double x, double y, double r) const {
  for (const Band& band : bands_) {
    if (band.head.empty()) continue;
    const double reach = r + band.max_radius;
    const std::int64_t ix0 = bin_index(x - reach - left_, band.bin, band.nx);
    const std::int64_t ix1 = bin_index(x + reach - left_, band.bin, band.nx);
    const std::int64_t iy0 = bin_index(y - reach, band.bin, band.ny);
    const std::int64_t iy1 = bin_index(y + reach, band.bin, band.ny);
    for (std::int64_t iy = iy0; iy <= iy1; ++iy) {
      for (std::int64_t ix = ix0; ix <= ix1; ++ix) {
        for (std::int32_t j = band.head[std::size_t(iy * band.nx + ix)]; j >= 0;
             j = next_[std::size_t(j)]) {
          const double dx = x - p_.x[std::size_t(j)], dy = y - p_.y[std::size_t(j)];
          const double touch = r + 0.5 * p_.diameter[std::size_t(j)];
          if (dx * dx + dy * dy < touch * touch) return true;
        }
      }
    }
  }
  return false;
}

void OverlapGrid::insert(std::size_t i) {
  Band& band = bands_[band_of(p_.diameter[i])];
  const std::int64_t ix = bin_index(p_.x[i] - left_, band.bin, band.nx);
  const std::int64_t iy = bin_index(p_.y[i], band.bin, band.ny);
  std::int32_t& head = band.head[std::size_t(iy * band.nx + ix)];
  next_[i] = head;
  head = std::int32_t(i);
}

std::size_t OverlapGrid::band_of(double d) const {
  const double b = std::floor(std::log2(d_max_ / d));
  return std::size_t(std::clamp(b, 0.0, double(kBands - 1)));
}

SceneError no_room_error(const Particles& p, const Cylinder& c, std::size_t placed_before,
                         std::size_t i) {
  std::ostringstream os;
  os << "cannot place particle " << placed_before + 1 << " of " << p.size() << " (diameter "
     << p.diameter[i] * 1e6 << " um) without overlap: the particles cover " << area_fraction(p, c)
     << " of the section's plane; lower sample.simulated_count";
  return SceneError(os.str());
}

}  // namespace sedem
