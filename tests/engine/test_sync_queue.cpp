#include "core/engine/schedule/sync_queue.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <queue>
#include <random>
#include <vector>

namespace sedem {
namespace {

using Sync = SyncQueue::Sync;
using Reference = std::priority_queue<Sync, std::vector<Sync>, std::greater<Sync>>;

// A sync pushes a window's end a little after the last pair taken; now and then one lands before
// it (a grain from another lane, a release at the members' time), and times repeat, so that
// pairs tie on time and the grain decides.
Sync draw(std::mt19937& rng, double now) {
  const double ahead = double(rng() % 64) * 0.125;
  const double t = rng() % 8 == 0 ? std::max(0.0, now - double(rng() % 16) * 0.25) : now + ahead;
  return {t, std::uint32_t(rng() % 40)};
}

std::vector<Sync> drain(Reference r) {
  std::vector<Sync> out;
  for (; !r.empty(); r.pop()) out.push_back(r.top());
  return out;
}

// The queue under test and a reference given the same pairs.
class SyncQueueAgainstReference : public ::testing::Test {
 protected:
  void push(const Sync& s) {
    queue.push(s.first, s.second);
    reference.push(s);
  }
  SyncQueue queue;
  Reference reference;
  double now = 0;  // the last pair's time taken
};

TEST_F(SyncQueueAgainstReference, TakesEveryPairInTimeThenGrainOrderThroughPushesPopsAndClearOuts) {
  std::mt19937 rng(7);
  for (int round = 0; round < 200000; ++round) {
    const unsigned what = rng() % 100;
    if (reference.empty() || what < 55) {
      push(draw(rng, now));
    } else if (what < 99) {
      ASSERT_EQ(queue.front(), reference.top()) << "round " << round;
      now = reference.top().first;
      queue.pop();
      reference.pop();
    } else {
      // The stepper's clean-up of stale entries: one grain's pairs go.
      const std::uint32_t gone = rng() % 40;
      auto stale = [&](const Sync& e) { return e.second == gone; };
      queue.erase_if(stale);
      std::vector<Sync> kept = drain(reference);
      std::erase_if(kept, stale);
      reference = Reference(kept.begin(), kept.end());
    }
    ASSERT_EQ(queue.size(), reference.size()) << "round " << round;
  }
  while (!reference.empty()) {
    ASSERT_EQ(queue.front(), reference.top());
    queue.pop();
    reference.pop();
  }
  EXPECT_TRUE(queue.empty());
}

TEST_F(SyncQueueAgainstReference, TheNthTimeIsTheOneTheNthPopWouldTakeAndNothingIsTaken) {
  std::mt19937 rng(11);
  for (int round = 0; round < 1500; ++round) {
    for (int k = 0; k < 3; ++k) push(draw(rng, now));
    if (rng() % 2) {
      now = reference.top().first;
      queue.pop();
      reference.pop();
    }
    const std::size_t n = 1 + rng() % 20;
    const double horizon = now + double(rng() % 32) * 0.25;
    const std::vector<Sync> all = drain(reference);
    const double expected =
        n <= all.size() && all[n - 1].first <= horizon ? all[n - 1].first : horizon;
    ASSERT_EQ(queue.nth_time(n, horizon), expected) << "round " << round;
    ASSERT_EQ(queue.size(), all.size());
    ASSERT_EQ(queue.front(), reference.top());
  }
}

// A burst of pairs before the last one taken (many grains released at the members' time after
// the queue looked ahead): past the early heap's bound everything is spread again.
TEST_F(SyncQueueAgainstReference, ABurstOfPairsBeforeTheLastTakenComesFirstInOrder) {
  std::mt19937 rng(17);
  for (std::uint32_t id = 0; id < 3000; ++id) push({100.0 + double(rng() % 100), id});
  ASSERT_EQ(queue.front(), reference.top());  // the buckets have looked ahead to t >= 100
  for (int burst = 0; burst < 3; ++burst)
    for (std::uint32_t id = 0; id < 1000; ++id)
      push({double(burst) * 10 + double(rng() % 37) * 0.25, id});
  ASSERT_EQ(queue.size(), reference.size());
  for (; !reference.empty(); reference.pop()) {
    ASSERT_EQ(queue.front(), reference.top());
    queue.pop();
  }
  EXPECT_TRUE(queue.empty());
}

TEST(SyncQueue, AssignedFromUnorderedPairsItTakesThemInOrder) {
  std::mt19937 rng(13);
  for (std::size_t n : {0u, 1u, 2u, 5u, 17u, 5000u}) {
    std::vector<Sync> all;
    for (std::size_t i = 0; i < n; ++i) all.push_back(draw(rng, 3.0));
    SyncQueue queue;
    queue.push(100.0, 1);  // replaced
    queue.assign(all);
    std::sort(all.begin(), all.end());
    std::vector<Sync> taken;
    while (!queue.empty()) {
      taken.push_back(queue.front());
      queue.pop();
    }
    EXPECT_EQ(taken, all) << n << " pairs";
  }
}

}  // namespace
}  // namespace sedem
