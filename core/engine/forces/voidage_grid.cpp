#include "core/engine/forces/voidage_grid.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sedem {

void VoidageGrid::configure(double cell, double half_width, double height, double slab_thickness,
                            double min_voidage, int threads) {
  inverse_cell_ = 1.0 / cell;
  half_width_ = half_width;
  columns_ = std::max(1L, long(std::ceil(2 * half_width / cell)));
  rows_ = std::max(1L, long(std::ceil(height / cell)));
  cell_volume_ = cell * cell * slab_thickness;
  inverse_volume_ = 1.0 / cell_volume_;
  min_voidage_ = min_voidage;
  threads_ = std::max(1, threads);
  voidage_.assign(std::size_t(columns_ * rows_), 1.0);
  log_voidage_.assign(voidage_.size(), 0.0);
  solid_.assign(voidage_.size(), 0.0);
  hindrance_.assign(voidage_.size(), 1.0);
  partial_.assign(voidage_.size() * std::size_t(threads_), 0.0);
}

void VoidageGrid::compute(std::size_t n, const double* x, const double* y, const double* diameter,
                          const double* weight) {
  const std::size_t cells = voidage_.size();
  std::fill(partial_.begin(), partial_.end(), 0.0);
#pragma omp parallel num_threads(threads_) if (threads_ > 1)
  {
    double* mine = partial_.data() + std::size_t(omp_get_thread_num()) * cells;
#pragma omp for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      const double d = diameter[i];
      mine[cell_of(x[i], y[i])] += weight[i] * (std::numbers::pi / 6.0) * d * d * d;
    }
  }
  const double inv = 1.0 / cell_volume_;
  for (std::size_t c = 0; c < cells; ++c) {
    double solid = 0;
    for (int t = 0; t < threads_; ++t) solid += partial_[std::size_t(t) * cells + c];
    solid_[c] = solid * inv;
    refresh(c);
  }
}

void VoidageGrid::refresh(std::size_t c) {
  voidage_[c] = std::min(1.0, std::max(min_voidage_, 1.0 - solid_[c]));
  log_voidage_[c] = std::log(voidage_[c]);
  hindrance_[c] = std::exp(-1.7 * log_voidage_[c]);
}

void VoidageGrid::deposit(std::size_t c, double weighted_volume) {
  solid_[c] += weighted_volume * inverse_volume_;
  refresh(c);
}

void VoidageGrid::set_solid(const std::vector<double>& solid) {
  solid_ = solid;
  for (std::size_t c = 0; c < solid_.size(); ++c) refresh(c);
}

}  // namespace sedem
