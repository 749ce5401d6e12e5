#include "trace/form_factor.h"

#include "geom/polygon.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <random>
#include <sstream>

namespace radview {
namespace {

constexpr double kPi = 3.14159265358979323846;

// --- An independent reference: brute-force Gauss-Legendre quadrature of the definition ----

struct GaussLegendre {
  std::vector<double> x, w;  // on [0, 1]
};

// Nodes by Newton's iteration on the Legendre polynomial P_m (three-term recurrence).
GaussLegendre gaussLegendre(int m) {
  GaussLegendre rule;
  for (int i = 0; i < m; ++i) {
    double z = std::cos(kPi * (i + 0.75) / (m + 0.5)), derivative = 0.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = z;
      for (int k = 2; k <= m; ++k) {
        const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      derivative = m * (z * p1 - p0) / (z * z - 1.0);
      const double step = p1 / derivative;
      z -= step;
      if (std::abs(step) < 1e-16) break;
    }
    rule.x.push_back(0.5 * (1.0 - z));
    rule.w.push_back(1.0 / ((1.0 - z * z) * derivative * derivative));
  }
  return rule;
}

// The kernel of the form factor, cos(theta) cos(theta') / (pi r^2), with the receiver's
// horizon and the emitter's back side cut off.
double kernel(const Vec3& x, const Vec3& n, const Vec3& p, const Vec3& N) {
  const Vec3 d = p - x;
  const double r2 = glm::dot(d, d);
  return std::max(0.0, glm::dot(n, d)) * std::max(0.0, -glm::dot(N, d)) / (kPi * r2 * r2);
}

// Integral of f over triangle (a, b, c), split regularly into k^2 triangles, each mapped from
// the unit square (Duffy: p = A + u (B - A) + u v (C - B), Jacobian u * 2 area).
template <typename F>
double integrateTriangle(const Vec3& a, const Vec3& b, const Vec3& c, int k, const GaussLegendre& rule, F f) {
  auto at = [&](int i, int j) { return a + (double(i) / k) * (b - a) + (double(j) / k) * (c - a); };
  double sum = 0.0;
  auto piece = [&](const Vec3& A, const Vec3& B, const Vec3& C) {
    const double twiceArea = glm::length(glm::cross(B - A, C - A));
    for (size_t i = 0; i < rule.x.size(); ++i)
      for (size_t j = 0; j < rule.x.size(); ++j) {
        const double u = rule.x[i], v = rule.x[j];
        sum += rule.w[i] * rule.w[j] * u * twiceArea * f(A + u * (B - A) + u * v * (C - B));
      }
  };
  for (int i = 0; i < k; ++i)
    for (int j = 0; i + j < k; ++j) {
      piece(at(i, j), at(i + 1, j), at(i, j + 1));
      if (i + j + 1 < k) piece(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return sum;
}

// Like integrateTriangle, but a triangle straddling the receiver's horizon plane (where the
// clipped kernel has a kink) is split into four, down to `depth` levels: the straddling area,
// and with it the error, halves with each level.
template <typename F>
double integrateAcrossHorizon(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& x, const Vec3& n, int depth,
                              const GaussLegendre& rule, F f) {
  const double sa = glm::dot(a - x, n), sb = glm::dot(b - x, n), sc = glm::dot(c - x, n);
  const bool straddles = std::min({sa, sb, sc}) < 0 && std::max({sa, sb, sc}) > 0;
  if (!straddles || depth == 0) return integrateTriangle(a, b, c, 1, rule, f);
  const Vec3 ab = 0.5 * (a + b), bc = 0.5 * (b + c), ca = 0.5 * (c + a);
  return integrateAcrossHorizon(a, ab, ca, x, n, depth - 1, rule, f) +
         integrateAcrossHorizon(ab, b, bc, x, n, depth - 1, rule, f) +
         integrateAcrossHorizon(ca, bc, c, x, n, depth - 1, rule, f) +
         integrateAcrossHorizon(ab, bc, ca, x, n, depth - 1, rule, f);
}

// Quadrature of the form factor over a polygon that is star-shaped about `centre` (a fan),
// each fan triangle cut into k^2 pieces and refined where it crosses the horizon.
double quadratureFormFactor(const Vec3& x, const Vec3& n, const std::vector<Vec3>& polygon, const Vec3& centre, int k,
                            int order, int horizonDepth = 0) {
  const GaussLegendre rule = gaussLegendre(order);
  const Vec3 N = unitNormal(polygon);
  auto f = [&](const Vec3& p) { return kernel(x, n, p, N); };
  double F = 0.0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Vec3 a = centre, b = polygon[i], c = polygon[(i + 1) % polygon.size()];
    auto at = [&](int s, int t) { return a + (double(s) / k) * (b - a) + (double(t) / k) * (c - a); };
    for (int s = 0; s < k; ++s)
      for (int t = 0; s + t < k; ++t) {
        F += integrateAcrossHorizon(at(s, t), at(s + 1, t), at(s, t + 1), x, n, horizonDepth, rule, f);
        if (s + t + 1 < k)
          F += integrateAcrossHorizon(at(s + 1, t), at(s + 1, t + 1), at(s, t + 1), x, n, horizonDepth, rule, f);
      }
  }
  return F;
}

// --- Closed forms -----------------------------------------------------------------------

// Differential area under the corner of a parallel a x b rectangle at height h, facing it.
double parallelCornerF(double a, double b, double h) {
  const double A = a / h, B = b / h, sA = std::sqrt(1 + A * A), sB = std::sqrt(1 + B * B);
  return (A / sA * std::atan(B / sA) + B / sB * std::atan(A / sB)) / (2 * kPi);
}

// Differential area in the plane of one edge of a perpendicular a (height) x b (width)
// rectangle, at distance c from it, in line with one of its perpendicular edges; X = a/b,
// Y = c/b. (Howell's catalogue, configuration B-3; checked against quadrature below.)
double perpendicularEdgeF(double a, double b, double c) {
  const double X = a / b, Y = c / b, s = std::sqrt(X * X + Y * Y);
  return (std::atan(1 / Y) - Y / s * std::atan(1 / s)) / (2 * kPi);
}

// corner, corner + U, corner + U + V, corner + V: faces U x V.
std::vector<Vec3> rectangle(const Vec3& corner, const Vec3& U, const Vec3& V) {
  return {corner, corner + U, corner + U + V, corner + V};
}

std::string describe(const Vec3& x, const Vec3& n, const std::vector<Vec3>& polygon) {
  std::ostringstream os;
  os.precision(17);
  os << "x=" << x << " n=" << n << " polygon:";
  for (const Vec3& p : polygon) os << ' ' << p;
  return os.str();
}

// --- Random configurations ---------------------------------------------------------------

struct Random {
  std::mt19937 rng;
  explicit Random(unsigned seed) : rng(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
  Vec3 direction() {
    const double z = uniform(-1, 1), phi = uniform(0, 2 * kPi), r = std::sqrt(1 - z * z);
    return {r * std::cos(phi), r * std::sin(phi), z};
  }
  // A polygon star-shaped about `centre` (angular gaps below pi), in a random plane: convex on
  // an ellipse, or with radii jittered (usually concave).
  std::vector<Vec3> polygon(const Vec3& centre, bool convex) {
    const Vec3 N = direction();
    const Vec3 u = glm::normalize(glm::cross(N, std::abs(N.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0)));
    const Vec3 v = glm::cross(N, u);
    const int count = 3 + int(uniform(0, convex ? 6 : 12));
    const double ru = uniform(0.5, 2), rv = uniform(0.5, 2);
    std::vector<Vec3> out;
    for (int i = 0; i < count; ++i) {
      const double angle = 2 * kPi * (i + uniform(0, 0.4)) / count, scale = convex ? 1.0 : uniform(0.3, 1.0);
      out.push_back(centre + scale * (ru * std::cos(angle) * u + rv * std::sin(angle) * v));
    }
    return out;  // CCW about N
  }
};

// --- Closed-form cases -------------------------------------------------------------------

TEST(FormFactorTest, CoaxialParallelSquareIsFourCornerRectangles) {
  for (double a : {0.1, 0.5, 1.0, 7.0})
    for (double h : {0.01, 0.3, 1.0, 20.0}) {
      const auto square = rectangle({-a, -a, h}, {0, 2 * a, 0}, {2 * a, 0, 0});  // faces -z
      const double expected = 4 * parallelCornerF(a, a, h);
      EXPECT_NEAR(pointToPolygonFormFactor({0, 0, 0}, {0, 0, 1}, square), expected, 1e-14 + 1e-13 * expected)
          << "a=" << a << " h=" << h;
    }
}

TEST(FormFactorTest, PointBelowTheCornerOfAParallelRectangle) {
  for (double a : {0.2, 1.0, 3.0})
    for (double b : {0.5, 2.0})
      for (double h : {0.1, 1.0, 5.0}) {
        const double expected = parallelCornerF(a, b, h);
        const auto rect = rectangle({0, 0, h}, {0, b, 0}, {a, 0, 0});
        EXPECT_NEAR(pointToPolygonFormFactor({0, 0, 0}, {0, 0, 1}, rect), expected, 1e-13 * expected);
      }
}

TEST(FormFactorTest, PerpendicularRectangleFormulaHoldsAndIsMatched) {
  // Receiver at the origin facing +z; the wall y = c, x in [0, b], z in [0, a], facing -y: its
  // bottom edge lies on the receiver's horizon.
  double worstFormula = 0.0, worstOurs = 0.0;
  for (double a : {0.3, 1.0, 4.0})
    for (double b : {0.5, 2.0})
      for (double c : {0.2, 1.0, 3.0}) {
        const auto wall = rectangle({0, c, 0}, {b, 0, 0}, {0, 0, a});
        const double formula = perpendicularEdgeF(a, b, c);
        // First the formula against the definition (the kernel is smooth here: the horizon is
        // an edge of the wall).
        const double quadrature = quadratureFormFactor({0, 0, 0}, {0, 0, 1}, wall, centroid(wall), 8, 16);
        EXPECT_NEAR(formula, quadrature, 1e-9 * formula) << "a=" << a << " b=" << b << " c=" << c;
        const double F = pointToPolygonFormFactor({0, 0, 0}, {0, 0, 1}, wall);
        EXPECT_NEAR(F, formula, 1e-13 * formula);
        worstFormula = std::max(worstFormula, std::abs(formula - quadrature) / formula);
        worstOurs = std::max(worstOurs, std::abs(F - formula) / formula);
      }
  std::printf("perpendicular rectangle: formula vs quadrature %.2e, F vs formula %.2e (max relative)\n", worstFormula,
              worstOurs);
}

TEST(FormFactorTest, RegularPolygonsApproachTheCoaxialDisc) {
  // Coaxial disc: F = R^2 / (h^2 + R^2). An inscribed regular N-gon misses, at angle phi from
  // an apothem, R - rho(phi) ~ R (pi^2 / (2 N^2) - phi^2 / 2), pi^2 / (3 N^2) on average, at
  // dF/dR = 2 R h^2 / (h^2 + R^2)^2: so N^2 (F_disc - F_N) -> 2 R^2 h^2 / (h^2 + R^2)^2 pi^2 / 3.
  const double R = 1.3, h = 0.7, disc = R * R / (h * h + R * R);
  const double limit = 2 * R * R * h * h / ((h * h + R * R) * (h * h + R * R)) * kPi * kPi / 3;
  for (int N : {64, 256, 1024, 4096}) {
    std::vector<Vec3> ngon;
    for (int i = 0; i < N; ++i) ngon.push_back({R * std::cos(-2 * kPi * i / N), R * std::sin(-2 * kPi * i / N), h});
    const double deficit = disc - pointToPolygonFormFactor({0, 0, 0}, {0, 0, 1}, ngon);
    EXPECT_NEAR(double(N) * N * deficit / limit, 1.0, 20.0 / (N * N) + 1e-5) << "N=" << N;
  }
}

// --- Property tests against the quadrature --------------------------------------------------

// Random convex and concave polygons, receivers in front at random orientations (about half of
// them with the polygon across their horizon).
TEST(FormFactorTest, RandomConfigurationsMatchQuadrature) {
  Random random(1234);
  double worstSmooth = 0.0, worstClipped = 0.0;
  int smoothCount = 0, clippedCount = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const Vec3 centre(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1));
    const std::vector<Vec3> polygon = random.polygon(centre, trial % 2 == 0);
    const Vec3 N = unitNormal(polygon);
    const Vec3 x = centre + random.uniform(0.5, 3) * N + random.uniform(-2, 2) * random.direction();
    if (glm::dot(x - centre, N) < 0.2) continue;  // keep x clearly in front
    Vec3 n = random.direction();
    if (glm::dot(n, centre - x) < 0) n = -n;
    bool crossesHorizon = false;
    for (const Vec3& p : polygon) crossesHorizon |= glm::dot(p - x, n) < 0;
    const double F = pointToPolygonFormFactor(x, n, polygon);
    // The clipped kernel has a kink along the horizon: refine there.
    const double reference = crossesHorizon ? quadratureFormFactor(x, n, polygon, centre, 4, 12, 8)
                                            : quadratureFormFactor(x, n, polygon, centre, 4, 12);
    const double error = std::abs(F - reference);
    ++(crossesHorizon ? clippedCount : smoothCount);
    (crossesHorizon ? worstClipped : worstSmooth) =
        std::max(crossesHorizon ? worstClipped : worstSmooth, error / std::max(reference, 1e-3));
    ASSERT_NEAR(F, reference, 1e-10 * std::max(reference, 1e-3))
        << "trial " << trial << ": " << describe(x, n, polygon);
  }
  std::printf(
      "max error vs quadrature, relative to max(F, 1e-3): whole polygon above the horizon %.2e "
      "(%d cases), across it %.2e (%d cases)\n",
      worstSmooth, smoothCount, worstClipped, clippedCount);
  EXPECT_GT(smoothCount, 50);
  EXPECT_GT(clippedCount, 50);
}

TEST(FormFactorTest, SplittingAPolygonAddsUp) {
  Random random(99);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 centre(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1));
    const std::vector<Vec3> polygon = random.polygon(centre, true);
    const Vec3 x = centre + random.uniform(0.1, 2) * unitNormal(polygon) + random.uniform(-1, 1) * random.direction();
    const Vec3 n = random.direction();
    // Cut along the chord from vertex 0 to vertex k.
    const size_t k = polygon.size() / 2 + 1;
    if (k >= polygon.size()) continue;
    const std::vector<Vec3> first(polygon.begin(), polygon.begin() + k + 1);
    std::vector<Vec3> second(polygon.begin() + k, polygon.end());
    second.push_back(polygon[0]);
    const double whole = pointToPolygonFormFactor(x, n, polygon);
    const double parts = pointToPolygonFormFactor(x, n, first) + pointToPolygonFormFactor(x, n, second);
    EXPECT_NEAR(whole, parts, 1e-14) << describe(x, n, polygon);
  }
}

