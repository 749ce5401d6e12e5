#include "core/parallel_for.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace radview {
namespace {

TEST(ParallelForTest, RunsEveryIndexOnce) {
  std::vector<int> runs(100003, 0);
  parallelFor(
      runs.size(), [&](size_t i) { ++runs[i]; }, 7);
  for (size_t i = 0; i < runs.size(); ++i) ASSERT_EQ(runs[i], 1) << "index " << i;
}

// Bodies that throw at several indices: the caller gets the lowest one's exception, as from a
// plain loop, whichever thread met it first, and no index below it is skipped.
TEST(ParallelForTest, RethrowsTheLowestIndexsException) {
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<int> runs(20000, 0);
    try {
      parallelFor(
          runs.size(),
          [&](size_t i) {
            ++runs[i];
            if (i == 15000 || i == 7001 || i == 19999) throw std::runtime_error("index " + std::to_string(i));
          },
          3);
      FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "index 7001");
    }
    for (size_t i = 0; i <= 7001; ++i) ASSERT_EQ(runs[i], 1) << "index " << i;
  }
}

}  // namespace
}  // namespace radview
