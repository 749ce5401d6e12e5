#include "core/disjoint_sets.h"

#include <gtest/gtest.h>

#include <cstdint>

namespace radview {
namespace {

TEST(DisjointSets, JoinsAreTransitiveAndLeaveTheRestApart) {
  DisjointSets<uint32_t> sets(6);
  for (uint32_t i = 0; i < 6; ++i) EXPECT_EQ(sets.find(i), i);
  sets.join(0, 1);
  sets.join(3, 4);
  sets.join(1, 4);  // 0, 1, 3, 4 now one set
  EXPECT_EQ(sets.find(0), sets.find(3));
  EXPECT_EQ(sets.find(1), sets.find(4));
  EXPECT_NE(sets.find(0), sets.find(2));
  EXPECT_NE(sets.find(2), sets.find(5));
  sets.join(2, 2);  // a set joined with itself stays alone
  EXPECT_NE(sets.find(2), sets.find(0));
}

// A long chain joined one by one finds one representative for all, without recursion.
TEST(DisjointSets, LongChainsHaveOneRepresentative) {
  const size_t n = 1000000;
  DisjointSets<> sets(n);
  for (size_t i = 1; i < n; ++i) sets.join(i - 1, i);
  const size_t root = sets.find(0);
  for (size_t i = 0; i < n; i += 99991) EXPECT_EQ(sets.find(i), root);
}

}  // namespace
}  // namespace radview
