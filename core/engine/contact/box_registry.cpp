#include "core/engine/contact/box_registry.h"

#include <algorithm>
#include <cmath>

namespace sedem {

void BoxRegistry::configure(double cell, double half_width, double height, std::size_t grains) {
  inverse_cell_ = 1.0 / cell;
  half_width_ = half_width;
  columns_ = std::max(1L, long(std::ceil(2 * half_width / cell)));
  rows_ = std::max(1L, long(std::ceil(height / cell)));
  cells_.assign(std::size_t(columns_ * rows_), {});
  row_entries_.assign(std::size_t(rows_), 0);
  box_.assign(grains, Box{});
  kind_.assign(grains, kNone);
}

void BoxRegistry::insert(std::uint32_t id) {
  long c0, c1, r0, r1;
  span(box_[id], c0, c1, r0, r1);
  for (long r = r0; r <= r1; ++r) {
    row_entries_[std::size_t(r)] += std::uint32_t(c1 - c0 + 1);
    for (long c = c0; c <= c1; ++c) cells_[std::size_t(r * columns_ + c)].push_back(id);
  }
}

void BoxRegistry::erase(std::uint32_t id) {
  long c0, c1, r0, r1;
  span(box_[id], c0, c1, r0, r1);
  for (long r = r0; r <= r1; ++r) {
    row_entries_[std::size_t(r)] -= std::uint32_t(c1 - c0 + 1);
    for (long c = c0; c <= c1; ++c) cells_[std::size_t(r * columns_ + c)].erase(id);
  }
}

void BoxRegistry::set(std::uint32_t id, const Box& box, std::uint8_t kind) {
  if (kind_[id] != kNone) {
    long a0, a1, b0, b1, c0, c1, d0, d1;
    span(box_[id], a0, a1, b0, b1);
    span(box, c0, c1, d0, d1);
    if (a0 == c0 && a1 == c1 && b0 == d0 && b1 == d1) {  // same cells: no list changes
      box_[id] = box;
      kind_[id] = kind;
      return;
    }
    erase(id);
  }
  box_[id] = box;
  kind_[id] = kind;
  insert(id);
}

void BoxRegistry::clear(std::uint32_t id) {
  if (kind_[id] == kNone) return;
  erase(id);
  kind_[id] = kNone;
}

std::size_t BoxRegistry::bytes() const {
  std::size_t b = box_.capacity() * sizeof(Box) + kind_.capacity() +
                  cells_.capacity() * sizeof(Cell) +
                  row_entries_.capacity() * sizeof(std::uint32_t);
  for (const Cell& c : cells_) b += c.more.capacity() * sizeof(std::uint32_t);
  return b;
}

}  // namespace sedem
