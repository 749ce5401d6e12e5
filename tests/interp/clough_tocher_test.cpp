#include "interp/clough_tocher.h"

#include "tests/interp/clough_tocher_edges.h"
#include "tests/interp/piece_check.h"
#include "tests/interp/test_fields.h"
#include "tests/test_print.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace radview {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

using namespace test;

// Sample points: corners, edge midpoints, the centroid and random points, as barycentrics.
std::vector<Vec3> samplePoints(std::mt19937& random, int count) {
  std::vector<Vec3> out{Vec3(1, 0, 0),     Vec3(0, 1, 0),     Vec3(0, 0, 1),  Vec3(0.5, 0.5, 0),
                        Vec3(0, 0.5, 0.5), Vec3(0.5, 0, 0.5), Vec3(1.0 / 3.0)};
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < count; ++i) {
    const double a = u(random), b = u(random);
    out.push_back(a + b <= 1.0 ? Vec3(a, b, 1.0 - a - b) : Vec3(1.0 - a, 1.0 - b, a + b - 1.0));
  }
  return out;
}

// A needle with its short edge oblique to its axis (scipy's example: (0,0), (0,1), (h,h)) and
// a cap (three nearly collinear vertices), of aspect ratio longest^2 / (2 area) about 1/h.
std::array<Vec2, 3> sliver(bool needle, double h) {
  if (h >= 1.0) return {Vec2(0, 0), Vec2(1, 0), Vec2(0.5, 0.8660254037844386)};
  return needle ? std::array<Vec2, 3>{Vec2(0, 0), Vec2(0, 1), Vec2(h, h)}
                : std::array<Vec2, 3>{Vec2(0, 0), Vec2(1, 0), Vec2(0.4, h)};
}

TEST(CloughTocher, InterpolatesCornerValuesAndGradients) {
  std::mt19937 random(1);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 100; ++trial) {
    const PlaneFrame plane = randomPlane(random);
    const std::array<Vec3, 3> V{plane.at({u(random), u(random)}), plane.at({u(random), u(random)}),
                                plane.at({u(random), u(random)})};
    const auto [f, g, gradientScale] = randomData(random, plane);
    std::array<CrossBoundary, 3> edges = boundaryEdges(V, trial % 2 ? Variant::Book : Variant::Affine);
    edges[trial % 3].reduced = false;
    edges[trial % 3].midDerivative = Rgb(u(random), u(random), u(random));
    const CloughTocherPatch patch = buildCloughTocher(V, f, g, edges);
    for (int i = 0; i < 3; ++i) {
      Vec3 corner(0.0);
      corner[i] = 1.0;
      const Sample s = evaluate(patch, corner);
      SCOPED_TRACE(testing::Message() << "trial " << trial << " corner " << i << ": " << s);
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(s.B[c], f[i][c], 1e-14);
        EXPECT_LE(glm::length(s.gradient[c] - g[i][c]), 1e-12 * (1.0 + glm::length(g[i][c])));
      }
    }
  }
}

// evaluate picks the piece that holds the point: checked against each piece's own barycentric
// frame in world space (a separate derivation of the piece coordinates), values and gradients.
TEST(CloughTocher, EvaluatesThePieceThatHoldsThePoint) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0), u01(0.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    const PlaneFrame plane = randomPlane(random);
    const std::array<Vec3, 3> V{plane.at({u(random), u(random)}), plane.at({u(random), u(random)}),
                                plane.at({u(random), u(random)})};
    const auto [f, g, gradientScale] = randomData(random, plane);
    const CloughTocherPatch patch = buildCloughTocher(V, f, g, boundaryEdges(V, Variant::Affine));
    for (const Vec3& lambda : samplePoints(random, 50)) {
      const Vec3 x = lambda.x * V[0] + lambda.y * V[1] + lambda.z * V[2];
      test::expectThePieceHoldingXIsEvaluated<10>(
          evaluate(patch, lambda), x, 3,
          [&](int k) {
            return std::pair(std::array<Vec3, 3>{V[k], V[(k + 1) % 3], patch.C}, patch.control[k]);
          },
          1e-12, 1e-10);
    }
  }
}

struct ReproductionError {
  double value = 0.0, gradient = 0.0;  // relative to the polynomial's largest value, gradient
};

