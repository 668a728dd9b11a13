#include "core/sample/memory_order.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

namespace sedem {
namespace {

// The bits of v spread to the even positions: interleaving two of them gives the Z-order key.
std::uint64_t spread_bits(std::uint64_t v) {
  v &= 0xFFFFFFFFull;
  v = (v | (v << 16)) & 0x0000FFFF0000FFFFull;
  v = (v | (v << 8)) & 0x00FF00FF00FF00FFull;
  v = (v | (v << 4)) & 0x0F0F0F0F0F0F0F0Full;
  v = (v | (v << 2)) & 0x3333333333333333ull;
  v = (v | (v << 1)) & 0x5555555555555555ull;
  return v;
}

template <class T>
void permute(std::vector<T>& v, const std::vector<std::size_t>& order) {
  std::vector<T> out(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) out[k] = v[order[k]];
  v = std::move(out);
}

}  // namespace

void order_for_memory(Particles& p, const Cylinder& c) {
  const std::size_t n = p.size();
  if (n < 2) return;
  const double hw = c.half_width();
  const double cell = std::sqrt(2 * hw * c.height / double(n));
  auto bin = [&](double v) { return std::uint64_t(std::clamp(v / cell, 0.0, 4294967295.0)); };
  std::vector<std::uint64_t> key(n);
  for (std::size_t k = 0; k < n; ++k)
    key[k] = spread_bits(bin(p.x[k] + hw)) | (spread_bits(bin(p.y[k])) << 1);
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (p.size_class[a] != p.size_class[b]) return p.size_class[a] < p.size_class[b];
    return key[a] < key[b];
  });
  permute(p.x, order);
  permute(p.y, order);
  permute(p.vx, order);
  permute(p.vy, order);
  permute(p.omega, order);
  permute(p.diameter, order);
  permute(p.weight, order);
  permute(p.size_class, order);
  std::iota(p.id.begin(), p.id.end(), std::uint32_t(0));
}

}  // namespace sedem
