#include "core/engine/contact/appended_cells.h"

#include <algorithm>
#include <cmath>

namespace sedem {

void AppendedCells::reset(double cell) {
  inverse_cell_ = 1 / cell;
  widest_ = 0;
  increasing_ = true;
  head_.assign(kBuckets, kNone);
  next_.clear();
  id_.clear();
}

std::int64_t AppendedCells::cell_of(double v) const {
  return std::int64_t(std::floor(v * inverse_cell_));
}

std::size_t AppendedCells::bucket(std::int64_t cx, std::int64_t cy) {
  const std::uint64_t h =
      std::uint64_t(cx) * 0x9E3779B97F4A7C15ull ^ std::uint64_t(cy) * 0xC2B2AE3D27D4EB4Full;
  return std::size_t(h >> 51);  // the top 13 bits: kBuckets
}

void AppendedCells::add(std::size_t m, double x, double y, double reach) {
  const std::size_t b = bucket(cell_of(x), cell_of(y));
  increasing_ = increasing_ && (id_.empty() || m > id_.back());
  next_.push_back(head_[b]);
  head_[b] = std::uint32_t(id_.size());
  id_.push_back(std::uint32_t(m));
  widest_ = std::max(widest_, reach);
}

void AppendedCells::collect(double x, double y, double reach) {
  found_.clear();
  if (next_.empty()) return;
  const double r = reach + widest_;
  const std::int64_t c0 = cell_of(x - r), c1 = cell_of(x + r);
  const std::int64_t r0 = cell_of(y - r), r1 = cell_of(y + r);
  if (double(c1 - c0 + 1) * double(r1 - r0 + 1) >= double(next_.size())) {
    // A block of more cells than particles added: looking at each of them is cheaper.
    found_ = id_;
    if (increasing_) return;
  } else {
    for (std::int64_t cy = r0; cy <= r1; ++cy)
      for (std::int64_t cx = c0; cx <= c1; ++cx)
        for (std::uint32_t e = head_[bucket(cx, cy)]; e != kNone; e = next_[e])
          found_.push_back(id_[e]);
  }
  // Cells sharing a bucket list its particles once each; the rows keep the scan's order.
  std::sort(found_.begin(), found_.end());
  found_.erase(std::unique(found_.begin(), found_.end()), found_.end());
}

}  // namespace sedem
