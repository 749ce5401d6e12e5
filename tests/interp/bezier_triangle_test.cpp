#include "interp/bezier_triangle.h"

#include "tests/interp/test_fields.h"
#include "tests/test_print.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace radview {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

using namespace test;

// The blossom (polar form) of degree n of a quadratic q (t = 0): the Bezier ordinate b_ijk of
// q is Q[V0 x i, V1 x j, V2 x k].
Rgb blossom(const Polynomial& q, const std::vector<Vec2>& args) {
  const double n = double(args.size());
  Rgb out;
  for (int ch = 0; ch < 3; ++ch) {
    double sum = q.c[ch];
    for (const Vec2& p : args) sum += glm::dot(q.a[ch], p) / n;
    // The quadratic part summed over the n(n-1)/2 pairs of arguments, weighted so that equal
    // arguments give back p^T H p / 2.
    for (size_t i = 0; i < args.size(); ++i)
      for (size_t j = i + 1; j < args.size(); ++j) sum += glm::dot(args[i], q.H[ch] * args[j]) / (n * (n - 1));
    out[ch] = sum;
  }
  return out;
}

template <size_t N>
std::array<Rgb, N> blossomNet(const Polynomial& q, const std::array<Vec2, 3>& V) {
  constexpr int n = N == 6 ? 2 : 3;
  std::array<Rgb, N> b{};
  for (int i = n; i >= 0; --i)
    for (int j = n - i; j >= 0; --j) {
      std::vector<Vec2> args;
      for (int r = 0; r < i; ++r) args.push_back(V[0]);
      for (int r = 0; r < j; ++r) args.push_back(V[1]);
      for (int r = 0; r < n - i - j; ++r) args.push_back(V[2]);
      b[bezierIndex(n, i, j)] = blossom(q, args);
    }
  return b;
}

double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }

TEST(BezierTriangle, IndexEnumeratesTheNetByDescendingIThenJ) {
  for (int n = 1; n <= 3; ++n) {
    int expected = 0;
    for (int i = n; i >= 0; --i)
      for (int j = n - i; j >= 0; --j) EXPECT_EQ(bezierIndex(n, i, j), expected++) << n << ' ' << i << ' ' << j;
    EXPECT_EQ(expected, (n + 1) * (n + 2) / 2);
  }
}

// de Casteljau against C&W eq. 9.7 written out, with its analytic partial derivatives, at
// barycentric coordinates inside and up to 0.3 outside the triangle.
TEST(BezierTriangle, DeCasteljauMatchesEquation97AndItsDerivatives) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0), beyond(-0.3, 1.3);
  for (int n = 1; n <= 3; ++n)
    for (int trial = 0; trial < 200; ++trial) {
      std::array<Rgb, 10> b{};
      for (Rgb& v : b) v = Rgb(u(random), u(random), u(random));
      const double bu = beyond(random), bv = beyond(random);
      const Vec3 beta(bu, bv, 1.0 - bu - bv);
      BezierJet expected;
      for (int i = n; i >= 0; --i)
        for (int j = n - i; j >= 0; --j) {
          const int k = n - i - j;
          const double m = factorial(n) / (factorial(i) * factorial(j) * factorial(k));
          const Rgb& bijk = b[bezierIndex(n, i, j)];
          expected.B += m * std::pow(beta.x, i) * std::pow(beta.y, j) * std::pow(beta.z, k) * bijk;
          if (i > 0)
            expected.dBeta[0] += m * i * std::pow(beta.x, i - 1) * std::pow(beta.y, j) * std::pow(beta.z, k) * bijk;
          if (j > 0)
            expected.dBeta[1] += m * j * std::pow(beta.x, i) * std::pow(beta.y, j - 1) * std::pow(beta.z, k) * bijk;
          if (k > 0)
            expected.dBeta[2] += m * k * std::pow(beta.x, i) * std::pow(beta.y, j) * std::pow(beta.z, k - 1) * bijk;
        }
      const BezierJet jet = evaluateBezier(n, b.data(), beta);
      SCOPED_TRACE(testing::Message() << "n " << n << " beta " << str(beta));
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(jet.B[c], expected.B[c], 1e-13);
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(jet.dBeta[i][c], expected.dBeta[i][c], 1e-13);
      }
    }
}