// Builds the patch of a polynomial from its exact corner gradients (and, for the full element,
// its exact derivative at the edge midpoints) and measures how far it is from the polynomial.
ReproductionError reproductionError(const PlaneFrame& plane, const std::array<Vec2, 3>& p, const Polynomial& q,
                                    Variant variant, bool full, std::mt19937& random) {
  const std::array<Vec3, 3> V{plane.at(p[0]), plane.at(p[1]), plane.at(p[2])};
  std::array<Rgb, 3> f;
  std::array<RgbGradient, 3> g;
  for (int i = 0; i < 3; ++i) {
    f[i] = q(p[i]);
    g[i] = q.gradient(plane, p[i]);
  }
  std::array<CrossBoundary, 3> edges = boundaryEdges(V, variant);
  if (full)
    for (int k = 0; k < 3; ++k) {
      edges[k].reduced = false;
      edges[k].midDerivative = along(q.gradient(plane, 0.5 * (p[k] + p[(k + 1) % 3])), edges[k].d);
    }
  const CloughTocherPatch patch = buildCloughTocher(V, f, g, edges);
  double maxValue = 0.0, maxGradient = 0.0;
  ReproductionError error;
  for (const Vec3& lambda : samplePoints(random, 300)) {
    const Vec2 x = lambda.x * p[0] + lambda.y * p[1] + lambda.z * p[2];
    const Rgb expected = q(x);
    const RgbGradient expectedGradient = q.gradient(plane, x);
    const Sample s = evaluate(patch, lambda);
    for (int c = 0; c < 3; ++c) {
      maxValue = std::max(maxValue, std::abs(expected[c]));
      maxGradient = std::max(maxGradient, glm::length(expectedGradient[c]));
      error.value = std::max(error.value, std::abs(s.B[c] - expected[c]));
      error.gradient = std::max(error.gradient, glm::length(s.gradient[c] - expectedGradient[c]));
    }
  }
  error.value /= maxValue;
  error.gradient /= maxGradient;
  return error;
}

// Quadratics are reproduced by both variants, to 1e-12 up to aspect ratio 1e3 and beyond that
// with an error that grows like eps * aspect in value (the cross directions are world vectors,
// nearly along a long edge or across a short one, whose components cancel to relative eps *
// aspect) and eps * aspect^2 in gradient (a value error over the sliver's height): see the
// printed table.
TEST(CloughTocher, ReproducesQuadraticsWithTheirGradients) {
  std::mt19937 random(2);
  std::printf("  Clough-Tocher, quadratic reproduction: max relative error, value / gradient\n");
  for (const bool needle : {true, false})
    for (const double aspect : {1.0, 1e1, 1e3, 1e5, 1e7}) {
      ReproductionError worst[2];
      for (int trial = 0; trial < 20; ++trial) {
        const PlaneFrame plane = randomPlane(random);
        std::array<Vec2, 3> p = sliver(needle, 1.0 / aspect);
        std::rotate(p.begin(), p.begin() + trial % 3, p.end());
        const Polynomial q = randomPolynomial(random, false);
        for (const Variant variant : {Variant::Book, Variant::Affine}) {
          const ReproductionError e = reproductionError(plane, p, q, variant, false, random);
          ReproductionError& w = worst[int(variant)];
          w.value = std::max(w.value, e.value);
          w.gradient = std::max(w.gradient, e.gradient);
        }
      }
      std::printf("  %-6s aspect %7.0e: book %.1e / %.1e   affine %.1e / %.1e\n", needle ? "needle" : "cap", aspect,
                  worst[0].value, worst[0].gradient, worst[1].value, worst[1].gradient);
      for (const Variant variant : {Variant::Book, Variant::Affine}) {
        SCOPED_TRACE(testing::Message() << name(variant) << (needle ? " needle" : " cap") << " aspect " << aspect);
        const ReproductionError& w = worst[int(variant)];
        if (aspect <= 10.0) {
          EXPECT_LE(w.gradient, 1e-12);
        }
        EXPECT_LE(w.value, aspect <= 1e3 ? 1e-12 : 4.0 * kEps * aspect);
        EXPECT_LE(w.gradient, 64.0 * kEps * aspect + 4.0 * kEps * aspect * aspect);
      }
    }
}

// Scale invariance: well-shaped triangles from 1e-6 to 1e6 across.
TEST(CloughTocher, ReproducesQuadraticsAtEveryScale) {
  std::mt19937 random(3);
  for (const double size : {1e-6, 1e-3, 1.0, 1e3, 1e6}) {
    PlaneFrame plane = randomPlane(random);
    plane.origin *= size;
    std::array<Vec2, 3> p{Vec2(0.1, -0.2), Vec2(0.9, 0.1), Vec2(0.3, 0.7)};
    for (Vec2& v : p) v *= size;
    Polynomial q = randomPolynomial(random, false);
    for (int ch = 0; ch < 3; ++ch) {  // O(1) variation over the triangle
      q.a[ch] /= size;
      q.H[ch] /= size * size;
    }
    for (const Variant variant : {Variant::Book, Variant::Affine}) {
      const ReproductionError e = reproductionError(plane, p, q, variant, false, random);
      EXPECT_LE(e.value, 1e-12) << name(variant) << " size " << size;
      EXPECT_LE(e.gradient, 1e-12) << name(variant) << " size " << size;
    }
  }
}

