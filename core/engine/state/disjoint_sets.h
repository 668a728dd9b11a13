#pragma once

// Union-find over indices 0..n-1, for grouping particles linked by pairs: the contact
// projection's islands, the carried steps' carrying sets.
//
// A root is always the least index of its set (unite links the larger root under the smaller,
// path halving only shortcuts to an ancestor), so a parent is never above its child. That
// keeps the sets' roots independent of the order pairs arrive in (and of the thread count that
// produced them), and lets flatten() point every index at its root in one pass.

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace sedem {

class DisjointSets {
 public:
  // n singletons.
  void assign(std::size_t n) {
    parent_.resize(n);
    for (std::size_t i = 0; i < n; ++i) parent_[i] = std::uint32_t(i);
  }
  // Singletons appended up to n (the sets of 0..size()-1 stand).
  void grow(std::size_t n) {
    for (std::size_t i = parent_.size(); i < n; ++i) parent_.push_back(std::uint32_t(i));
  }
  // Makes i a singleton again; only sound once every index of i's set is made one, so callers
  // that reset a few sets (not assign) reset all of each set's indices.
  void make_single(std::uint32_t i) { parent_[i] = i; }

  std::uint32_t root(std::uint32_t i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = root(a);
    b = root(b);
    if (a == b) return;
    if (a < b) std::swap(a, b);
    parent_[a] = b;
  }
  // Every index's parent becomes its root: since a parent is never above its child, in index
  // order each parent is already flat when its children are reached.
  void flatten() {
    for (std::size_t i = 0; i < parent_.size(); ++i) parent_[i] = parent_[parent_[i]];
  }
  // After flatten(): the root without a walk.
  std::uint32_t flat_root(std::uint32_t i) const { return parent_[i]; }

  std::size_t bytes() const { return parent_.capacity() * sizeof(std::uint32_t); }

 private:
  std::vector<std::uint32_t> parent_;
};

}  // namespace sedem
