#include "geom/plane_segments.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace radview {
namespace {

TEST(PlaneSegments, ClipSegmentToConcavePolygonKeepsTheInsidePartsOnly) {
  // An L: the segment y = 1.5 crosses the notch [1, 2] x [1, 2].
  const std::vector<Vec2> ell = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  auto pieces = clipSegmentToPolygon({-1, 0.5}, {3, 0.5}, ell, 1e-9);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_NEAR(pieces[0].t0, 0.25, 1e-15);
  EXPECT_NEAR(pieces[0].t1, 0.75, 1e-15);
  pieces = clipSegmentToPolygon({-1, 1.5}, {3, 1.5}, ell, 1e-9);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_NEAR(pieces[0].t1, 0.5, 1e-15);
  // Along an edge (the notch's bottom, then on into the inside): only the inside part.
  pieces = clipSegmentToPolygon({2, 1}, {0.5, 1}, ell, 1e-9);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_NEAR(pieces[0].t0, 1.0 / 1.5, 1e-15);
  // Through a vertex, and entirely on the boundary.
  EXPECT_EQ(clipSegmentToPolygon({0, 0}, {2, 2}, ell, 1e-9).size(), 1u);
  EXPECT_TRUE(clipSegmentToPolygon({0, 0}, {2, 0}, ell, 1e-9).empty());
  EXPECT_TRUE(clipSegmentToPolygon({5, 5}, {6, 6}, ell, 1e-9).empty());
}

TEST(PlaneSegments, DistancesToASegmentAndABoundary) {
  EXPECT_DOUBLE_EQ(distanceToSegment({1, 2}, {0, 0}, {3, 0}), 2.0);
  EXPECT_DOUBLE_EQ(distanceToSegment({5, 4}, {0, 0}, {2, 0}), 5.0);  // beyond the end: to the end
  EXPECT_DOUBLE_EQ(distanceToSegment({1, 1}, {2, 2}, {2, 2}), std::sqrt(2.0));
  const std::vector<Vec2> square = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  EXPECT_DOUBLE_EQ(distanceToPolygonBoundary({1, 2}, square), 1.0);
  EXPECT_TRUE(strictlyInsidePolygon({1, 2}, square));
  EXPECT_FALSE(strictlyInsidePolygon({5, 2}, square));
}

TEST(PlaneSegments, AnEndIsPutOnTheOtherLineAlongItsOwn) {
  // From (0, 0) towards (1, 0.9): its line meets y = 1 at (10/9, 1), within reach.
  const Vec2 end = endOntoLine({0, 0}, {1, 0.9}, {-5, 1}, {5, 1}, 0.5);
  EXPECT_NEAR(end.x, 10.0 / 9.0, 1e-15);
  EXPECT_NEAR(end.y, 1.0, 1e-15);
  // Nearly parallel lines meet far away: the end is projected instead.
  const Vec2 projected = endOntoLine({0, 0.999}, {1, 0.9991}, {-5, 1}, {5, 1}, 0.01);
  EXPECT_NEAR(projected.x, 1.0, 1e-15);
  EXPECT_NEAR(projected.y, 1.0, 1e-15);
}

}  // namespace
}  // namespace radview