// The full element (mid-edge cross derivatives given) has cubic precision.
TEST(CloughTocher, FullElementReproducesCubics) {
  std::mt19937 random(4);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    const PlaneFrame plane = randomPlane(random);
    const std::array<Vec2, 3> p{Vec2(u(random), u(random)), Vec2(u(random), u(random)), Vec2(u(random), u(random))};
    const Polynomial q = randomPolynomial(random, true);
    for (const Variant variant : {Variant::Book, Variant::Affine}) {
      const ReproductionError e = reproductionError(plane, p, q, variant, true, random);
      EXPECT_LE(e.value, 1e-10) << name(variant) << " trial " << trial;
      EXPECT_LE(e.gradient, 1e-9) << name(variant) << " trial " << trial;
    }
    // The reduced element does not: the cross derivative of a cubic is quadratic along an edge.
    EXPECT_GT(reproductionError(plane, p, q, Variant::Affine, false, random).value, 1e-6);
  }
}

// C&W step 4 read literally: d is where the plane through the inner edge's b and the c on
// either side (as points over their domain positions) passes over d's position - the mean
// of the three, as the code has it; and e is the mean of the d.
TEST(CloughTocher, DAndEAreOnThePlanesOfTheirWedges) {
  std::mt19937 random(8);
  const PlaneFrame plane = randomPlane(random);
  const std::array<Vec3, 3> V{plane.at({0.0, 0.0}), plane.at({1.0, 0.1}), plane.at({0.2, 0.9})};
  const auto [f, g, gradientScale] = randomData(random, plane);
  const CloughTocherPatch patch = buildCloughTocher(V, f, g, boundaryEdges(V, Variant::Book));
  const Vec3 C = patch.C;
  Rgb meanD(0.0);
  for (int i = 0; i < 3; ++i) {
    const int prev = (i + 2) % 3;
    // Domain positions: b at (2 V_i + C)/3, c of piece i at (V_i + V_i+1 + C)/3, c of piece
    // i-1 at (V_i-1 + V_i + C)/3, d at (V_i + 2 C)/3.
    const BarycentricFrame wedge =
        barycentricFrame({(2.0 * V[i] + C) / 3.0, (V[i] + V[(i + 1) % 3] + C) / 3.0, (V[prev] + V[i] + C) / 3.0});
    const Vec3 w = wedge((V[i] + 2.0 * C) / 3.0);
    const auto& piece = patch.control[i];
    const Rgb onPlane = w.x * piece[bezierIndex(3, 2, 0)] + w.y * piece[bezierIndex(3, 1, 1)] +
                        w.z * patch.control[prev][bezierIndex(3, 1, 1)];
    const Rgb d = piece[bezierIndex(3, 1, 0)];
    EXPECT_NEAR(glm::length(onPlane - d), 0.0, 1e-14) << "d of inner edge " << i << ", weights " << str(w);
    EXPECT_EQ(d, patch.control[prev][bezierIndex(3, 0, 1)]) << "shared by the two pieces";
    meanD += d / 3.0;
  }
  EXPECT_NEAR(glm::length(patch.control[0][bezierIndex(3, 0, 0)] - meanD), 0.0, 1e-15);
}

