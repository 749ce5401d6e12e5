// Clough-Tocher patches side by side (C&W §9.2, step 2; Farin 1986): neighbours that share the
// cross-boundary direction and the end gradients of their common edge join C1 across it, and
// the three pieces of one element join C1 across its inner edges, whatever the data.
#include "interp/clough_tocher.h"

#include "tests/interp/clough_tocher_edges.h"
#include "tests/interp/test_fields.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>

namespace radview {
namespace {

using namespace test;

// Two coplanar triangles T = (A, B, P) and T' = (B, A, Q) sharing edge 0 (A -> B in T), with
// random values and gradients; the one-sided values and gradients at points along the edge.
struct EdgePair {
  PlaneFrame plane;
  std::array<Vec3, 3> V, W;  // T, T'
  std::array<Rgb, 3> f, fW;
  std::array<RgbGradient, 3> g, gW;
  double gradientScale = 0.0;
};
EdgePair randomEdgePair(std::mt19937& random) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  EdgePair e;
  e.plane = randomPlane(random);
  const Vec3 A = e.plane.at({-0.5 + 0.2 * u(random), 0.1 * u(random)});
  const Vec3 B = e.plane.at({0.5 + 0.2 * u(random), 0.1 * u(random)});
  const Vec3 P = e.plane.at({0.6 * u(random), 0.5 + 0.3 * u(random)});
  const Vec3 Q = e.plane.at({0.6 * u(random), -0.5 - 0.3 * u(random)});
  e.V = {A, B, P};
  e.W = {B, A, Q};
  const Rgb fA(u(random), u(random), u(random)), fB(u(random), u(random), u(random));
  RgbGradient gA, gB, gP, gQ;
  for (RgbGradient* g : {&gA, &gB, &gP, &gQ})
    for (Vec3& gc : *g) gc = e.plane.vector({u(random), u(random)});
  e.f = {fA, fB, Rgb(u(random), u(random), u(random))};
  e.fW = {fB, fA, Rgb(u(random), u(random), u(random))};
  e.g = {gA, gB, gP};
  e.gW = {gB, gA, gQ};
  for (const RgbGradient* g : {&gA, &gB, &gP, &gQ})
    for (const Vec3& gc : *g) e.gradientScale = std::max(e.gradientScale, glm::length(gc));
  return e;
}

struct Jump {
  double value = 0.0, gradient = 0.0;
};
Jump jumpAcrossSharedEdge(const EdgePair& e, const std::array<CrossBoundary, 3>& edgesT,
                          const std::array<CrossBoundary, 3>& edgesW) {
  const CloughTocherPatch T = buildCloughTocher(e.V, e.f, e.g, edgesT);
  const CloughTocherPatch W = buildCloughTocher(e.W, e.fW, e.gW, edgesW);
  Jump jump;
  for (int i = 0; i <= 40; ++i) {
    const double s = i / 40.0;
    const Sample a = evaluate(T, Vec3(1.0 - s, s, 0.0)), b = evaluate(W, Vec3(s, 1.0 - s, 0.0));
    for (int c = 0; c < 3; ++c) {
      jump.value = std::max(jump.value, std::abs(a.B[c] - b.B[c]));
      jump.gradient = std::max(jump.gradient, glm::length(a.gradient[c] - b.gradient[c]) / e.gradientScale);
    }
  }
  return jump;
}

std::array<CrossBoundary, 3> sharedEdgeConditions(const std::array<Vec3, 3>& V, const Vec3& neighbourC,
                                                  Variant variant) {
  std::array<CrossBoundary, 3> edges = boundaryEdges(V, variant);
  if (variant == Variant::Affine) edges[0].d = affineCrossDirection(V[0], V[1], (V[0] + V[1] + V[2]) / 3.0, neighbourC);
  return edges;
}

TEST(CloughTocher, NeighboursSharingDirectionAndEndGradientsJoinC1) {
  std::mt19937 random(5);
  for (int trial = 0; trial < 50; ++trial) {
    const EdgePair e = randomEdgePair(random);
    const Vec3 CT = (e.V[0] + e.V[1] + e.V[2]) / 3.0, CW = (e.W[0] + e.W[1] + e.W[2]) / 3.0;
    for (const Variant variant : {Variant::Book, Variant::Affine}) {
      const Jump jump =
          jumpAcrossSharedEdge(e, sharedEdgeConditions(e.V, CW, variant), sharedEdgeConditions(e.W, CT, variant));
      EXPECT_LE(jump.value, 1e-14) << name(variant) << " trial " << trial;
      EXPECT_LE(jump.gradient, 1e-13) << name(variant) << " trial " << trial;
    }
    // Full elements given the same derivative along the same d at the midpoint (its sign
    // follows d's) join C1 too.
    std::array<CrossBoundary, 3> edgesT = sharedEdgeConditions(e.V, CW, Variant::Affine);
    std::array<CrossBoundary, 3> edgesW = sharedEdgeConditions(e.W, CT, Variant::Affine);
    edgesT[0].reduced = edgesW[0].reduced = false;
    edgesT[0].midDerivative = Rgb(0.3, -0.2, 0.7);
    edgesW[0].midDerivative = -edgesT[0].midDerivative;
    const Jump full = jumpAcrossSharedEdge(e, edgesT, edgesW);
    EXPECT_LE(full.value, 1e-14) << "full, trial " << trial;
    EXPECT_LE(full.gradient, 1e-13) << "full, trial " << trial;
  }
}

TEST(CloughTocher, NotC1WithoutTheReducedConditionOrWithDifferentDirections) {
  std::mt19937 random(6);
  double worstValue = 0.0, fullJump = 1e300, mixedJump = 1e300;
  for (int trial = 0; trial < 50; ++trial) {
    const EdgePair e = randomEdgePair(random);
    const Vec3 CT = (e.V[0] + e.V[1] + e.V[2]) / 3.0, CW = (e.W[0] + e.W[1] + e.W[2]) / 3.0;
    // One side the full element with a mid-edge derivative off the linear one.
    std::array<CrossBoundary, 3> edgesT = sharedEdgeConditions(e.V, CW, Variant::Affine);
    edgesT[0].reduced = false;
    edgesT[0].midDerivative = 0.5 * (along(e.g[0], edgesT[0].d) + along(e.g[1], edgesT[0].d)) + Rgb(0.5);
    const Jump full = jumpAcrossSharedEdge(e, edgesT, sharedEdgeConditions(e.W, CT, Variant::Affine));
    // Both reduced, one with the book's direction, the other with the affine one.
    const Jump mixed = jumpAcrossSharedEdge(e, sharedEdgeConditions(e.V, CW, Variant::Book),
                                            sharedEdgeConditions(e.W, CT, Variant::Affine));
    worstValue = std::max({worstValue, full.value, mixed.value});
    fullJump = std::min(fullJump, full.gradient);
    mixedJump = std::min(mixedJump, mixed.gradient);
  }
  std::printf(
      "  smallest derivative jump over 50 pairs (relative to the largest corner gradient): "
      "full element %.2e, book vs affine d %.2e\n",
      fullJump, mixedJump);
  EXPECT_LE(worstValue, 1e-14) << "still C0: values along an edge depend on its own data only";
  EXPECT_GT(fullJump, 1e-3);
  EXPECT_GT(mixedJump, 1e-6);
}

// The three pieces join C1 across the inner edges V_i - C, whatever the data.
TEST(CloughTocher, PiecesJoinC1AcrossTheInnerEdges) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 100; ++trial) {
    const PlaneFrame plane = randomPlane(random);
    const std::array<Vec3, 3> V{plane.at({u(random), u(random)}), plane.at({u(random), u(random)}),
                                plane.at({u(random), u(random)})};
    std::array<Rgb, 3> f;
    std::array<RgbGradient, 3> g;
    double scale = 0.0;
    for (int i = 0; i < 3; ++i) {
      f[i] = Rgb(u(random), u(random), u(random));
      for (Vec3& gc : g[i]) {
        gc = plane.vector({u(random), u(random)});
        scale = std::max(scale, glm::length(gc));
      }
    }
    std::array<CrossBoundary, 3> edges = boundaryEdges(V, trial % 2 ? Variant::Book : Variant::Affine);
    edges[1].reduced = false;
    edges[1].midDerivative = Rgb(u(random), u(random), u(random));
    const CloughTocherPatch patch = buildCloughTocher(V, f, g, edges);
    // Scale of the gradients inside: the data's, or that of the control values over the size.
    for (const auto& piece : patch.control)
      for (const Rgb& b : piece)
        for (const Vec3& gl : patch.frame.grad) scale = std::max(scale, glm::length(b) * glm::length(gl));
    for (int i = 0; i < 3; ++i)
      for (int s = 0; s <= 10; ++s) {
        Vec3 corner(0.0);
        corner[i] = 1.0;
        const Vec3 lambda = (1.0 - s / 10.0) * corner + (s / 10.0) * Vec3(1.0 / 3.0);
        const Sample a = evaluatePiece(patch, i, lambda), b = evaluatePiece(patch, (i + 2) % 3, lambda);
        for (int c = 0; c < 3; ++c) {
          EXPECT_NEAR(a.B[c], b.B[c], 1e-14) << "trial " << trial << " inner edge " << i;
          EXPECT_LE(glm::length(a.gradient[c] - b.gradient[c]), 1e-13 * scale)
              << "trial " << trial << " inner edge " << i;
        }
      }
  }
}

}  // namespace
}  // namespace radview
