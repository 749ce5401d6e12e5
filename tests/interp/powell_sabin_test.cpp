#include "interp/powell_sabin.h"

#include "tests/interp/piece_check.h"
#include "tests/interp/test_fields.h"
#include "tests/test_print.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace radview {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

using namespace test;

std::array<Vec3, 3> midpoints(const std::array<Vec3, 3>& V) {
  return {0.5 * (V[0] + V[1]), 0.5 * (V[1] + V[2]), 0.5 * (V[2] + V[0])};
}

std::array<Vec3, 3> randomTriangle(std::mt19937& random, const PlaneFrame& plane) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  return {plane.at({u(random), u(random)}), plane.at({u(random), u(random)}), plane.at({u(random), u(random)})};
}

double distanceToLine(const Vec3& p, const Vec3& a, const Vec3& b) {
  return glm::length(glm::cross(b - a, p - a)) / glm::length(b - a);
}

TEST(PowellSabin, IncenterIsEquidistantFromTheSides) {
  std::mt19937 random(1);
  for (int trial = 0; trial < 100; ++trial) {
    const std::array<Vec3, 3> V = randomTriangle(random, randomPlane(random));
    const Vec3 Z = incenter(V[0], V[1], V[2]);
    const double r = distanceToLine(Z, V[0], V[1]);
    EXPECT_NEAR(distanceToLine(Z, V[1], V[2]), r, 1e-13);
    EXPECT_NEAR(distanceToLine(Z, V[2], V[0]), r, 1e-13);
    const Vec3 lambda = barycentricFrame(V)(Z);
    EXPECT_GT(std::min({lambda.x, lambda.y, lambda.z}), 0.0) << "inside";
  }
  const Vec3 a(1, 2, 3);
  EXPECT_EQ(incenter(a, a, a), a);
}

// Two triangles T = (A, B, P) and T' = (B, A, Q) sharing edge 0 (A -> B in T), each side's
// gradients at A and B the same.
struct EdgePair {
  PlaneFrame plane;
  std::array<Vec3, 3> V, W;
  RandomData dataV, dataW;
};
EdgePair randomEdgePair(std::mt19937& random) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  EdgePair e;
  e.plane = randomPlane(random);
  const Vec3 A = e.plane.at({-0.5 + 0.2 * u(random), 0.1 * u(random)});
  const Vec3 B = e.plane.at({0.5 + 0.2 * u(random), 0.1 * u(random)});
  e.V = {A, B, e.plane.at({0.6 * u(random), 0.5 + 0.3 * u(random)})};
  e.W = {B, A, e.plane.at({0.6 * u(random), -0.5 - 0.3 * u(random)})};
  e.dataV = randomData(random, e.plane);
  e.dataW = randomData(random, e.plane);
  e.dataW.f[0] = e.dataV.f[1];
  e.dataW.f[1] = e.dataV.f[0];
  e.dataW.g[0] = e.dataV.g[1];
  e.dataW.g[1] = e.dataV.g[0];
  e.dataV.gradientScale = e.dataW.gradientScale = std::max(e.dataV.gradientScale, e.dataW.gradientScale);
  return e;
}

TEST(PowellSabin, EdgeSplitPointIsOnTheEdgeAndOnTheSegmentOfTheIncenters) {
  std::mt19937 random(2);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int trial = 0; trial < 100; ++trial) {
    const EdgePair e = randomEdgePair(random);
    const Vec3 &A = e.V[0], &B = e.V[1];
    const Vec3 Z = incenter(e.V[0], e.V[1], e.V[2]), ZN = incenter(e.W[0], e.W[1], e.W[2]);
    const Vec3 R = edgeSplitPoint(A, B, Z, ZN);
    EXPECT_LE(distanceToLine(R, A, B), 1e-15);
    const double t = glm::dot(R - A, B - A) / glm::dot(B - A, B - A);
    EXPECT_GT(t, 0.0);
    EXPECT_LT(t, 1.0);
    EXPECT_LE(distanceToLine(R, Z, ZN), 1e-15) << "on the segment of the incenters";
    // Both neighbours get the same bits.
    EXPECT_EQ(edgeSplitPoint(B, A, ZN, Z), R);
    EXPECT_EQ(edgeSplitPoint(B, A, Z, ZN), R);
    EXPECT_EQ(edgeSplitPoint(A, B, ZN, Z), R);
    // The neighbour folded about the edge out of the plane: the same point (unfolded).
    const glm::dmat3 fold = glm::dmat3(glm::rotate(glm::dmat4(1.0), 0.3 + u01(random), glm::normalize(B - A)));
    const Vec3 Q = A + fold * (e.W[2] - A);
    EXPECT_NEAR(glm::length(edgeSplitPoint(A, B, Z, incenter(B, A, Q)) - R), 0.0, 1e-14);
  }
}