// The book's direction is not affine invariant: on a needle whose short edge is oblique to
// its axis, data that differ across the short edge are amplified by about the aspect ratio.
// Corner values f = linear + noise, gradients those of the linear part; the ratio of the
// largest departure of B from the linear function to the largest noise.
TEST(CloughTocher, BookVariantAmplifiesValuesOnNeedles) {
  std::mt19937 random(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::printf(
      "  needle amplification max|B - linear| / max|noise|, and scipy's example max|B| "
      "(F = 0, 0, 1 on (0,0), (0,1), (h,h), zero gradients)\n");
  for (const double aspect : {1e1, 1e2, 1e3, 1e5, 1e7}) {
    double ratio[2] = {0.0, 0.0}, scipyExample[2] = {0.0, 0.0};
    for (int trial = 0; trial < 20; ++trial) {
      const PlaneFrame plane = randomPlane(random);
      const std::array<Vec2, 3> p = sliver(true, 1.0 / aspect);
      const std::array<Vec3, 3> V{plane.at(p[0]), plane.at(p[1]), plane.at(p[2])};
      const Vec2 slope(u(random), u(random));
      std::array<Rgb, 3> f;
      std::array<RgbGradient, 3> g;
      double noise = 0.0;
      for (int i = 0; i < 3; ++i) {
        const Rgb n(0.01 * u(random), 0.01 * u(random), 0.01 * u(random));
        noise = std::max({noise, std::abs(n.x), std::abs(n.y), std::abs(n.z)});
        f[i] = Rgb(glm::dot(slope, p[i])) + n;
        g[i] = {plane.vector(slope), plane.vector(slope), plane.vector(slope)};
      }
      const std::array<Rgb, 3> F{Rgb(0.0), Rgb(0.0), Rgb(1.0)};
      const std::array<RgbGradient, 3> zero{};
      for (const Variant variant : {Variant::Book, Variant::Affine}) {
        const CloughTocherPatch patch = buildCloughTocher(V, f, g, boundaryEdges(V, variant));
        const CloughTocherPatch example = buildCloughTocher(V, F, zero, boundaryEdges(V, variant));
        for (int i = 0; i <= 60; ++i)
          for (int j = 0; i + j <= 60; ++j) {
            const Vec3 lambda(i / 60.0, j / 60.0, 1.0 - (i + j) / 60.0);
            const double linear = glm::dot(slope, lambda.x * p[0] + lambda.y * p[1] + lambda.z * p[2]);
            const Sample s = evaluate(patch, lambda);
            for (int c = 0; c < 3; ++c)
              ratio[int(variant)] = std::max(ratio[int(variant)], std::abs(s.B[c] - linear) / noise);
            scipyExample[int(variant)] = std::max(scipyExample[int(variant)], std::abs(evaluate(example, lambda).B.x));
          }
      }
    }
    std::printf("  aspect %7.0e: book %.3g, affine %.3g   scipy's example: book %.3g, affine %.3g\n", aspect, ratio[0],
                ratio[1], scipyExample[0], scipyExample[1]);
    EXPECT_LE(ratio[1], 2.0) << "affine, aspect " << aspect;
    EXPECT_LE(scipyExample[1], 1.5) << "affine, aspect " << aspect;
    EXPECT_GE(scipyExample[0], 0.05 * aspect) << "book, aspect " << aspect;
  }
}

// d parallel to the edge, or zero, falls back on the edge normal: the book's element.
TEST(CloughTocher, DirectionAlongTheEdgeFallsBackOnTheNormal) {
  std::mt19937 random(10);
  const PlaneFrame plane = randomPlane(random);
  const std::array<Vec3, 3> V{plane.at({0.0, 0.0}), plane.at({1.0, 0.2}), plane.at({0.3, 0.8})};
  const auto [f, g, gradientScale] = randomData(random, plane);
  std::array<CrossBoundary, 3> edges = boundaryEdges(V, Variant::Book);
  const CloughTocherPatch book = buildCloughTocher(V, f, g, edges);
  edges[0].d = 3.0 * (V[1] - V[0]);
  edges[1].d = Vec3(0.0);
  const CloughTocherPatch fallback = buildCloughTocher(V, f, g, edges);
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 10; ++i) EXPECT_NEAR(glm::length(book.control[k][i] - fallback.control[k][i]), 0.0, 1e-14);
}

TEST(CloughTocher, DegenerateTriangleIsTheLinearInterpolantAndFinite) {
  const std::array<Rgb, 3> f{Rgb(1, 2, 3), Rgb(4, 5, 6), Rgb(-1, 0, 1)};
  RgbGradient g;
  g.fill(Vec3(1, 2, 3));
  const Vec3 a(0.1, 0.2, 0.3), b(1.1, 0.2, -0.7);
  for (const std::array<Vec3, 3>& V : {std::array<Vec3, 3>{a, b, 0.5 * (a + b)}, std::array<Vec3, 3>{a, a, a}}) {
    std::array<CrossBoundary, 3> edges;
    for (int k = 0; k < 3; ++k) edges[k].d = bookCrossDirection(V[k], V[(k + 1) % 3], (V[0] + V[1] + V[2]) / 3.0);
    const CloughTocherPatch patch = buildCloughTocher(V, f, {g, g, g}, edges);
    for (const Vec3& lambda : {Vec3(1, 0, 0), Vec3(0.2, 0.3, 0.5), Vec3(0.6, 0.4, 0.0), Vec3(-0.1, 0.5, 0.6)}) {
      const Sample s = evaluate(patch, lambda);
      const Rgb linear = lambda.x * f[0] + lambda.y * f[1] + lambda.z * f[2];
      EXPECT_NEAR(glm::length(s.B - linear), 0.0, 1e-14) << s;
      for (const Vec3& gc : s.gradient) EXPECT_EQ(gc, Vec3(0.0)) << s;
    }
  }
}

