#include "geom/triangulate_cgal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace radview {
namespace {

std::vector<Vec2> asPolygon(const std::array<Vec2, 4>& quad) { return {quad.begin(), quad.end()}; }

// The shortcut must be CGAL's answer exactly: the same diagonal, the same triangles in the same
// order and rotation, which every later step (pieces, their packing) follows.
void expectSameAsCgal(const std::array<Vec2, 4>& quad) {
  const auto shortcut = convexQuadDelaunay(quad);
  ASSERT_TRUE(shortcut.has_value());
  const std::vector<std::array<int, 3>> cgal = constrainedDelaunayTriangulation(asPolygon(quad));
  ASSERT_EQ(cgal.size(), 2u);
  EXPECT_EQ(cgal[0], (*shortcut)[0]);
  EXPECT_EQ(cgal[1], (*shortcut)[1]);
}

bool strictlyConvex(const std::array<Vec2, 4>& q) {
  for (int i = 0; i < 4; ++i) {
    const Vec2 a = q[(i + 1) % 4] - q[i], b = q[(i + 2) % 4] - q[(i + 1) % 4];
    if (a.x * b.y - a.y * b.x <= 0.0) return false;  // small integers: exact
  }
  return true;
}

TEST(ConvexQuadDelaunay, RectanglesAndSquaresInEveryRotationAreCgalsTieBreak) {
  // Every corner of a rectangle is on one circle: CGAL's tie-break alone decides.
  for (const Vec2 size : {Vec2(4, 3), Vec2(4, 4), Vec2(1, 7), Vec2(1024, 1)}) {
    const std::array<Vec2, 4> rectangle{Vec2(0, 0), Vec2(size.x, 0), size, Vec2(0, size.y)};
    for (int r = 0; r < 4; ++r) {
      std::array<Vec2, 4> q;
      for (int i = 0; i < 4; ++i) q[i] = rectangle[(i + r) % 4];
      expectSameAsCgal(q);
      // Turned a quarter and a half: other corners are lexicographically largest.
      for (Vec2& p : q) p = Vec2(-p.y, p.x);
      expectSameAsCgal(q);
      for (Vec2& p : q) p = Vec2(-p.y, p.x);
      expectSameAsCgal(q);
    }
  }
}

TEST(ConvexQuadDelaunay, RandomIntegerQuadsMatchCgal) {
  // Small integer corners make cocircular and near-cocircular quads common; large ones are the
  // 2^40 grid SurfaceTriangulation rounds to.
  std::mt19937 rng(7);
  int compared = 0, ties = 0;
  for (const int range : {3, 6, 1 << 20}) {
    std::uniform_int_distribution<int> coordinate(-range, range);
    for (int trial = 0; trial < 40000; ++trial) {
      std::array<Vec2, 4> q;
      for (Vec2& p : q) p = Vec2(coordinate(rng), coordinate(rng));
      if (range > 100)
        for (Vec2& p : q) p *= 1 << 20;
      if (!strictlyConvex(q)) {
        // Not strictly convex, counter-clockwise: no shortcut (CGAL decides, or refuses).
        EXPECT_FALSE(convexQuadDelaunay(q).has_value());
        continue;
      }
      expectSameAsCgal(q);
      ++compared;
      const Vec2 a = q[0], b = q[1], c = q[2], d = q[3];
      auto lifted = [&](Vec2 p) { return glm::dot(p - d, p - d); };
      const double incircle = (a.x - d.x) * ((b.y - d.y) * lifted(c) - lifted(b) * (c.y - d.y)) -
                              (a.y - d.y) * ((b.x - d.x) * lifted(c) - lifted(b) * (c.x - d.x)) +
                              lifted(a) * ((b.x - d.x) * (c.y - d.y) - (b.y - d.y) * (c.x - d.x));
      if (range < 100 && incircle == 0.0) ++ties;  // exact for these small integers
    }
  }
  EXPECT_GT(compared, 5000);
  EXPECT_GT(ties, 100);  // the tie-break was exercised, not only the clear cases
}

TEST(ConvexQuadDelaunay, DegenerateOrClockwiseQuadsAreLeftToCgal) {
  EXPECT_FALSE(convexQuadDelaunay({Vec2(0, 0), Vec2(0, 1), Vec2(1, 1), Vec2(1, 0)}).has_value());  // clockwise
  EXPECT_FALSE(convexQuadDelaunay({Vec2(0, 0), Vec2(1, 0), Vec2(2, 0), Vec2(1, 1)}).has_value());  // collinear
  EXPECT_FALSE(convexQuadDelaunay({Vec2(0, 0), Vec2(2, 0), Vec2(1, 0.5), Vec2(1, 2)}).has_value());  // reflex
  EXPECT_FALSE(convexQuadDelaunay({Vec2(0, 0), Vec2(0, 0), Vec2(1, 1), Vec2(0, 1)}).has_value());  // repeated
}

}  // namespace
}  // namespace radview