TEST(PowellSabin, EdgeSplitPointOfFlatNeighbours) {
  // Segment of the incenters nearly along the edge: both triangles 1e-9 high.
  const Vec3 A(0, 0, 0), B(1, 0, 0);
  const Vec3 Z = incenter(A, B, Vec3(0.2, 1e-9, 0)), ZN = incenter(B, A, Vec3(0.9, -1e-9, 0));
  const Vec3 R = edgeSplitPoint(A, B, Z, ZN);
  EXPECT_TRUE(R.y == 0.0 && R.z == 0.0 && R.x > 0.0 && R.x < 1.0) << str(R);
  EXPECT_LE(distanceToLine(R, Z, ZN), 1e-15);
  // Both degenerate: the midpoint.
  EXPECT_EQ(edgeSplitPoint(A, B, Vec3(0.3, 0, 0), Vec3(0.8, 0, 0)), Vec3(0.5, 0, 0));
}

TEST(PowellSabin, InterpolatesCornerValuesAndGradients) {
  std::mt19937 random(3);
  for (int trial = 0; trial < 100; ++trial) {
    const PlaneFrame plane = randomPlane(random);
    const std::array<Vec3, 3> V = randomTriangle(random, plane);
    const RandomData d = randomData(random, plane);
    const PowellSabinPatch patch = buildPowellSabin(V, d.f, d.g, midpoints(V));
    for (int i = 0; i < 3; ++i) {
      Vec3 corner(0.0);
      corner[i] = 1.0;
      const Sample s = evaluate(patch, corner);
      SCOPED_TRACE(testing::Message() << "trial " << trial << " corner " << i << ": " << s);
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(s.B[c], d.f[i][c], 1e-14);
        EXPECT_LE(glm::length(s.gradient[c] - d.g[i][c]), 1e-12 * (1.0 + glm::length(d.g[i][c])));
      }
    }
  }
}

// evaluate picks the piece that holds the point: checked against each piece's own barycentric
// frame in world space (a separate derivation of the piece coordinates), values and gradients.
TEST(PowellSabin, EvaluatesThePieceThatHoldsThePoint) {
  std::mt19937 random(4);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    const PlaneFrame plane = randomPlane(random);
    const std::array<Vec3, 3> V = randomTriangle(random, plane);
    const RandomData d = randomData(random, plane);
    std::array<Vec3, 3> R;
    for (int k = 0; k < 3; ++k) R[k] = V[k] + (0.2 + 0.6 * u(random)) * (V[(k + 1) % 3] - V[k]);
    const PowellSabinPatch patch = buildPowellSabin(V, d.f, d.g, R);
    for (int s = 0; s < 50; ++s) {
      const double a = u(random), b = u(random);
      const Vec3 lambda = a + b <= 1.0 ? Vec3(a, b, 1.0 - a - b) : Vec3(1.0 - a, 1.0 - b, a + b - 1.0);
      const Vec3 x = lambda.x * V[0] + lambda.y * V[1] + lambda.z * V[2];
      test::expectThePieceHoldingXIsEvaluated<6>(
          evaluate(patch, lambda), x, 6,
          [&](int p) {
            const int k = p / 2;
            return std::pair(std::array<Vec3, 3>{V[(k + p % 2) % 3], R[k], patch.Z}, patch.control[p]);
          },
          1e-13, 1e-11);
    }
  }
}