TEST(BezierTriangle, InterpolatesItsCornerControlValues) {
  std::array<Rgb, 10> b{};
  for (int i = 0; i < 10; ++i) b[i] = Rgb(i, 2.0 * i, -i);
  EXPECT_EQ(evaluateBezier(b, Vec3(1, 0, 0)).B, b[bezierIndex(3, 3, 0)]);  // b300
  EXPECT_EQ(evaluateBezier(b, Vec3(0, 1, 0)).B, b[bezierIndex(3, 0, 3)]);  // b030
  EXPECT_EQ(evaluateBezier(b, Vec3(0, 0, 1)).B, b[bezierIndex(3, 0, 0)]);  // b003
}

// The nets of degree 2 and 3 of a quadratic (its blossom) give back the quadratic and its
// world-space gradient on a triangle anywhere in 3D, inside and outside the triangle.
TEST(BezierTriangle, NetOfAQuadraticGivesItsValueAndWorldGradient) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0), beyond(-0.2, 1.2);
  for (int trial = 0; trial < 100; ++trial) {
    const PlaneFrame plane = randomPlane(random);
    const std::array<Vec2, 3> p{Vec2(u(random), u(random)), Vec2(u(random), u(random)), Vec2(u(random), u(random))};
    const BarycentricFrame frame = barycentricFrame({plane.at(p[0]), plane.at(p[1]), plane.at(p[2])});
    if (frame.degenerate) continue;
    const Polynomial q = randomPolynomial(random, false);
    const auto net2 = blossomNet<6>(q, p);
    const auto net3 = blossomNet<10>(q, p);
    for (int s = 0; s < 10; ++s) {
      const double bu = beyond(random), bv = beyond(random);
      const Vec3 beta(bu, bv, 1.0 - bu - bv);
      const Vec2 x = beta.x * p[0] + beta.y * p[1] + beta.z * p[2];
      const Rgb expected = q(x);
      const RgbGradient expectedGradient = q.gradient(plane, x);
      for (const Sample& sample : {sampleBezier(net2, frame, beta), sampleBezier(net3, frame, beta)}) {
        SCOPED_TRACE(testing::Message() << "beta " << str(beta) << ": " << sample);
        for (int c = 0; c < 3; ++c) {
          EXPECT_NEAR(sample.B[c], expected[c], 1e-12);
          EXPECT_NEAR(glm::length(sample.gradient[c] - expectedGradient[c]), 0.0, 1e-10);
        }
      }
    }
  }
}

TEST(BarycentricFrame, ReconstructsTheProjectedPointAndDifferentiatesLambda) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const std::array<Vec3, 3> V{Vec3(u(random), u(random), u(random)), Vec3(u(random), u(random), u(random)),
                                Vec3(u(random), u(random), u(random))};
    const BarycentricFrame frame = barycentricFrame(V);
    ASSERT_FALSE(frame.degenerate);
    const Vec3 n = glm::normalize(glm::cross(V[1] - V[0], V[2] - V[0]));
    const Vec3 inPlane = 0.2 * V[0] + 0.5 * V[1] + 0.3 * V[2] + u(random) * (V[1] - V[2]);
    const Vec3 lambda = frame(inPlane + 0.7 * n);  // off the plane: projected
    EXPECT_NEAR(lambda.x + lambda.y + lambda.z, 1.0, 1e-15);
    EXPECT_NEAR(glm::length(lambda.x * V[0] + lambda.y * V[1] + lambda.z * V[2] - inPlane), 0.0, 1e-14);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(glm::dot(frame.grad[i], n), 0.0, 1e-12) << "in the plane";
      for (int j = 0; j < 3; ++j)
        EXPECT_NEAR(glm::dot(frame.grad[i], V[j] - V[(j + 1) % 3]), (i == j) - (i == (j + 1) % 3), 1e-13);
    }
  }
}

