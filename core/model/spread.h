#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace sedem {

// The indices of at most `most` of `n` items, spread evenly over them in order, the first and
// the last among them (all of them when n <= most).
inline std::vector<std::size_t> spread_indices(std::size_t n, std::size_t most) {
  std::vector<std::size_t> out;
  if (n <= most || most < 2) {
    for (std::size_t i = 0; i < std::min(n, n <= most ? n : most); ++i) out.push_back(i);
    return out;
  }
  for (std::size_t i = 0; i < most; ++i) out.push_back((i * (n - 1) + (most - 1) / 2) / (most - 1));
  return out;
}

}  // namespace sedem