// Quadratics are reproduced given their exact gradients: values to 1e-12 at every aspect ratio
// up to 1e7 (every control value is an affine combination of the data, nothing cancels), the
// gradient with an error ~50 eps * aspect, the condition of the slope across a sliver
// (printed).
TEST(PowellSabin, ReproducesQuadraticsWithTheirGradients) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::printf("  Powell-Sabin, quadratic reproduction: max relative error, value / gradient\n");
  for (const bool needle : {true, false})
    for (const double aspect : {1.0, 1e1, 1e3, 1e5, 1e7}) {
      const double h = 1.0 / aspect;
      double valueError = 0.0, gradientError = 0.0;
      for (int trial = 0; trial < 20; ++trial) {
        const PlaneFrame plane = randomPlane(random);
        std::array<Vec2, 3> p = aspect == 1.0
                                    ? std::array<Vec2, 3>{Vec2(0, 0), Vec2(1, 0), Vec2(0.5, 0.8660254037844386)}
                                : needle ? std::array<Vec2, 3>{Vec2(0, 0), Vec2(0, 1), Vec2(h, h)}
                                         : std::array<Vec2, 3>{Vec2(0, 0), Vec2(1, 0), Vec2(0.4, h)};
        std::rotate(p.begin(), p.begin() + trial % 3, p.end());
        const Polynomial q = randomPolynomial(random, false);
        const std::array<Vec3, 3> V{plane.at(p[0]), plane.at(p[1]), plane.at(p[2])};
        std::array<Rgb, 3> f;
        std::array<RgbGradient, 3> g;
        for (int i = 0; i < 3; ++i) {
          f[i] = q(p[i]);
          g[i] = q.gradient(plane, p[i]);
        }
        // Split points anywhere on the edges: reproduction does not depend on them.
        std::array<Vec3, 3> R;
        for (int k = 0; k < 3; ++k) R[k] = V[k] + (0.1 + 0.8 * u(random)) * (V[(k + 1) % 3] - V[k]);
        const PowellSabinPatch patch = buildPowellSabin(V, f, g, R);
        double maxValue = 0.0, maxGradient = 0.0, e = 0.0, eg = 0.0;
        for (int s = 0; s < 300; ++s) {
          const double a = u(random), b = u(random);
          const Vec3 lambda = a + b <= 1.0 ? Vec3(a, b, 1.0 - a - b) : Vec3(1.0 - a, 1.0 - b, a + b - 1.0);
          const Vec2 x = lambda.x * p[0] + lambda.y * p[1] + lambda.z * p[2];
          const Rgb expected = q(x);
          const RgbGradient expectedGradient = q.gradient(plane, x);
          const Sample got = evaluate(patch, lambda);
          for (int c = 0; c < 3; ++c) {
            maxValue = std::max(maxValue, std::abs(expected[c]));
            maxGradient = std::max(maxGradient, glm::length(expectedGradient[c]));
            e = std::max(e, std::abs(got.B[c] - expected[c]));
            eg = std::max(eg, glm::length(got.gradient[c] - expectedGradient[c]));
          }
        }
        valueError = std::max(valueError, e / maxValue);
        gradientError = std::max(gradientError, eg / maxGradient);
      }
      std::printf("  %-6s aspect %7.0e: %.1e / %.1e\n", needle ? "needle" : "cap", aspect, valueError, gradientError);
      SCOPED_TRACE(testing::Message() << (needle ? "needle" : "cap") << " aspect " << aspect);
      EXPECT_LE(valueError, 1e-12);
      if (aspect <= 10.0) {
        EXPECT_LE(gradientError, 1e-12);
      }
      EXPECT_LE(gradientError, 128.0 * kEps * aspect);
    }
}

