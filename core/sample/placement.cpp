#include "core/sample/placement.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <vector>

#include "core/sample/overlap_grid.h"
#include "core/sample/random_stream.h"

namespace sedem {
namespace {

// Where a centre may go: the cell's span, cut to the span the walls allow. A cell narrower
// than a radius at a wall lies wholly outside that span; the particle then takes the strip
// of one cell's width along the wall, the nearest place to its cell.
struct Span {
  double lo, hi;
};
Span centre_span(double cell_lo, double cell_hi, double allowed_lo, double allowed_hi) {
  const double lo = std::max(cell_lo, allowed_lo), hi = std::min(cell_hi, allowed_hi);
  if (lo <= hi) return {lo, hi};
  const double width = cell_hi - cell_lo;
  if (cell_lo >= allowed_hi) return {std::max(allowed_lo, allowed_hi - width), allowed_hi};
  return {allowed_lo, std::min(allowed_hi, allowed_lo + width)};
}

}  // namespace

std::int64_t cells_per_side(const PlacementConfig& config, std::size_t particle_count) {
  if (config.cells_per_side > 0) return config.cells_per_side;
  auto side = std::int64_t(std::sqrt(double(particle_count)));
  while (side * side < std::int64_t(particle_count)) ++side;
  while (side > 1 && (side - 1) * (side - 1) >= std::int64_t(particle_count)) --side;
  return std::max<std::int64_t>(side, 1);
}

double area_fraction(const Particles& p, const Cylinder& c) {
  double covered = 0;
  for (double d : p.diameter) covered += 0.25 * std::numbers::pi * d * d;
  return covered / (c.diameter * c.height);
}

void place_particles(Particles& p, const Cylinder& c, const PlacementConfig& config,
                     std::uint64_t seed) {
  if (config.method == "low_discrepancy")
    place_low_discrepancy(p, c, seed);
  else
    place_stratified(p, c, config, seed);
}

void place_stratified(Particles& p, const Cylinder& c, const PlacementConfig& config,
                      std::uint64_t seed) {
  const std::size_t n = p.size();
  if (n == 0) return;
  RandomStream random(seed);
  const std::int64_t side = cells_per_side(config, n);
  const std::size_t cells = std::size_t(side * side);

  // The order in which cells receive particles: n_mt passes, each visiting every row once
  // in a random order, and each row's cells in a random order over the passes. Particles are
  // dealt in their order in the arrays, so a run of consecutive particles (one size, as
  // build_sample orders them) is spread evenly over the height: in L particles every row
  // gets floor(L / n_mt) of them, give or take one or two. Dealing wraps around when there
  // are more particles than cells: every cell gets floor(n / cells) or one more.
  const auto n_side = std::size_t(side);
  std::vector<std::uint32_t> columns(cells);
  for (std::size_t row = 0; row < n_side; ++row) {
    auto* cols = columns.data() + row * n_side;
    std::iota(cols, cols + n_side, 0u);
    for (std::size_t i = n_side; i > 1; --i) std::swap(cols[i - 1], cols[random.below(i)]);
  }
  std::vector<std::uint32_t> cell_order;
  cell_order.reserve(cells);
  std::vector<std::uint32_t> rows(n_side);
  for (std::size_t pass = 0; pass < n_side; ++pass) {
    std::iota(rows.begin(), rows.end(), 0u);
    for (std::size_t i = n_side; i > 1; --i) std::swap(rows[i - 1], rows[random.below(i)]);
    for (std::uint32_t row : rows)
      cell_order.push_back(std::uint32_t(row * n_side + columns[row * n_side + pass]));
  }
  std::vector<std::uint32_t> cell_of(n);
  for (std::size_t i = 0; i < n; ++i) cell_of[i] = cell_order[i % cells];

  // Large particles first: small ones fit into the gaps the large ones leave.
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return p.diameter[a] > p.diameter[b]; });

  const double cell_w = c.diameter / double(side), cell_h = c.height / double(side);
  const double left = -c.half_width();
  OverlapGrid grid(p, c);
  auto try_cell = [&](std::size_t i, std::int64_t cx, std::int64_t cy, int attempts) {
    const double r = 0.5 * p.diameter[i];
    const Span sx = centre_span(left + double(cx) * cell_w, left + double(cx + 1) * cell_w,
                                left + r, c.half_width() - r);
    const Span sy = centre_span(double(cy) * cell_h, double(cy + 1) * cell_h, r, c.height - r);
    for (int a = 0; a < attempts; ++a) {
      const double x = random.uniform(sx.lo, sx.hi), y = random.uniform(sy.lo, sy.hi);
      if (!grid.overlaps(x, y, r)) {
        p.x[i] = x;
        p.y[i] = y;
        grid.insert(i);
        return true;
      }
    }
    return false;
  };

  constexpr int kInCell = 64, kPerReach = 32;
  for (std::size_t placed = 0; placed < n; ++placed) {
    const std::size_t i = order[placed];
    const std::int64_t cx = cell_of[i] % side, cy = cell_of[i] / side;
    if (try_cell(i, cx, cy, kInCell)) continue;
    // Its cell is full (a large particle may cover many cells): look in the cells around it,
    // ever farther, so that the particle lands as near its cell as there is room.
    bool done = false;
    for (std::int64_t reach = 1; !done; reach *= 2) {
      for (int a = 0; a < kPerReach && !done; ++a) {
        const auto span = std::uint64_t(2 * reach + 1);
        const auto nx =
            std::clamp<std::int64_t>(cx + std::int64_t(random.below(span)) - reach, 0, side - 1);
        const auto ny =
            std::clamp<std::int64_t>(cy + std::int64_t(random.below(span)) - reach, 0, side - 1);
        done = try_cell(i, nx, ny, 1);
      }
      if (reach >= side) break;
    }
    if (!done) throw no_room_error(p, c, placed, i);
  }
}

}  // namespace sedem
