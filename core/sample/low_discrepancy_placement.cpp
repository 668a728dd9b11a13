#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "core/sample/overlap_grid.h"
#include "core/sample/placement.h"
#include "core/sample/quasi_random.h"
#include "core/sample/random_stream.h"

namespace sedem {
namespace {

std::vector<std::uint64_t> band_order(std::uint64_t bands) {
  // Bands by the golden-ratio points frac(k / phi): each prefix of the order is spread over
  // the height, so a few consecutive particles never crowd into neighbouring bands.
  std::vector<std::uint64_t> k(bands);
  std::iota(k.begin(), k.end(), 0u);
  auto golden = [](std::uint64_t a) {
    const double f = double(a) * 0.61803398874989484820;
    return f - std::floor(f);
  };
  std::sort(k.begin(), k.end(), [&](auto a, auto b) { return golden(a) < golden(b); });
  std::vector<std::uint64_t> band(bands);
  for (std::uint64_t rank = 0; rank < bands; ++rank) band[k[rank]] = rank;
  return band;
}

}  // namespace

void place_low_discrepancy(Particles& p, const Cylinder& c, std::uint64_t seed) {
  const std::size_t n = p.size();
  if (n == 0) return;
  RandomStream random(seed);
  const UnitPoint shift{random.uniform(), random.uniform()};

  // The section is about seven times as tall as it is wide: one R2 set stretched over it
  // would stand in rows seven times farther apart than its columns, and a circle a few rows
  // tall (the pipette's) would count them coarsely. Near-square bands, particle i in band
  // (i mod bands) at point i / bands of the band's own R2 sequence, keep the pattern as fine
  // across as along, and every run of particles shares itself out evenly among the bands.
  const auto bands = std::max<std::uint64_t>(1, std::uint64_t(std::llround(c.height / c.diameter)));
  const std::vector<std::uint64_t> band_of = band_order(bands);

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
    const std::uint64_t k = i % bands;
    // Each band its own shift, so that the bands do not repeat one pattern.
    const UnitPoint target = r2_point(i / bands, r2_point(k, shift));
    const double x = x_lo + target.u * (x_hi - x_lo);
    const double y = y_lo + (double(band_of[k]) + target.v) / double(bands) * (y_hi - y_lo);
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
