#pragma once

// The queue of the coasting grains' syncs (schedule/local_stepper.h): (time, grain) pairs taken
// earliest first, ties by grain.
//
// Why not a binary heap: in a test's last hours nearly every grain coasts, the heap holds one
// entry each, and its pops (a cache miss at every level below the first few) were a fifth of
// that time at 10^5 grains. But the syncs' times only move forward: a sync at t pushes its next
// window's end, later than t. A radix heap uses that. The entries sit in 65 buckets by the
// highest bit in which their time differs from the last minimum taken (bucket 0: equal to it);
// every key of a bucket is below every key of the next, so a pop takes bucket 0, and an empty
// bucket 0 is refilled from the first bucket that is not empty, whose entries then spread over
// the buckets below it. Pushes and refills append to vectors, read in order; an entry moves down
// a few buckets in its life.
//
// Not every push is later than the last minimum: a grain crossing into another lane's column
// (local_lanes.cpp), or one released at the members' time after the queue has looked further
// ahead. Those go to a small binary heap beside the buckets (`early_`), and a pop takes the
// earlier of the two fronts; if it grows, everything is spread again from the least time.
//
// Pairs compare by time, then grain, so the queue takes the same pairs in the same order as any
// other priority queue of them: the run does not depend on which one holds them. Times are not
// negative (nor -0): the keys are a double's bits, ordered as the doubles are for those.

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace sedem {

class SyncQueue {
 public:
  using Sync = std::pair<double, std::uint32_t>;

  bool empty() const { return size_ == 0; }
  // Every entry held, stale ones included (the stepper's clean-ups are counted by it).
  std::size_t size() const { return size_; }

  // The earliest pair (the queue must not be empty). Not const: it may refill bucket 0.
  const Sync& front() { return early_first() ? early_.front() : buckets_[0].back(); }

  // Removes the earliest pair.
  void pop() {
    if (early_first()) {
      std::pop_heap(early_.begin(), early_.end(), kLater);
      early_.pop_back();
    } else {
      buckets_[0].pop_back();
    }
    --size_;
  }

  void push(double t, std::uint32_t id) {
    const std::uint64_t k = key(t);
    ++size_;
    if (size_ == early_.size() + 1) {  // the buckets were empty: any time can be their least
      last_ = k;
      buckets_[0].emplace_back(t, id);
      return;
    }
    if (k < last_) {
      early_.emplace_back(t, id);
      std::push_heap(early_.begin(), early_.end(), kLater);
      if (early_.size() > kEarlyLeast + size_ / 16) spread_again();
      return;
    }
    std::vector<Sync>& b = buckets_[bucket(k)];
    if (&b != &buckets_[0]) {
      b.emplace_back(t, id);
      return;
    }
    // Bucket 0 is kept with the least grain last.
    b.insert(std::upper_bound(b.begin(), b.end(), id,
                              [](std::uint32_t i, const Sync& e) { return i > e.second; }),
             Sync{t, id});
  }

  void clear() {
    for (std::vector<Sync>& b : buckets_) b.clear();
    early_.clear();
    size_ = 0;
  }

  // Every pair of `all`, in any order (replaces what the queue held).
  void assign(std::vector<Sync> all) {
    clear();
    size_ = all.size();
    spread(all);
  }

  // Drops the pairs `stale` picks.
  template <class Pred>
  void erase_if(Pred stale) {
    size_ = 0;
    for (std::vector<Sync>& b : buckets_) {
      std::erase_if(b, stale);  // keeps bucket 0's order
      size_ += b.size();
    }
    std::erase_if(early_, stale);
    std::make_heap(early_.begin(), early_.end(), kLater);
    size_ += early_.size();
  }

  // The time of the n-th earliest pair (n >= 1) if at least n are due by `horizon`; else
  // `horizon`. Nothing is taken.
  double nth_time(std::size_t n, double horizon) {
    scratch_.clear();
    for (const Sync& e : early_)
      if (e.first <= horizon) scratch_.push_back(e);
    // The buckets in order: once they gave n, the later ones hold only later pairs.
    std::size_t from_buckets = 0;
    for (const std::vector<Sync>& b : buckets_) {
      if (from_buckets >= n) break;
      for (const Sync& e : b)
        if (e.first <= horizon) {
          scratch_.push_back(e);
          ++from_buckets;
        }
    }
    if (scratch_.size() < n) return horizon;
    std::nth_element(scratch_.begin(), scratch_.begin() + std::ptrdiff_t(n - 1), scratch_.end());
    return scratch_[n - 1].first;
  }

  std::size_t bytes() const {
    std::size_t entries = early_.capacity() + scratch_.capacity();
    for (const std::vector<Sync>& b : buckets_) entries += b.capacity();
    return entries * sizeof(Sync);
  }

 private:
  static constexpr auto kLater = std::greater<Sync>{};
  // The early heap may hold this many, plus a sixteenth of the queue, before the buckets take
  // everything again from the least time.
  static constexpr std::size_t kEarlyLeast = 256;
  // A bucket emptied by a refill keeps room for this many entries; a larger one gives its room
  // back (each bucket would otherwise keep the most it ever held: several times the queue).
  static constexpr std::size_t kKeptRoom = 1024;

  // Non-negative doubles are ordered as their bits.
  static std::uint64_t key(double t) { return std::bit_cast<std::uint64_t>(t); }
  // 0 for the last least key itself, else one more than the highest bit in which k differs.
  std::size_t bucket(std::uint64_t k) const {
    return std::size_t(64 - std::countl_zero(k ^ last_));
  }
  std::size_t radix_size() const { return size_ - early_.size(); }

  // Whether the earliest pair is the early heap's; else it is bucket 0's last (refilled first
  // if need be).
  bool early_first() {
    if (radix_size() == 0) return true;
    if (buckets_[0].empty()) refill();
    return !early_.empty() && early_.front() < buckets_[0].back();
  }

  // Bucket 0 is empty, some later one is not: the first such spreads over those below it.
  void refill() {
    std::size_t i = 1;
    while (buckets_[i].empty()) ++i;
    std::vector<Sync>& from = buckets_[i];
    spread(from);  // into buckets below i only: `from` is not written while it is read
    if (from.capacity() > kKeptRoom)
      std::vector<Sync>().swap(from);
    else
      from.clear();
  }

  void order_bucket_zero() {
    std::vector<Sync>& b = buckets_[0];
    if (b.size() > 1)
      std::sort(b.begin(), b.end(),
                [](const Sync& a, const Sync& c) { return a.second > c.second; });
  }

  // Everything spread from the least time, the early heap emptied into the buckets.
  void spread_again() {
    std::vector<Sync> all;
    all.reserve(size_);
    for (std::vector<Sync>& b : buckets_) {
      all.insert(all.end(), b.begin(), b.end());
      b.clear();
    }
    all.insert(all.end(), early_.begin(), early_.end());
    early_.clear();
    spread(all);
  }

  // From the least time of `all`, each pair into its bucket.
  void spread(const std::vector<Sync>& all) {
    if (all.empty()) return;
    std::uint64_t least = key(all.front().first);
    for (const Sync& e : all) least = std::min(least, key(e.first));
    last_ = least;
    for (const Sync& e : all) buckets_[bucket(key(e.first))].push_back(e);
    order_bucket_zero();
  }

  std::array<std::vector<Sync>, 65> buckets_;
  std::vector<Sync> early_;    // a min-heap of pairs pushed earlier than last_ was then
  std::vector<Sync> scratch_;  // of nth_time
  std::uint64_t last_ = 0;     // the key of the least pair at the last refill
  std::size_t size_ = 0;
};

}  // namespace sedem
