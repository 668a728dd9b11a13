#pragma once

// Neighbour search for sizes spanning 1:28 and more: a hierarchy of square cell grids, cell
// sides s_l = s_0 2^l, every particle stored in the finest level whose cells are at least its
// search diameter. A particle looks for partners in its own level and the coarser ones only,
// 3 x 3 cells in each, so a small grain never scans the cells of a fine grid around a large one,
// nor a large grain the many small cells it covers; pairs across levels are found once, from
// the finer side. The grids are not stored densely (the column is 10^5 small cells tall):
// cells are hashed to buckets (key mod 2^k, so a row of cells stays contiguous) and the
// particles counting-sorted by bucket every step. Memory: ~3 ints per particle.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace sedem {

class NeighbourGrid {
 public:
  // `radius[i]` is the search radius of i (its radius plus half the interaction range);
  // i and j may interact when their distance is below radius[i] + radius[j].
  void configure(double min_search_diameter, double max_search_diameter, double half_width,
                 double height, int threads = 1);
  void build(std::size_t n, const double* x, const double* y, const double* radius);

  // Calls visit(j), once, for every j != i stored in a level >= level(i) whose cell lies
  // within radius[i] + the level's largest radius of i, and possibly for some farther j of
  // those levels (the caller tests the distance). Same-level pairs are thus seen from both
  // sides; cross-level pairs only from the finer side.
  // With `coarser_only`, the levels above i's own only (the cross-level pairs of i).
  template <class Visit>
  void for_each_candidate(std::size_t i, const double* x, const double* y, const double* radius,
                          Visit&& visit, bool coarser_only = false) const;

  // Calls visit(j) for every particle j of every level whose cell lies within
  // reach + the level's largest radius of (x, y), and possibly for some farther ones (the caller
  // tests the distance): what a particle not in the grid, of search radius `reach`, may meet.
  // px, py: the positions the grid was built at.
  template <class Visit>
  void for_each_near(double x, double y, double reach, const double* px, const double* py,
                     Visit&& visit) const;

  std::uint8_t level(std::size_t i) const { return level_[i]; }
  // Particles in bucket order: iterating in this order keeps neighbours cache-local.
  const std::vector<std::uint32_t>& order() const { return sorted_; }
  int level_count() const { return levels_; }
  std::size_t bytes() const;

 private:
  std::uint64_t key(int level, std::int64_t cx, std::int64_t cy) const {
    return offset_[level] + std::uint64_t(cy) * std::uint64_t(columns_[level]) + std::uint64_t(cx);
  }
  std::int64_t column(int level, double x) const;
  std::int64_t row(int level, double y) const;
  // visit(j) for the particles j != skip of level l in the cells within r of (x, y).
  template <class Visit>
  void for_each_in_block(int l, double x, double y, double r, std::size_t skip, const double* px,
                         const double* py, Visit&& visit) const;

  int levels_ = 1, threads_ = 1;
  double cell0_ = 1, half_width_ = 0, height_ = 0;
  std::vector<double> cell_, inverse_cell_;
  std::vector<std::int64_t> columns_, rows_;
  std::vector<std::uint64_t> offset_;
  std::uint64_t mask_ = 0;
  std::vector<std::uint8_t> level_;
  std::vector<std::uint32_t> bucket_, sorted_, start_;
  std::vector<double> level_max_radius_;
};

inline std::int64_t NeighbourGrid::column(int level, double x) const {
  std::int64_t c = std::int64_t((x + half_width_) * inverse_cell_[level]);
  if (x + half_width_ < 0) c = 0;
  return c >= columns_[level] ? columns_[level] - 1 : c;
}

inline std::int64_t NeighbourGrid::row(int level, double y) const {
  std::int64_t r = std::int64_t(y * inverse_cell_[level]);
  if (y < 0) r = 0;
  return r >= rows_[level] ? rows_[level] - 1 : r;
}

template <class Visit>
void NeighbourGrid::for_each_candidate(std::size_t i, const double* x, const double* y,
                                       const double* radius, Visit&& visit,
                                       bool coarser_only) const {
  const int own = level_[i];
  for (int l = coarser_only ? own + 1 : own; l < levels_; ++l) {
    const double reach = level_max_radius_[l];
    if (reach < 0) continue;  // empty level
    for_each_in_block(l, x[i], y[i], reach + radius[i], i, x, y, visit);
  }
}

template <class Visit>
void NeighbourGrid::for_each_near(double x, double y, double reach, const double* px,
                                  const double* py, Visit&& visit) const {
  for (int l = 0; l < levels_; ++l)
    if (level_max_radius_[l] >= 0)
      for_each_in_block(l, x, y, reach + level_max_radius_[l], SIZE_MAX, px, py, visit);
}

template <class Visit>
void NeighbourGrid::for_each_in_block(int l, double x, double y, double r, std::size_t skip,
                                      const double* px, const double* py, Visit&& visit) const {
  const std::int64_t c0 = column(l, x - r), c1 = column(l, x + r);
  const std::int64_t r0 = row(l, y - r), r1 = row(l, y + r);
  // The cells of one row are consecutive buckets. When no two cells of the block can share a
  // bucket, a row is one range of the sorted particles, and a particle met there is visited
  // once: only its level need be checked (buckets are shared by distant cells; the caller's
  // distance test drops those).
  // (The block's cells span keys up to (r1 - r0) columns + (c1 - c0) apart; a neighbour
  // search's block is at most 3 x 3.)
  const std::uint64_t span = std::uint64_t((r1 - r0) * columns_[l] + (c1 - c0) + 1);
  const bool distinct = std::max(std::uint64_t(2 * columns_[l] + 3), span) <= mask_;
  for (std::int64_t cy = r0; cy <= r1; ++cy) {
    const std::uint64_t b0 = key(l, c0, cy) & mask_, b1 = key(l, c1, cy) & mask_;
    if (distinct && b0 <= b1) {
      for (std::uint32_t k = start_[b0], e = start_[b1 + 1]; k < e; ++k) {
        const std::uint32_t j = sorted_[k];
        if (level_[j] == l && j != skip) visit(j);
      }
      continue;
    }
    for (std::int64_t cx = c0; cx <= c1; ++cx) {
      const std::uint64_t b = key(l, cx, cy) & mask_;
      for (std::uint32_t k = start_[b], e = start_[b + 1]; k < e; ++k) {
        const std::uint32_t j = sorted_[k];
        // Keep only the particles of this cell (by the positions the grid was built at).
        if (level_[j] != l || j == skip || column(l, px[j]) != cx || row(l, py[j]) != cy) continue;
        visit(j);
      }
    }
  }
}

}  // namespace sedem