TEST(PowellSabin, ReproducesQuadraticsAtEveryScale) {
  std::mt19937 random(6);
  for (const double size : {1e-6, 1e-3, 1.0, 1e3, 1e6}) {
    PlaneFrame plane = randomPlane(random);
    plane.origin *= size;
    std::array<Vec2, 3> p{Vec2(0.1, -0.2), Vec2(0.9, 0.1), Vec2(0.3, 0.7)};
    for (Vec2& v : p) v *= size;
    Polynomial q = randomPolynomial(random, false);
    for (int ch = 0; ch < 3; ++ch) {
      q.a[ch] /= size;
      q.H[ch] /= size * size;
    }
    const std::array<Vec3, 3> V{plane.at(p[0]), plane.at(p[1]), plane.at(p[2])};
    std::array<Rgb, 3> f;
    std::array<RgbGradient, 3> g;
    for (int i = 0; i < 3; ++i) {
      f[i] = q(p[i]);
      g[i] = q.gradient(plane, p[i]);
    }
    const PowellSabinPatch patch = buildPowellSabin(V, f, g, midpoints(V));
    for (const Vec3& lambda : {Vec3(0.2, 0.3, 0.5), Vec3(0.7, 0.1, 0.2), Vec3(0.05, 0.9, 0.05)}) {
      const Vec2 x = lambda.x * p[0] + lambda.y * p[1] + lambda.z * p[2];
      const Sample s = evaluate(patch, lambda);
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(s.B[c], q(x)[c], 1e-12 * 3.0) << "size " << size;
        EXPECT_LE(glm::length(s.gradient[c] - q.gradient(plane, x)[c]), 1e-12 * 3.0 / size) << "size " << size;
      }
    }
  }
}

struct Jump {
  double value = 0.0, gradient = 0.0;
};
// One-sided values and gradients at points along the shared edge, split at R on both sides.
Jump jumpAcrossSharedEdge(const EdgePair& e, const Vec3& R) {
  std::array<Vec3, 3> RV = midpoints(e.V), RW = midpoints(e.W);
  RV[0] = RW[0] = R;
  const PowellSabinPatch T = buildPowellSabin(e.V, e.dataV.f, e.dataV.g, RV);
  const PowellSabinPatch W = buildPowellSabin(e.W, e.dataW.f, e.dataW.g, RW);
  Jump jump;
  for (int i = 0; i <= 40; ++i) {
    const double s = i / 40.0;
    const Sample a = evaluate(T, Vec3(1.0 - s, s, 0.0)), b = evaluate(W, Vec3(s, 1.0 - s, 0.0));
    for (int c = 0; c < 3; ++c) {
      jump.value = std::max(jump.value, std::abs(a.B[c] - b.B[c]));
      jump.gradient = std::max(jump.gradient, glm::length(a.gradient[c] - b.gradient[c]) / e.dataV.gradientScale);
    }
  }
  return jump;
}

TEST(PowellSabin, NeighboursSplitOnTheSegmentOfTheirIncentersJoinC1) {
  std::mt19937 random(7);
  for (int trial = 0; trial < 100; ++trial) {
    const EdgePair e = randomEdgePair(random);
    const Vec3 R = edgeSplitPoint(e.V[0], e.V[1], incenter(e.V[0], e.V[1], e.V[2]), incenter(e.W[0], e.W[1], e.W[2]));
    const Jump jump = jumpAcrossSharedEdge(e, R);
    EXPECT_LE(jump.value, 1e-14) << "trial " << trial;
    EXPECT_LE(jump.gradient, 1e-13) << "trial " << trial;
  }
}

// Split where the segment between the centroids crosses the edge (the same R on both sides):
// C0, but the derivative across the edge jumps.
TEST(PowellSabin, CentroidSplitIsNotC1) {
  std::mt19937 random(8);
  double smallest = 1e300, largest = 0.0, worstValue = 0.0;
  for (int trial = 0; trial < 100; ++trial) {
    const EdgePair e = randomEdgePair(random);
    const Vec3 R = edgeSplitPoint(e.V[0], e.V[1], (e.V[0] + e.V[1] + e.V[2]) / 3.0, (e.W[0] + e.W[1] + e.W[2]) / 3.0);
    const Jump jump = jumpAcrossSharedEdge(e, R);
    smallest = std::min(smallest, jump.gradient);
    largest = std::max(largest, jump.gradient);
    worstValue = std::max(worstValue, jump.value);
  }
  std::printf(
      "  centroid split: derivative jump across the edge over 100 pairs (relative to the largest "
      "corner gradient) from %.2e to %.2e\n",
      smallest, largest);
  EXPECT_LE(worstValue, 1e-14);
  EXPECT_GT(smallest, 1e-4);
}

