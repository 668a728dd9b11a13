#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "core/engine/state/disjoint_sets.h"

namespace sedem {
namespace {

// The same pairs in any order give the same roots, each the least index of its set: the
// projection numbers islands by them, so a run must not depend on the order pairs arrive in.
TEST(DisjointSets, RootsAreLeastIndicesWhateverThePairsOrder) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs = {{9, 4},   {4, 7}, {12, 3}, {3, 15},
                                                                {15, 12}, {1, 0}, {18, 11}};
  // Sets: {4,7,9} {3,12,15} {0,1} {11,18}; the rest alone.
  const std::vector<std::uint32_t> expected = {0,  0,  2, 3,  4,  5, 6,  4,  8,  4,
                                               10, 11, 3, 13, 14, 3, 16, 17, 11, 19};
  std::mt19937 shuffle(5);
  for (int order = 0; order < 20; ++order) {
    std::shuffle(pairs.begin(), pairs.end(), shuffle);
    DisjointSets sets;
    sets.assign(expected.size());
    for (auto [a, b] : pairs) sets.unite(a, b);
    for (std::uint32_t i = 0; i < expected.size(); ++i)
      ASSERT_EQ(sets.root(i), expected[i]) << "index " << i << ", order " << order;
    sets.flatten();
    for (std::uint32_t i = 0; i < expected.size(); ++i)
      ASSERT_EQ(sets.flat_root(i), expected[i]) << "index " << i << ", order " << order;
  }
}

// The carried steps reset only the sets they used: once every index of a set is single again,
// the structure is as fresh.
TEST(DisjointSets, ResettingEverySetMemberMakesItFresh) {
  DisjointSets sets;
  sets.assign(8);
  sets.unite(6, 2);
  sets.unite(2, 5);
  ASSERT_EQ(sets.root(6), 2u);
  for (std::uint32_t i : {6u, 2u, 5u}) sets.make_single(i);
  sets.unite(6, 7);
  EXPECT_EQ(sets.root(7), 6u);
  EXPECT_EQ(sets.root(5), 5u);
  EXPECT_EQ(sets.root(2), 2u);
}

}  // namespace
}  // namespace sedem
