#pragma once
// The check that a piecewise Bezier patch (Clough-Tocher, Powell-Sabin) evaluates the piece
// that holds the point: every piece whose triangle holds x gives, from its own control net and
// its own barycentric frame, the value and gradient the patch's evaluation gave.
#include "interp/bezier_triangle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>

namespace radview::test {

// `pieceAt(p)` is piece p's {triangle, control net}; tolerances on B and on the gradient
// (relative to 1 + its length).
template <size_t N, class PieceAt>
void expectThePieceHoldingXIsEvaluated(const Sample& got, const Vec3& x, int pieces, const PieceAt& pieceAt,
                                       double valueTolerance, double gradientTolerance) {
  int holding = 0;
  for (int p = 0; p < pieces; ++p) {
    const auto [triangle, control] = pieceAt(p);
    const BarycentricFrame piece = barycentricFrame(triangle);
    const Vec3 sigma = piece(x);
    if (std::min({sigma.x, sigma.y, sigma.z}) < -1e-12) continue;
    ++holding;
    const Sample expected = sampleBezier<N>(control, piece, sigma);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(got.B[c], expected.B[c], valueTolerance) << "piece " << p;
      EXPECT_LE(glm::length(got.gradient[c] - expected.gradient[c]),
                gradientTolerance * (1.0 + glm::length(expected.gradient[c])))
          << "piece " << p;
    }
  }
  EXPECT_GE(holding, 1) << "no piece holds the point";
}

}  // namespace radview::test
