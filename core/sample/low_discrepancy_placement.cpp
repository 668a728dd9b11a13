#include <algorithm>
#include <numeric>
#include <vector>

#include "core/sample/overlap_grid.h"
#include "core/sample/placement.h"
#include "core/sample/quasi_random.h"
#include "core/sample/random_stream.h"

namespace sedem {

void place_low_discrepancy(Particles& p, const Cylinder& c, std::uint64_t seed) {
  const std::size_t n = p.size();
  if (n == 0) return;
  RandomStream random(seed);
  const UnitPoint shift{random.uniform(), random.uniform()};

  // Large particles first: in a dense sample the small ones fit into the gaps they leave.
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return p.diameter[a] > p.diameter[b]; });

  OverlapGrid grid(p, c);
  auto put = [&](std::size_t i, double x, double y) {
    if (grid.overlaps(x, y, 0.5 * p.diameter[i])) return false;
    p.x[i] = x;
    p.y[i] = y;
    grid.insert(i);
    return true;
  };

  constexpr int kPerReach = 32;
  const double largest_reach = std::max(c.diameter, c.height);
  for (std::size_t placed = 0; placed < n; ++placed) {
    const std::size_t i = order[placed];
    const double r = 0.5 * p.diameter[i];
    // The centre's span: inside the walls, above the bottom, below the surface.
    const double x_lo = -c.half_width() + r, x_hi = c.half_width() - r;
    const double y_lo = r, y_hi = c.height - r;
    const UnitPoint target = r2_point(i, shift);
    const double x = x_lo + target.u * (x_hi - x_lo), y = y_lo + target.v * (y_hi - y_lo);
    if (put(i, x, y)) continue;
    // Taken: random points in ever larger squares around it, so the particle stays as near
    // its point as there is room and the spread stays even at any larger scale.
    bool done = false;
    for (double reach = p.diameter[i]; !done; reach *= 2) {
      const double xa = std::max(x_lo, x - reach), xb = std::min(x_hi, x + reach);
      const double ya = std::max(y_lo, y - reach), yb = std::min(y_hi, y + reach);
      for (int a = 0; a < kPerReach && !done; ++a)
        done = put(i, random.uniform(xa, xb), random.uniform(ya, yb));
      if (reach > largest_reach) break;
    }
    if (!done) throw no_room_error(p, c, placed, i);
  }
}

}  // namespace sedem