// A patch of several polygons: the outline sum where the receiver sees all of it, the clipped
// polygons where its horizon cuts it; either way the sum of the polygons' own form factors.
TEST(FormFactorTest, PatchOfPolygonsIsTheSumOfItsPolygons) {
  Random random(7);
  int cut = 0, whole = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Vec3 centre(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1));
    const std::vector<Vec3> polygon = random.polygon(centre, true);
    // A fan of triangles from the centroid: every inner edge is shared by two of them.
    const Vec3 middle = centroid(polygon);
    std::vector<std::vector<Vec3>> fan;
    for (size_t i = 0; i < polygon.size(); ++i) fan.push_back({middle, polygon[i], polygon[(i + 1) % polygon.size()]});
    const PatchFormFactor patch(fan);
    const Vec3 x = centre + random.uniform(0.05, 2) * unitNormal(polygon) + random.uniform(-1, 1) * random.direction();
    const Vec3 n = random.direction();
    double sum = 0.0;
    bool horizonCuts = false;
    for (const auto& triangle : fan) {
      sum += pointToPolygonFormFactor(x, n, triangle);
      for (const Vec3& v : triangle) horizonCuts |= glm::dot(v - x, n) < 0.0;
    }
    (horizonCuts ? cut : whole) += 1;
    EXPECT_NEAR(patch.from(x, n), sum, 1e-13) << describe(x, n, polygon);
    EXPECT_NEAR(patch.from(x, n), pointToPolygonFormFactor(x, n, polygon), 1e-13) << describe(x, n, polygon);
  }
  EXPECT_GT(cut, 25);  // both ways of computing it were exercised
  EXPECT_GT(whole, 25);
}

