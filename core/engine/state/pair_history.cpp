#include "core/engine/state/pair_history.h"

#include <algorithm>
#include <bit>

namespace sedem {

double PairHistory::find(std::uint64_t k) const {
  if (size_ == 0) return 0;
  for (std::uint64_t s = hash(k) & mask_;; s = (s + 1) & mask_) {
    const Entry& e = slots_[s];
    if (e.key == k) return e.spring;
    if (e.key == kEmpty) return 0;
  }
}

void PairHistory::assign(const std::vector<Entry>* lists, std::size_t list_count) {
  std::size_t n = 0;
  for (std::size_t l = 0; l < list_count; ++l) n += lists[l].size();
  // The table is sized for these entries, not for the most a step ever held: clearing the
  // whole buffer at every step, after the first minute's crowd had grown it, was most of this
  // function's time over a whole test. Slots past the table's size are always empty.
  const std::size_t wanted = std::bit_ceil(std::max<std::size_t>(2 * n + 2, 16));
  if (slots_.size() < wanted) {
    slots_.assign(wanted, Entry{});
  } else if (size_ > 0) {
    std::fill(slots_.begin(), slots_.begin() + std::ptrdiff_t(mask_ + 1), Entry{});
  }
  mask_ = wanted - 1;
  size_ = n;
  for (std::size_t l = 0; l < list_count; ++l) {
    for (const Entry& e : lists[l]) {
      std::uint64_t s = hash(e.key) & mask_;
      while (slots_[s].key != kEmpty) s = (s + 1) & mask_;
      slots_[s] = e;
    }
  }
}

std::vector<PairHistory::Entry> PairHistory::sorted_entries() const {
  std::vector<Entry> out;
  for (const Entry& e : slots_)
    if (e.key != kEmpty) out.push_back(e);
  std::sort(out.begin(), out.end(), [](const Entry& a, const Entry& b) { return a.key < b.key; });
  return out;
}

}  // namespace sedem
