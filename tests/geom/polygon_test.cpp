#include "geom/polygon.h"

#include "core/error.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <random>
#include <sstream>

namespace radview {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::vector<Vec3> square() { return {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}; }
// L of three unit squares: [0,2]x[0,1] plus [0,1]x[1,2].
std::vector<Vec3> lShape() { return {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}}; }
// A comb: a spine 1 high along the bottom with `teeth` teeth 0.5 wide and 3 tall on it.
std::vector<Vec3> comb(int teeth) {
  std::vector<Vec3> out{{0, 0, 0}, {teeth - 0.5, 0, 0}};
  for (int t = teeth - 1; t >= 0; --t) {
    out.push_back({t + 0.5, 4, 0});
    out.push_back({t + 0.0, 4, 0});
    if (t > 0) {
      out.push_back({t + 0.0, 1, 0});
      out.push_back({t - 0.5, 1, 0});
    }
  }
  return out;
}

// Tilts a polygon of the z = 0 plane into a general plane (rotation + translation).
std::vector<Vec3> tilted(const std::vector<Vec3>& flat) {
  const glm::dmat3 rotation = glm::dmat3(glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(Vec3(1, 2, 3))));
  std::vector<Vec3> out;
  for (const Vec3& p : flat) out.push_back(rotation * p + Vec3(10, -4, 7));
  return out;
}

std::string describe(const std::vector<Vec3>& polygon) {
  std::ostringstream os;
  os.precision(17);
  for (const Vec3& p : polygon) os << p << ' ';
  return os.str();
}

// Even-odd point-in-polygon test in the polygon's plane frame (independent of CGAL).
bool insidePolygon(const std::vector<Vec2>& polygon, const Vec2& p) {
  bool inside = false;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Vec2 a = polygon[i], b = polygon[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
  }
  return inside;
}

double cross2(const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; }

bool insideTriangle(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& p) {
  return cross2(b - a, p - a) > 0 && cross2(c - b, p - b) > 0 && cross2(a - c, p - c) > 0;
}

// The triangulation covers exactly the polygon: triangles have the polygon's orientation,
// their areas sum to its area, and random points of its bounding box lie in exactly one
// triangle when inside the polygon and in none when outside.
void expectExactCover(const std::vector<Vec3>& polygon, const std::vector<std::array<int, 3>>& triangles) {
  SCOPED_TRACE("polygon: " + describe(polygon));
  ASSERT_EQ(triangles.size(), polygon.size() - 2);
  const Vec3 n = unitNormal(polygon);
  double sum = 0.0;
  for (const auto& t : triangles) {
    const std::vector<Vec3> corners{polygon[t[0]], polygon[t[1]], polygon[t[2]]};
    EXPECT_GT(glm::dot(newellNormal(corners), n), 0.0) << "triangle " << t[0] << ',' << t[1] << ',' << t[2];
    sum += area(corners);
  }
  EXPECT_NEAR(sum, area(polygon), 1e-12 * area(polygon));

  const PlaneFrame frame = planeFrame(polygon);
  std::vector<Vec2> flat;
  Vec2 lo(1e300), hi(-1e300);
  for (const Vec3& p : polygon) {
    flat.push_back(frame.project(p));
    lo = glm::min(lo, flat.back());
    hi = glm::max(hi, flat.back());
  }
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int s = 0; s < 2000; ++s) {
    const Vec2 p = lo + Vec2(unit(rng), unit(rng)) * (hi - lo);
    int covering = 0;
    for (const auto& t : triangles) covering += insideTriangle(flat[t[0]], flat[t[1]], flat[t[2]], p);
    ASSERT_EQ(covering, insidePolygon(flat, p) ? 1 : 0) << "sample (" << p.x << ", " << p.y << ")";
  }
}

TEST(PolygonTest, NewellNormalAndAreaOfUnitSquare) {
  EXPECT_EQ(newellNormal(square()), Vec3(0, 0, 2));
  EXPECT_EQ(unitNormal(square()), Vec3(0, 0, 1));
  EXPECT_DOUBLE_EQ(area(square()), 1.0);
}

TEST(PolygonTest, AreaIsExactFarFromTheOrigin) {
  std::vector<Vec3> far = square();
  for (Vec3& p : far) p += Vec3(1e8, -3e8, 2e8);
  EXPECT_DOUBLE_EQ(area(far), 1.0);
}

TEST(PolygonTest, AreaAndCentroidOfAnLShape) {
  const std::vector<Vec3> l = tilted(lShape());
  EXPECT_NEAR(area(l), 3.0, 1e-12);
  // Two unit squares centred at (0.5,0.5), (1.5,0.5) and one at (0.5,1.5): mean (5/6, 5/6).
  const std::vector<Vec3> expected = tilted({{5.0 / 6.0, 5.0 / 6.0, 0.0}});
  EXPECT_NEAR(glm::distance(centroid(l), expected[0]), 0.0, 1e-12);
}

TEST(PolygonTest, CentroidOfDegeneratePolygonIsVertexMean) {
  EXPECT_EQ(centroid({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}), Vec3(1, 0, 0));
  EXPECT_EQ(unitNormal({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}), Vec3(0.0));
}

TEST(PolygonTest, PlanarityErrorOfTwistedQuadIsAQuarterOfTheLift) {
  // Unit square with one corner lifted by h: the mean plane leaves every corner about h/4 off.
  const double h = 1e-3;
  const std::vector<Vec3> twisted{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, h}};
  EXPECT_NEAR(planarityError(twisted), h / 4.0, 1e-6 * h);
  EXPECT_NEAR(planarityError(tilted(lShape())), 0.0, 1e-13);
}