// A1 F(1->2) = A2 F(2->1): the point form factor integrated over each polygon.
TEST(FormFactorTest, ReciprocityBetweenTwoPolygons) {
  const auto floor = rectangle({0, 0, 0}, {1, 0, 0}, {0, 1.5, 0});                           // faces +z
  const auto tilted = std::vector<Vec3>{{0.2, 0.1, 1.0}, {0.3, 1.2, 0.8}, {1.4, 0.9, 1.3}};  // faces down
  ASSERT_LT(unitNormal(tilted).z, 0.0);
  const GaussLegendre rule = gaussLegendre(10);
  auto areaTimesF = [&](const std::vector<Vec3>& from, const std::vector<Vec3>& to) {
    const Vec3 n = unitNormal(from);
    double sum = 0.0;
    for (size_t i = 1; i + 1 < from.size(); ++i)
      sum += integrateTriangle(from[0], from[i], from[i + 1], 4, rule,
                               [&](const Vec3& x) { return pointToPolygonFormFactor(x, n, to); });
    return sum;
  };
  const double A1F12 = areaTimesF(floor, tilted), A2F21 = areaTimesF(tilted, floor);
  EXPECT_NEAR(A1F12, A2F21, 1e-9 * A1F12);
}

// --- Edge cases: horizon, back side, touching ------------------------------------------------

