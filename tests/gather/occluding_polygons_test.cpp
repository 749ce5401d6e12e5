#include "gather/occluding_polygons.h"

#include "gather/hemisphere_sampling.h"
#include "trace/form_factor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

namespace radview {
namespace {

// A square in the plane z = height, facing +z (counter-clockwise seen from above) or -z.
std::vector<Vec3> square(double x0, double y0, double side, double height, bool up = true) {
  std::vector<Vec3> s = {
      {x0, y0, height}, {x0 + side, y0, height}, {x0 + side, y0 + side, height}, {x0, y0 + side, height}};
  if (!up) std::swap(s[1], s[3]);
  return s;
}

std::vector<double> visibleFormFactors(const OccludingPolygons& polygons, const Vec3& x, const Vec3& n) {
  std::vector<double> F(polygons.size(), 0.0);
  polygons.visibleParts(x, n, polygons.facing(x), [&](size_t i, const std::vector<Vec3>& piece) {
    F[i] += formFactorAboveHorizon(x, n, piece.data(), piece.size());
  });
  return F;
}

TEST(OccludingPolygonsTest, AnUnhiddenPolygonHasLambertsFormFactorHorizonCutOrNot) {
  const std::vector<Vec3> floor = square(-1.0, -1.0, 2.0, 0.0);
  const OccludingPolygons polygons({floor});
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 200; ++k) {
    const Vec3 x(1.5 * u(random), 1.5 * u(random), 0.05 + std::abs(u(random)));
    const Vec3 n = glm::normalize(Vec3(u(random), u(random), u(random)));
    EXPECT_NEAR(visibleFormFactors(polygons, x, n)[0], pointToPolygonFormFactor(x, n, floor), 1e-12) << k;
  }
}

TEST(OccludingPolygonsTest, AParallelSquareHidesItsShadowFromTheOneBehind) {
  // Seen from x above both, the small square at z = 0.5 hides its central projection on the
  // large one at z = 0: what x sees of the large one is it less that projected square.
  const std::vector<Vec3> large = square(-2.0, -2.0, 4.0, 0.0), small = square(-0.2, -0.1, 0.3, 0.5);
  const OccludingPolygons polygons({large, small});
  const Vec3 x(0.1, 0.05, 1.0), n(0.0, 0.0, -1.0);
  std::vector<Vec3> shadow;
  for (const Vec3& v : small) shadow.push_back(x + (v - x) * (x.z / (x.z - v.z)));
  const std::vector<double> F = visibleFormFactors(polygons, x, n);
  // x is below neither: both face it.
  EXPECT_NEAR(F[1], pointToPolygonFormFactor(x, n, small), 1e-12);
  EXPECT_NEAR(F[0], pointToPolygonFormFactor(x, n, large) - pointToPolygonFormFactor(x, n, shadow), 1e-12);
  EXPECT_NEAR(F[0] + F[1], pointToPolygonFormFactor(x, n, large), 1e-12);
}

TEST(OccludingPolygonsTest, PolygonsThatCrossDoNotHideEachOther) {
  // A vertical square through a horizontal one: neither hides the other, so a ray through both
  // sees both, and each has its whole form factor.
  const std::vector<Vec3> floor = square(-1.0, -1.0, 2.0, 0.0);
  const std::vector<Vec3> wall = {{-0.5, 0.0, -0.5}, {0.5, 0.0, -0.5}, {0.5, 0.0, 0.5}, {-0.5, 0.0, 0.5}};
  const OccludingPolygons polygons({floor, wall});
  const Vec3 x(0.0, -1.0, 1.0);
  const Vec3 through = glm::normalize(Vec3(0.0, 1.2, -1.0));  // meets the wall, then the floor
  EXPECT_EQ(polygons.seenAlong(x, through, polygons.facing(x)), 3u);
  const Vec3 n = glm::normalize(Vec3(0.0, 1.0, -1.0));
  const std::vector<double> F = visibleFormFactors(polygons, x, n);
  EXPECT_NEAR(F[0], pointToPolygonFormFactor(x, n, floor), 1e-12);
  EXPECT_NEAR(F[1], pointToPolygonFormFactor(x, n, wall), 1e-12);
}

// The property the gather's control variate rests on: a value per polygon, taken in each
// direction from the polygons seenAlong() reports, integrates over the cosine-weighted
// hemisphere to the sum of those values times visibleParts()' form factors. Checked by Monte
// Carlo (5 standard errors) from points among boxes that hide one another, part behind the
// horizon, and a pair that crosses.
TEST(OccludingPolygonsTest, SeenAlongIntegratesToTheVisibleFormFactors) {
  std::vector<std::vector<Vec3>> scene = {
      square(-2.0, -2.0, 4.0, 0.0),                                                  // floor
      square(-2.0, -2.0, 4.0, 2.0, false),                                           // ceiling, facing down
      square(-0.6, -0.4, 0.5, 0.7),                                                  // a box's top
      {{-0.6, -0.4, 0.0}, {-0.1, -0.4, 0.0}, {-0.1, -0.4, 0.7}, {-0.6, -0.4, 0.7}},  // its front (-y)
      {{-0.1, -0.4, 0.0}, {-0.1, 0.1, 0.0}, {-0.1, 0.1, 0.7}, {-0.1, -0.4, 0.7}},    // its side (+x)
      square(0.3, 0.2, 0.6, 0.4),                                                    // a floating tile
      {{0.2, 0.5, 0.2}, {1.2, 0.5, 0.2}, {1.2, 0.5, 0.9}, {0.2, 0.5, 0.9}},          // crossing the tile
  };
  const OccludingPolygons polygons(scene);
  const double value[] = {0.7, 0.2, 1.3, 0.4, 0.9, 2.0, 0.5};
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Vec3 points[][2] = {{{0.4, -1.2, 0.01}, {0.0, 0.0, 1.0}},
                            {{0.0, 0.0, 1.99}, {0.0, 0.0, -1.0}},
                            {{-1.0, 1.0, 1.0}, glm::normalize(Vec3(1.0, -1.0, -0.3))},
                            {{1.5, -1.5, 0.3}, glm::normalize(Vec3(-1.0, 1.0, 0.2))}};
  for (const auto& [x, n] : points) {
    const std::vector<double> F = visibleFormFactors(polygons, x, n);
    double exact = 0.0;
    for (size_t i = 0; i < F.size(); ++i) exact += value[i] * F[i];
    const int samples = 400000;
    double sum = 0.0, squares = 0.0;
    for (int k = 0; k < samples; ++k) {
      double h = 0.0;
      for (uint64_t seen = polygons.seenAlong(x, cosineWeightedDirection(n, u(random), u(random)), polygons.facing(x));
           seen != 0; seen &= seen - 1)
        h += value[__builtin_ctzll(seen)];
      sum += h;
      squares += h * h;
    }
    const double mean = sum / samples, standardError = std::sqrt((squares / samples - mean * mean) / samples);
    std::printf("at (%.2f, %.2f, %.2f): closed form %.6f, Monte Carlo %.6f +- %.6f\n", x.x, x.y, x.z, exact, mean,
                standardError);
    EXPECT_LT(std::abs(mean - exact), 5.0 * standardError + 1e-9);
    EXPECT_GT(exact, 0.05);
  }
}

TEST(OccludingPolygonsTest, SeenAtAgreesWithSeenAlong) {
  const std::vector<Vec3> lamp = square(-0.25, -0.25, 0.5, 2.0, false), block = square(-0.3, -0.3, 0.4, 1.0, false);
  const OccludingPolygons polygons({lamp, block});
  const Vec3 x(0.0, 0.0, 0.0);
  const uint64_t facing = polygons.facing(x);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int hidden = 0;
  for (int k = 0; k < 2000; ++k) {
    const Vec3 target(-0.25 + 0.5 * u(random), -0.25 + 0.5 * u(random), 2.0);
    const bool seen = polygons.seenAt(x, target, facing, 0);
    EXPECT_EQ(seen, (polygons.seenAlong(x, glm::normalize(target - x), facing) & 1u) != 0) << k;
    // The block hides the lamp's points over it, (-0.3, 0.1)^2 at z = 1, so (-0.6, 0.2)^2 at z = 2.
    EXPECT_EQ(seen, !(target.x < 0.2 && target.y < 0.2)) << target.x << " " << target.y;
    hidden += !seen;
  }
  EXPECT_GT(hidden, 1000);
}

}  // namespace
}  // namespace radview
