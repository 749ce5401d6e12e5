#include "gather/gather_sequence.h"

#include "core/error.h"

#include <gtest/gtest.h>

#include <boost/random/sobol.hpp>

#include <cmath>
#include <set>
#include <vector>

namespace radview {
namespace {

// Coordinate `d` of pass `pass` as pixel `pixel` of gather `seed` takes it.
double coordinate(const GatherSequence& sequence, uint64_t seed, uint64_t pixel, uint32_t pass, int d) {
  const std::vector<uint32_t> point = sequence.point(pass);
  return GatherSequence::PixelPoint(point, seed, pixel, pass)(d);
}

// The first 2^k passes of coordinates (d0, d1) of one pixel: for every a + b = k, one point in
// each of the 2^a x 2^b strata of the unit square (a (0, k, 2)-net), as the unshifted Sobol
// points are; the pixel's shift must keep that.
bool isNet(const GatherSequence& sequence, uint64_t pixel, int d0, int d1, int k) {
  const uint32_t n = 1u << k;
  for (int a = 0; a <= k; ++a) {
    std::set<std::pair<int, int>> strata;
    for (uint32_t pass = 0; pass < n; ++pass)
      strata.insert({int(std::floor(coordinate(sequence, 3, pixel, pass, d0) * (1 << a))),
                     int(std::floor(coordinate(sequence, 3, pixel, pass, d1) * (1 << (k - a))))});
    if (strata.size() != n) return false;
  }
  return true;
}

TEST(GatherSequenceTest, EachPixelsFirstPassesOfTheFirstPairAreNets) {
  const GatherSequence sequence(7);
  for (uint64_t pixel : {0u, 1u, 12345u})
    for (int k : {2, 4, 6, 8}) EXPECT_TRUE(isNet(sequence, pixel, 0, 1, k)) << pixel << " " << k;
}

TEST(GatherSequenceTest, EveryCoordinateAloneIsStratified) {
  const GatherSequence sequence(7);
  for (int d = 0; d < 7; ++d) {
    std::set<int> strata;
    for (uint32_t pass = 0; pass < 64; ++pass) {
      const double u = coordinate(sequence, 3, 42, pass, d);
      ASSERT_GE(u, 0.0);
      ASSERT_LT(u, 1.0);
      strata.insert(int(u * 64));
    }
    EXPECT_EQ(strata.size(), 64u) << d;
  }
}

TEST(GatherSequenceTest, PixelsDifferByOneShiftPerCoordinate) {
  // The XOR of two pixels' points is the same at every pass: each pixel's points are the
  // sequence's, digitally shifted, and the shifts differ between pixels and seeds.
  const GatherSequence sequence(5);
  auto word = [&](uint64_t seed, uint64_t pixel, uint32_t pass, int d) {
    return uint32_t(std::ldexp(coordinate(sequence, seed, pixel, pass, d), 32));
  };
  for (int d = 0; d < 5; ++d) {
    const uint32_t shift = word(1, 10, 0, d) ^ word(1, 11, 0, d);
    EXPECT_NE(shift, 0u);
    for (uint32_t pass = 1; pass < 100; ++pass) EXPECT_EQ(word(1, 10, pass, d) ^ word(1, 11, pass, d), shift);
    EXPECT_NE(word(1, 10, 0, d), word(2, 10, 0, d));
  }
}

TEST(GatherSequenceTest, PointsAreBoostsSobolPoints) {
  // Pass i is Boost's point i in its own (Gray-code) order, whose first point is the
  // sequence's second: the set of the first 2^k points is the same either way.
  constexpr int kDims = 4;
  const GatherSequence sequence(kDims);
  boost::random::sobol_engine<uint32_t, 32> engine(kDims);
  std::set<std::vector<uint32_t>> boost, ours;
  boost.insert(std::vector<uint32_t>(kDims, 0u));
  for (int i = 0; i < 255; ++i) {
    std::vector<uint32_t> point(kDims);
    for (uint32_t& x : point) x = engine();
    boost.insert(point);
  }
  for (uint32_t pass = 0; pass < 256; ++pass) ours.insert(sequence.point(pass));
  EXPECT_EQ(ours, boost);
}

TEST(GatherSequenceTest, PassesTwoToTheEighteenApartTakeTheSamePointUnderAnotherShift) {
  const GatherSequence sequence(2);
  EXPECT_EQ(sequence.point(5), sequence.point(5 + (1u << 18)));
  EXPECT_NE(coordinate(sequence, 1, 7, 5, 0), coordinate(sequence, 1, 7, 5 + (1u << 18), 0));
}

TEST(SampleStreamTest, AtIsWhatNextReturnsThatManyCallsLater) {
  SampleStream stream = SampleStream::forKey(1, 2, 3);
  const SampleStream start = stream;
  for (uint64_t i = 0; i < 10; ++i) EXPECT_EQ(start.at(i), stream.next()) << i;
}

TEST(GatherSequenceTest, RefusesDimensionsBeyondTheTable) {
  EXPECT_THROW(GatherSequence(0), Error);
  EXPECT_THROW(GatherSequence(100000), Error);
}

}  // namespace
}  // namespace radview