TEST(FormFactorTest, EmitterBelowTheHorizonOrFacingAwayGivesZero) {
  const auto above = rectangle({-1, -1, 1}, {0, 2, 0}, {2, 0, 0});         // faces -z, at z = 1
  EXPECT_EQ(pointToPolygonFormFactor({0, 0, 0}, {0, 0, -1}, above), 0.0);  // receiver faces away
  EXPECT_EQ(pointToPolygonFormFactor({0, 0, 2}, {0, 0, -1}, above), 0.0);  // x behind the emitter
  EXPECT_EQ(pointToPolygonFormFactor({5, 0, 1}, {-1, 0, 0}, above), 0.0);  // x on its plane
  // Emitter plane through x's horizon: exactly half of a coaxial square is above it.
  const double half = pointToPolygonFormFactor({0, 0, 0}, {1, 0, 0}, above);
  const auto rightHalf = rectangle({0, -1, 1}, {0, 2, 0}, {1, 0, 0});
  EXPECT_NEAR(half, pointToPolygonFormFactor({0, 0, 0}, {1, 0, 0}, rightHalf), 1e-15);
  EXPECT_GT(half, 0.0);
}

TEST(FormFactorTest, TouchingAFacingEmitterTendsToTheCoveredFraction) {
  // Large square facing +z; a receiver facing it from height eps sees it cover the whole
  // hemisphere over its interior, half of it over an edge, a quarter over a corner.
  const auto big = rectangle({-1, -1, 0}, {2, 0, 0}, {0, 2, 0});
  for (double eps : {1e-3, 1e-6, 1e-9, 1e-11}) {
    EXPECT_NEAR(pointToPolygonFormFactor({0, 0, eps}, {0, 0, -1}, big), 1.0, 2 * eps) << eps;
    EXPECT_NEAR(pointToPolygonFormFactor({1, 0, eps}, {0, 0, -1}, big), 0.5, 2 * eps) << eps;
    EXPECT_NEAR(pointToPolygonFormFactor({1, 1, eps}, {0, 0, -1}, big), 0.25, 2 * eps) << eps;
  }
  EXPECT_EQ(pointToPolygonFormFactor({0, 0, 0}, {0, 0, -1}, big), 0.0);  // on the plane: edge-on
  EXPECT_EQ(pointToPolygonFormFactor({1, 0, 0}, {0, 0, -1}, big), 0.0);  // on an edge
  EXPECT_EQ(pointToPolygonFormFactor({1, 1, 0}, {0, 0, -1}, big), 0.0);  // on a corner
}

