#pragma once
// Triangular Bezier patches over a 3D triangle (C&W §9.2.2, eq. 9.7, fig. 9.11): the
// per-piece mathematics under the Clough-Tocher and Powell-Sabin interpolants. Values are RGB;
// gradients are world-space vectors in the triangle's plane, one per channel.
#include "core/types.h"
#include "interp/interpolant.h"

#include <array>
#include <cstddef>
#include <ostream>

namespace radview {

using RgbGradient = std::array<Vec3, 3>;  // [c] = gradient of channel c

// The barycentric coordinate functions lambda_i of a triangle V, as the affine functions of
// space they are: lambda_i(x) = dot(grad[i], x - V[i+1]), i.e. each measured from a vertex of
// the edge where it vanishes (so a point near an edge gets its small coordinate with a small
// absolute error). Points off the plane are projected onto it (grad lies in the plane).
//
// grad[i] = N x (V[i+2] - V[i+1]) / |N|^2 with N the area vector, taken as the cross product
// of the two edges that meet at the triangle's largest angle (the vertex opposite the longest
// edge): that angle has the largest sine of the three, so the cross product cancels least.
// On a needle (one short edge) N then comes from the short edge and a long one, nearly
// orthogonal: grad is exact to ~1e-13 at aspect 1e7, where N from the two long edges loses
// ~1e-9. lambda(x) itself is ill-conditioned on any sliver: rounding x - V to doubles moves x
// by ~eps |x - V| and lambda by that over the triangle's height, and that bound, ~eps * aspect,
// is what this (and every double-precision formulation measured) attains.
// Degenerate (|N| <= 16 eps L^2, L the longest edge: the normal is round-off): grad is zero
// and lambda(x) projects x onto the longest edge (clamped to it), coordinate 0 for the third
// vertex; all three vertices coincident: (1/3, 1/3, 1/3). Never NaN for finite input.
struct BarycentricFrame {
  std::array<Vec3, 3> V{};
  std::array<Vec3, 3> grad{};
  bool degenerate = true;

  Vec3 operator()(const Vec3& x) const;  // (lambda_0, lambda_1, lambda_2), summing to 1
};
BarycentricFrame barycentricFrame(const std::array<Vec3, 3>& V);

// Control values b_ijk of a triangular Bezier patch of degree n = 1..3, i + j + k = n, stored
// by descending i then descending j: b_n00, b_(n-1)10, b_(n-1)01, b_(n-2)20, ...; for n = 3
// that is b300 b210 b201 b120 b111 b102 b030 b021 b012 b003. The degree follows from the
// size: 3, 6 or 10 control values.
constexpr int bezierIndex(int n, int i, int j) { return (n - i) * (n - i + 1) / 2 + (n - i - j); }

// B and its partial derivatives dB/dbeta_i, the beta taken as independent variables.
struct BezierJet {
  Rgb B{0.0};
  std::array<Rgb, 3> dBeta{};
};

// C&W eq. 9.7, B(beta) = sum n!/(i!j!k!) bu^i bv^j bw^k b_ijk, by de Casteljau's algorithm:
// convex combinations only inside the triangle, and an affine (stable) extrapolation for
// beta slightly outside [0, 1].
BezierJet evaluateBezier(int n, const Rgb* b, const Vec3& beta);
template <size_t N>
BezierJet evaluateBezier(const std::array<Rgb, N>& b, const Vec3& beta) {
  static_assert(N == 3 || N == 6 || N == 10, "a triangular Bezier net of degree 1, 2 or 3");
  return evaluateBezier(N == 3 ? 1 : N == 6 ? 2 : 3, b.data(), beta);
}

// World-space value and gradient of a patch whose barycentric coordinates beta have the
// world gradients gradBeta (chain rule: grad B = sum_i dB/dbeta_i grad beta_i).
Sample toWorld(const BezierJet& jet, const std::array<Vec3, 3>& gradBeta);

// A patch of degree n over triangle V at barycentric coordinates beta.
template <size_t N>
Sample sampleBezier(const std::array<Rgb, N>& b, const BarycentricFrame& frame, const Vec3& beta) {
  return toWorld(evaluateBezier(b, beta), frame.grad);
}

// The Bezier net of the linear function with values f at the corners: b_ijk = (i f0 + j f1 +
// k f2) / n. What the interpolants fall back to on a degenerate triangle.
template <size_t N>
std::array<Rgb, N> linearBezierNet(const std::array<Rgb, 3>& f) {
  constexpr int n = N == 3 ? 1 : N == 6 ? 2 : 3;
  std::array<Rgb, N> b{};
  for (int i = n; i >= 0; --i)
    for (int j = n - i; j >= 0; --j)
      b[bezierIndex(n, i, j)] = (double(i) * f[0] + double(j) * f[1] + double(n - i - j) * f[2]) / double(n);
  return b;
}

// (dot(g[0], v), dot(g[1], v), dot(g[2], v)): the derivative of each channel along v.
inline Rgb along(const RgbGradient& g, const Vec3& v) {
  return {glm::dot(g[0], v), glm::dot(g[1], v), glm::dot(g[2], v)};
}

}  // namespace radview
