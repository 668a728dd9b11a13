#include "core/engine/contact/neighbour_grid.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace sedem {

void NeighbourGrid::configure(double min_search_diameter, double max_search_diameter,
                              double half_width, double height, int threads) {
  threads_ = std::max(1, threads);
  cell0_ = min_search_diameter;
  half_width_ = half_width;
  height_ = height;
  levels_ = 1;
  while (cell0_ * std::ldexp(1.0, levels_ - 1) < max_search_diameter && levels_ < 32) ++levels_;
  cell_.assign(levels_, 0);
  inverse_cell_.assign(levels_, 0);
  columns_.assign(levels_, 0);
  rows_.assign(levels_, 0);
  offset_.assign(levels_ + 1, 0);
  for (int l = 0; l < levels_; ++l) {
    cell_[l] = cell0_ * std::ldexp(1.0, l);
    inverse_cell_[l] = 1.0 / cell_[l];
    columns_[l] = std::max<std::int64_t>(1, std::int64_t(std::ceil(2 * half_width / cell_[l])));
    rows_[l] = std::max<std::int64_t>(1, std::int64_t(std::ceil(height / cell_[l])) + 1);
    offset_[l + 1] = offset_[l] + std::uint64_t(columns_[l]) * std::uint64_t(rows_[l]);
  }
  level_max_radius_.assign(levels_, -1);
}

void NeighbourGrid::build(std::size_t n, const double* x, const double* y, const double* radius) {
  if (level_.size() != n) {
    level_.resize(n);
    bucket_.resize(n);
    sorted_.resize(n);
    const std::size_t buckets = std::bit_ceil(std::max<std::size_t>(n, 64));
    mask_ = buckets - 1;
    start_.assign(buckets + 1, 0);
  }
  std::fill(level_max_radius_.begin(), level_max_radius_.end(), -1.0);
  // The engine's thread count: a serial engine (local steps) must not wake a thread pool.
#pragma omp parallel for schedule(static) num_threads(threads_) if (threads_ > 1 && n >= 2048)
  for (std::size_t i = 0; i < n; ++i) {
    int l = 0;
    while (l + 1 < levels_ && cell_[l] < 2 * radius[i]) ++l;
    level_[i] = std::uint8_t(l);
    bucket_[i] = std::uint32_t(key(l, column(l, x[i]), row(l, y[i])) & mask_);
  }
  for (std::size_t i = 0; i < n; ++i) {
    double& m = level_max_radius_[level_[i]];
    m = std::max(m, radius[i]);
  }
  // Counting sort by bucket; stable, hence deterministic.
  std::fill(start_.begin(), start_.end(), 0u);
  for (std::size_t i = 0; i < n; ++i) ++start_[bucket_[i] + 1];
  for (std::size_t b = 1; b < start_.size(); ++b) start_[b] += start_[b - 1];
  for (std::size_t i = 0; i < n; ++i) sorted_[start_[bucket_[i]]++] = std::uint32_t(i);
  // The scatter advanced each start to the next bucket's; shift back.
  for (std::size_t b = start_.size() - 1; b > 0; --b) start_[b] = start_[b - 1];
  start_[0] = 0;
}

std::size_t NeighbourGrid::bytes() const {
  return level_.capacity() + 4 * (bucket_.capacity() + sorted_.capacity() + start_.capacity());
}

}  // namespace sedem