// Needles (one short edge) and caps (three nearly collinear vertices) of aspect ratio
// longest^2 / (2 area) up to 1e7, rotated and moved in 3D, against a long-double evaluation of
// the same double vertices: lambda(x) at the eps * aspect bound that rounding x - V implies,
// and on needles grad to ~1e-13 (the edges at the sharp apex would lose ~1e-9 at 1e7).
TEST(BarycentricFrame, SliversLoseOnlyThePrecisionTheirShapeCosts) {
  using LD = long double;
  std::mt19937 random(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const bool needle : {true, false})
    for (const double h : {1e-1, 1e-3, 1e-5, 1e-7}) {
      const double aspect = 1.0 / h;
      double lambdaError = 0.0, gradError = 0.0;
      for (int trial = 0; trial < 100; ++trial) {
        const glm::dmat3 R = randomRotation(random);
        const Vec3 offset(3 * u(random), 3 * u(random), 3 * u(random));
        const Vec3 apex = needle ? Vec3(1.0 + 1e-3 * u(random), h, 0) : Vec3(0.3 + 0.4 * u(random), h, 0);
        std::array<Vec3, 3> V{offset, R * Vec3(1, 0, 0) + offset, R * apex + offset};
        std::rotate(V.begin(), V.begin() + trial % 3, V.end());
        const BarycentricFrame frame = barycentricFrame(V);
        ASSERT_FALSE(frame.degenerate);
        // Reference: the same formulas in long double (64-bit mantissa).
        auto ld = [](const Vec3& v) { return glm::vec<3, LD>(v); };
        const glm::vec<3, LD> N = glm::cross(ld(V[1]) - ld(V[0]), ld(V[2]) - ld(V[0]));
        for (int i = 0; i < 3; ++i) {
          const glm::vec<3, LD> g = glm::cross(N, ld(V[(i + 2) % 3]) - ld(V[(i + 1) % 3])) / glm::dot(N, N);
          gradError = std::max(gradError, double(glm::length(ld(frame.grad[i]) - g) / glm::length(g)));
        }
        for (int s = 0; s < 20; ++s) {
          const double a = u(random), b = u(random) * (1.0 - a);
          const Vec3 x = a * V[0] + b * V[1] + (1.0 - a - b) * V[2];
          const Vec3 lambda = frame(x);
          for (int i = 0; i < 3; ++i) {
            const glm::vec<3, LD> e = ld(V[(i + 2) % 3]) - ld(V[(i + 1) % 3]);
            const LD exact = glm::dot(glm::cross(e, ld(x) - ld(V[(i + 1) % 3])), N) / glm::dot(N, N);
            lambdaError = std::max(lambdaError, double(std::abs(LD(lambda[i]) - exact)));
          }
        }
      }
      std::printf("  %-6s aspect %7.0e: lambda error %.2e (%.2f eps*aspect), grad relative error %.2e\n",
                  needle ? "needle" : "cap", aspect, lambdaError, lambdaError / (kEps * aspect), gradError);
      EXPECT_LE(lambdaError, 4.0 * kEps * aspect);
      if (needle) {
        EXPECT_LE(gradError, 1e-11);
      }
    }
}

TEST(BarycentricFrame, DegenerateTrianglesFallBackToTheLongestEdge) {
  // Collinear, the middle vertex last: linear along V0 -> V1, nothing for V2.
  const BarycentricFrame line = barycentricFrame({Vec3(0, 0, 0), Vec3(2, 2, 2), Vec3(1, 1, 1)});
  EXPECT_TRUE(line.degenerate);
  for (const Vec3& g : line.grad) EXPECT_EQ(g, Vec3(0.0));
  EXPECT_EQ(line(Vec3(0.5, 0.5, 0.5)), Vec3(0.75, 0.25, 0.0));
  EXPECT_EQ(line(Vec3(5, 4, 6)), Vec3(0.0, 1.0, 0.0)) << "clamped to the edge";
  // Round-off away from collinear is still degenerate.
  const Vec3 a(0.1, 0.2, 0.3), b(0.7, -0.4, 1.3);
  EXPECT_TRUE(barycentricFrame({a, b, a + (1.0 / 3.0) * (b - a)}).degenerate);
  // All three coincident.
  const BarycentricFrame point = barycentricFrame({a, a, a});
  EXPECT_TRUE(point.degenerate);
  EXPECT_EQ(point(b), Vec3(1.0 / 3.0));
}

}  // namespace
}  // namespace radview