TEST(PolygonTest, ConvexityClassifiesCorners) {
  EXPECT_TRUE(isConvex(square()));
  std::vector<Vec3> clockwise = square();
  std::reverse(clockwise.begin(), clockwise.end());
  EXPECT_TRUE(isConvex(clockwise));  // convex about its own normal
  const std::vector<Vec3> withMidpoint{{0, 0, 0}, {0.5, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  EXPECT_TRUE(isConvex(withMidpoint));
  EXPECT_FALSE(isStrictlyConvex(withMidpoint));
  EXPECT_TRUE(isStrictlyConvex(square()));
  EXPECT_FALSE(isConvex(lShape()));
  std::vector<Vec3> pentagram;
  for (int i = 0; i < 5; ++i) pentagram.push_back({std::cos(4 * kPi * i / 5), std::sin(4 * kPi * i / 5), 0});
  EXPECT_FALSE(isConvex(pentagram));                                     // every turn is left, but it winds twice
  EXPECT_FALSE(isConvex({{0, 0, 0}, {2, 0, 0}, {1, 0, 0}, {1, 1, 0}}));  // folds back on itself
  EXPECT_FALSE(isConvex({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}));             // degenerate
}

TEST(PolygonTest, PlaneFrameIsRightHandedAndKeepsOrientation) {
  const std::vector<Vec3> l = tilted(lShape());
  const PlaneFrame f = planeFrame(l);
  EXPECT_NEAR(glm::dot(f.u, f.v), 0.0, 1e-15);
  EXPECT_NEAR(glm::length(f.u), 1.0, 1e-15);
  EXPECT_NEAR(glm::distance(glm::cross(f.u, f.v), f.n), 0.0, 1e-15);
  double signedArea = 0.0;
  for (size_t i = 0; i < l.size(); ++i) signedArea += cross2(f.project(l[i]), f.project(l[(i + 1) % l.size()]));
  EXPECT_NEAR(0.5 * signedArea, 3.0, 1e-12);
  EXPECT_THROW(planeFrame({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}), Error);
}

TEST(PolygonTest, StrictlyConvexPolygonIsAFanFromVertexZero) {
  const auto triangles = triangulatePolygon(tilted(square()));
  ASSERT_EQ(triangles.size(), 2u);
  EXPECT_EQ(triangles[0], (std::array<int, 3>{0, 1, 2}));
  EXPECT_EQ(triangles[1], (std::array<int, 3>{0, 2, 3}));
}

TEST(PolygonTest, ConcavePolygonsAreCoveredExactlyWithTheirOrientation) {
  for (const auto& polygon : {lShape(), comb(2), comb(5), tilted(lShape()), tilted(comb(4))}) {
    expectExactCover(polygon, triangulatePolygon(polygon));
    std::vector<Vec3> reversed(polygon.rbegin(), polygon.rend());
    expectExactCover(reversed, triangulatePolygon(reversed));
  }
}

TEST(PolygonTest, CollinearCornersGetNoZeroAreaTriangle) {
  const std::vector<Vec3> withMidpoints{{0, 0, 0}, {0.5, 0, 0}, {1, 0, 0}, {1, 0.5, 0},
                                        {1, 1, 0}, {0.5, 1, 0}, {0, 1, 0}, {0, 0.5, 0}};
  const auto triangles = triangulatePolygon(withMidpoints);
  expectExactCover(withMidpoints, triangles);
  for (const auto& t : triangles) EXPECT_GT(area({withMidpoints[t[0]], withMidpoints[t[1]], withMidpoints[t[2]]}), 0.1);
}

// Property: random star-shaped (so simple, mostly concave) polygons in random planes.
TEST(PolygonTest, RandomStarShapedPolygonsAreCoveredExactly) {
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 3 + int(unit(rng) * 30);
    std::vector<Vec3> flat;
    for (int i = 0; i < n; ++i) {
      const double angle = 2 * kPi * (i + 0.8 * unit(rng)) / n, radius = 0.2 + unit(rng);
      flat.push_back({radius * std::cos(angle), radius * std::sin(angle), 0});
    }
    const std::vector<Vec3> polygon = tilted(flat);
    SCOPED_TRACE("trial " + std::to_string(trial));
    expectExactCover(polygon, triangulatePolygon(polygon));
  }
}

TEST(PolygonTest, BadPolygonsThrow) {
  EXPECT_THROW(triangulatePolygon({{0, 0, 0}, {1, 0, 0}}), Error);
  EXPECT_THROW(triangulatePolygon({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}), Error);  // zero area
  EXPECT_THROW(triangulatePolygon({{0, 0, 0}, {1, 0, 0}, {NAN, 1, 0}}), Error);
  EXPECT_THROW(triangulatePolygon({{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0.5, 0}}),
               Error);  // crossing
  // A vertex repeated, and a vertex touching an edge (two loops sharing a point).
  EXPECT_THROW(triangulatePolygon({{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {1, 1, 0}, {0, 2, 0}, {1, 1, 0}}), Error);
  EXPECT_THROW(triangulatePolygon({{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {1, 0, 0}, {0, 2, 0}}), Error);
  try {
    triangulatePolygon({{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0.5, 0}});
    ADD_FAILURE() << "a self-intersecting polygon was triangulated";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("not simple"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace radview