TEST(FormFactorTest, IndependentOfPlacementAndStartingVertex) {
  Random random(5);
  const glm::dmat4 move = glm::translate(glm::dmat4(1.0), Vec3(300, -20, 1e4)) *
                          glm::rotate(glm::dmat4(1.0), 1.1, glm::normalize(Vec3(3, -1, 2)));
  for (int trial = 0; trial < 100; ++trial) {
    const Vec3 centre(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1));
    std::vector<Vec3> polygon = random.polygon(centre, false);
    const Vec3 x = centre + random.uniform(0.1, 2) * unitNormal(polygon) + random.uniform(-1, 1) * random.direction();
    const Vec3 n = random.direction();
    const double F = pointToPolygonFormFactor(x, n, polygon);
    std::vector<Vec3> moved;
    for (const Vec3& p : polygon) moved.push_back(Vec3(move * glm::dvec4(p, 1.0)));
    const Vec3 movedX(move * glm::dvec4(x, 1.0)), movedN(move * glm::dvec4(n, 0.0));
    EXPECT_NEAR(pointToPolygonFormFactor(movedX, movedN, moved), F, 1e-11) << describe(x, n, polygon);
    std::rotate(polygon.begin(), polygon.begin() + 1, polygon.end());
    EXPECT_NEAR(pointToPolygonFormFactor(x, n, polygon), F, 1e-15) << describe(x, n, polygon);
  }
}