TEST(CloughTocher, CrossDirections) {
  const Vec3 A(0, 0, 1), B(2, 0, 1), C(0.5, 1, 1), neighbourC(1.2, -0.7, 1);
  const Vec3 book = bookCrossDirection(A, B, C);
  EXPECT_NEAR(glm::length(book - Vec3(0, 1, 0)), 0.0, 1e-15) << str(book);
  EXPECT_NEAR(glm::length(bookCrossDirection(B, A, C) - Vec3(0, 1, 0)), 0.0, 1e-15) << "into the triangle either way";
  EXPECT_EQ(affineCrossDirection(A, B, C, neighbourC), neighbourC - C);
  EXPECT_EQ(affineCrossDirection(A, B, C, std::nullopt), C - Vec3(1, 0, 1));
}

// scipy's CloughTocher2DInterpolator (tests/data/scipy_clough_tocher.txt, written by
// tests/interp/make_scipy_reference.py) is the affine variant: the same values, to round-off,
// from the same gradients, on its triangles at its barycentric coordinates.
TEST(CloughTocher, AffineVariantIsScipysElement) {
  const std::string path = std::string(RADVIEW_SOURCE_DIR) + "/tests/data/scipy_clough_tocher.txt";
  std::ifstream in(path);
  ASSERT_TRUE(in) << path;
  auto section = [&](const std::string& expected) {
    std::string line, word;
    while (std::getline(in, line) && (line.empty() || line[0] == '#')) {
    }
    std::istringstream is(line);
    size_t count = 0;
    is >> word >> count;
    EXPECT_EQ(word, expected);
    return count;
  };
  std::vector<Vec3> points(section("points"));
  for (Vec3& p : points) in >> p.x >> p.y;
  struct Triangle {
    std::array<int, 3> v, neighbour;  // neighbour[k] opposite v[k]
  };
  std::vector<Triangle> triangles(section("triangles"));
  for (Triangle& t : triangles) in >> t.v[0] >> t.v[1] >> t.v[2] >> t.neighbour[0] >> t.neighbour[1] >> t.neighbour[2];
  std::vector<Rgb> values(section("values"));
  for (Rgb& v : values) in >> v.x >> v.y >> v.z;
  std::vector<RgbGradient> gradients(section("gradients"));
  for (RgbGradient& g : gradients)
    for (Vec3& gc : g) in >> gc.x >> gc.y;
  const size_t samples = section("samples");
  ASSERT_TRUE(in);
  ASSERT_GE(samples, 200u);

  auto centroid = [&](const Triangle& t) { return (points[t.v[0]] + points[t.v[1]] + points[t.v[2]]) / 3.0; };
  double maxError = 0.0, maxValue = 0.0;
  for (size_t s = 0; s < samples; ++s) {
    Vec2 x;
    int t = 0;
    Vec3 lambda;
    Rgb expected;
    in >> x.x >> x.y >> t >> lambda.x >> lambda.y >> lambda.z >> expected.x >> expected.y >> expected.z;
    ASSERT_TRUE(in) << "sample " << s;
    const Triangle& tri = triangles[t];
    const std::array<Vec3, 3> V{points[tri.v[0]], points[tri.v[1]], points[tri.v[2]]};
    std::array<CrossBoundary, 3> edges;
    for (int k = 0; k < 3; ++k) {
      const int across = tri.neighbour[(k + 2) % 3];  // edge k is opposite vertex k + 2
      edges[k].d = affineCrossDirection(V[k], V[(k + 1) % 3], centroid(tri),
                                        across >= 0 ? std::optional<Vec3>(centroid(triangles[across])) : std::nullopt);
    }
    const CloughTocherPatch patch =
        buildCloughTocher(V, {values[tri.v[0]], values[tri.v[1]], values[tri.v[2]]},
                          {gradients[tri.v[0]], gradients[tri.v[1]], gradients[tri.v[2]]}, edges);
    const Rgb B = evaluate(patch, lambda).B;
    for (int c = 0; c < 3; ++c) {
      maxError = std::max(maxError, std::abs(B[c] - expected[c]));
      maxValue = std::max(maxValue, std::abs(expected[c]));
    }
  }
  std::printf("  scipy agreement over %zu samples: max |B - scipy| = %.2e (max |B| %.2f)\n", samples, maxError,
              maxValue);
  EXPECT_LE(maxError, 1e-13 * maxValue);
}

}  // namespace
}  // namespace radview