TEST(PowellSabin, PiecesJoinC1AcrossTheInnerEdges) {
  std::mt19937 random(9);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 100; ++trial) {
    const PlaneFrame plane = randomPlane(random);
    const std::array<Vec3, 3> V = randomTriangle(random, plane);
    const RandomData d = randomData(random, plane);
    std::array<Vec3, 3> R;
    for (int k = 0; k < 3; ++k) R[k] = V[k] + (0.1 + 0.8 * u(random)) * (V[(k + 1) % 3] - V[k]);
    const PowellSabinPatch patch = buildPowellSabin(V, d.f, d.g, R);
    double scale = d.gradientScale;  // and that of the control values over the size
    for (const auto& piece : patch.control)
      for (const Rgb& b : piece)
        for (const Vec3& gl : patch.frame.grad) scale = std::max(scale, glm::length(b) * glm::length(gl));
    const BarycentricFrame frame = barycentricFrame(V);
    for (int k = 0; k < 3; ++k) {
      // Inner edge V_k - Z: pieces 2k and 2k-1; inner edge R_k - Z: pieces 2k and 2k+1.
      const std::array<std::array<int, 2>, 2> pairs{{{2 * k, (2 * k + 5) % 6}, {2 * k, 2 * k + 1}}};
      const std::array<Vec3, 2> ends{V[k], R[k]};
      for (int edge = 0; edge < 2; ++edge)
        for (int s = 0; s <= 10; ++s) {
          const Vec3 lambda = frame(ends[edge] + (s / 10.0) * (patch.Z - ends[edge]));
          const Sample a = evaluatePiece(patch, pairs[edge][0], lambda),
                       b = evaluatePiece(patch, pairs[edge][1], lambda);
          for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(a.B[c], b.B[c], 1e-14) << "trial " << trial << " edge " << k << ' ' << edge;
            EXPECT_LE(glm::length(a.gradient[c] - b.gradient[c]), 1e-12 * scale)
                << "trial " << trial << " edge " << k << ' ' << edge;
          }
        }
    }
  }
}

TEST(PowellSabin, DegenerateTriangleIsTheLinearInterpolantAndFinite) {
  const std::array<Rgb, 3> f{Rgb(1, 2, 3), Rgb(4, 5, 6), Rgb(-1, 0, 1)};
  RgbGradient g;
  g.fill(Vec3(1, 2, 3));
  const Vec3 a(0.1, 0.2, 0.3), b(1.1, 0.2, -0.7);
  for (const std::array<Vec3, 3>& V :
       {std::array<Vec3, 3>{a, b, 0.5 * (a + b)}, std::array<Vec3, 3>{a, a, b}, std::array<Vec3, 3>{a, a, a}}) {
    const PowellSabinPatch patch = buildPowellSabin(V, f, {g, g, g}, midpoints(V));
    for (const Vec3& lambda : {Vec3(1, 0, 0), Vec3(0.2, 0.3, 0.5), Vec3(0.6, 0.4, 0.0), Vec3(-0.1, 0.5, 0.6)}) {
      const Sample s = evaluate(patch, lambda);
      const Rgb linear = lambda.x * f[0] + lambda.y * f[1] + lambda.z * f[2];
      EXPECT_NEAR(glm::length(s.B - linear), 0.0, 1e-14) << s;
      for (const Vec3& gc : s.gradient) EXPECT_EQ(gc, Vec3(0.0)) << s;
    }
  }
}

}  // namespace
}  // namespace radview
