#pragma once

// The tangential spring of every frictional contact (Eq. 2 accumulated over the contact's
// life), keyed by the pair of sample indices (stable under the engine's re-sorting). An
// open-addressing table, read-only during the parallel force pass; the next step's table is
// filled afterwards, in a fixed order, from the per-thread lists of the springs that survive.

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace sedem {

class PairHistory {
 public:
  struct Entry {
    std::uint64_t key = kEmpty;
    double spring = 0;
  };
  static constexpr std::uint64_t kEmpty = ~std::uint64_t(0);

  static std::uint64_t key(std::uint32_t a, std::uint32_t b) {
    return a < b ? (std::uint64_t(a) << 32) | b : (std::uint64_t(b) << 32) | a;
  }
  // The two of pair `key`, the lesser first (a wall, numbered above every grain, second).
  static std::pair<std::uint32_t, std::uint32_t> grains(std::uint64_t key) {
    return {std::uint32_t(key >> 32), std::uint32_t(key & 0xFFFFFFFFu)};
  }
  // The spring of pair `key`, 0 if the pair was not in contact.
  double find(std::uint64_t key) const;
  // Rebuilds the table from `entries` (keys unique); keeps its capacity.
  void assign(const std::vector<Entry>* lists, std::size_t list_count);
  std::size_t size() const { return size_; }
  // Every stored entry, in ascending key order (for checkpoints).
  std::vector<Entry> sorted_entries() const;
  std::size_t bytes() const { return slots_.capacity() * sizeof(Entry); }

 private:
  static std::uint64_t hash(std::uint64_t k) {
    k ^= k >> 33;
    k *= 0xff51afd7ed558ccdULL;
    k ^= k >> 33;
    return k;
  }
  std::vector<Entry> slots_;
  std::uint64_t mask_ = 0;
  std::size_t size_ = 0;
};

}  // namespace sedem
