#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/engine/state/pair_history.h"

namespace sedem {
namespace {

std::vector<PairHistory::Entry> pairs_from(std::uint32_t first, std::uint32_t count,
                                           double spring) {
  std::vector<PairHistory::Entry> out;
  for (std::uint32_t i = 0; i < count; ++i)
    out.push_back({PairHistory::key(first + i, first + 2 * i + 1), spring + i});
  return out;
}

// The table shrinks to a step's few contacts after a crowd and grows back within the buffer
// the crowd left: no entry of an earlier step may be found, nor lost, at any size.
TEST(PairHistory, ACrowdThenFewThenACrowdAgainFindsOnlyTheLastStep) {
  PairHistory h;
  const auto crowd = pairs_from(0, 1000, 1.0);
  const auto few = pairs_from(5000, 3, 2000.0);
  const auto again = pairs_from(10000, 700, 3000.0);
  h.assign(&crowd, 1);
  for (const auto& e : crowd) ASSERT_EQ(h.find(e.key), e.spring);
  h.assign(&few, 1);
  EXPECT_EQ(h.size(), 3u);
  for (const auto& e : few) ASSERT_EQ(h.find(e.key), e.spring);
  for (const auto& e : crowd) ASSERT_EQ(h.find(e.key), 0.0) << "a spring of two steps ago";
  h.assign(&again, 1);
  for (const auto& e : again) ASSERT_EQ(h.find(e.key), e.spring);
  for (const auto& e : few) ASSERT_EQ(h.find(e.key), 0.0);
  for (const auto& e : crowd) ASSERT_EQ(h.find(e.key), 0.0);
  const auto sorted = h.sorted_entries();
  ASSERT_EQ(sorted.size(), again.size());
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    EXPECT_EQ(sorted[i].key, again[i].key);  // `again`'s keys ascend
    EXPECT_EQ(sorted[i].spring, again[i].spring);
  }
  const std::vector<PairHistory::Entry> none;
  h.assign(&none, 1);
  EXPECT_EQ(h.size(), 0u);
  EXPECT_TRUE(h.sorted_entries().empty());
  for (const auto& e : again) ASSERT_EQ(h.find(e.key), 0.0);
}

}  // namespace
}  // namespace sedem