// No NaN and always in [0, 1], at the places where the formula's pieces degenerate: x on a
// vertex, on an edge or its line, on the plane, just off it, normals lying in the emitter's
// plane, polygons with repeated vertices.
TEST(FormFactorTest, NeverNaNNearDegenerateConfigurations) {
  Random random(77);
  int checked = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<Vec3> polygon = random.polygon(Vec3(0.0), trial % 2 == 0);
    if (trial % 5 == 0) polygon.insert(polygon.begin() + 1, polygon[1]);  // repeated vertex
    const Vec3 N = unitNormal(polygon);
    // b is the next vertex (an edge) or the one after (a chord).
    const Vec3 a = polygon[trial % polygon.size()], b = polygon[(trial + 1 + trial % 2) % polygon.size()];
    for (double t : {0.0, 0.5, 1.0, 1.5, -3.0})
      for (double height : {0.0, 1e-300, 1e-15, 1e-9, 1e-3})
        for (const Vec3& n : {N, -N, a == b ? N : glm::normalize(b - a), random.direction()}) {
          const Vec3 x = a + t * (b - a) + height * N;
          const double F = pointToPolygonFormFactor(x, n, polygon);
          ASSERT_TRUE(F >= 0.0 && F <= 1.0) << "F=" << F << ' ' << describe(x, n, polygon);
          ++checked;
        }
  }
  EXPECT_EQ(checked, 300 * 5 * 5 * 4);
}

}  // namespace
}  // namespace radview
