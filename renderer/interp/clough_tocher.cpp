#include "interp/clough_tocher.h"

#include "core/error.h"

#include <cmath>

namespace radview {

namespace {

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// C&W §9.2.2, fig. 9.12, step 3 (c): the inner control value b111 of piece k from the
// condition across its outer edge. With delta the barycentric components of d in the piece,
// the derivative along d is 3 sum_{|m|=2} B^2_m (delta0 b_m+100 + delta1 b_m+010 + delta2
// b_m+001); along the edge it is the quadratic with Bezier coefficients D0, D1, D2 (m = 200,
// 110, 020). Its ends are fixed by the corners' tangent planes,
// D0 = dot(g_k, d) / 3 and D2 = dot(g_k+1, d) / 3, and
//   reduced: D1 = (D0 + D2) / 2 (linear: the wedge's slope is the average of the ends');
//   full:    D1 = 2 m / 3 - (D0 + D2) / 2 (the midpoint value 3 (D0 + 2 D1 + D2) / 4 = m).
// D1 = delta0 b210 + delta1 b120 + delta2 b111 is then solved for b111, measured from the
// mean L of b210 and b120 (the deltas sum to 0) so that a large common offset cancels first.
Rgb innerControl(const std::array<Vec3, 3>& gradSigma, const Vec3& edgeNormal, const CrossBoundary& edge,
                 const RgbGradient& gStart, const RgbGradient& gEnd, const Rgb& b210, const Rgb& b120) {
  Vec3 d = edge.d;
  const double sine = std::abs(glm::dot(edgeNormal, d)) / (glm::length(edgeNormal) * glm::length(d));
  if (!(sine > 1e-10)) d = edgeNormal;
  const Vec3 delta(glm::dot(gradSigma[0], d), glm::dot(gradSigma[1], d), glm::dot(gradSigma[2], d));
  const Rgb D0 = along(gStart, d) / 3.0, D2 = along(gEnd, d) / 3.0;
  const Rgb D1 = edge.reduced ? 0.5 * (D0 + D2) : 2.0 / 3.0 * edge.midDerivative - 0.5 * (D0 + D2);
  const Rgb L = 0.5 * (b210 + b120);
  return L + (D1 - 0.5 * (delta.x - delta.y) * (b210 - b120)) / delta.z;
}

}  // namespace

// C&W §9.2.2, fig. 9.12, steps 1-4 (a-e); the full element is Clough & Tocher's (1965), the
// reduced one the book's; per-corner gradients are Salesin et al.'s (1992) relaxed vertices.
CloughTocherPatch buildCloughTocher(const std::array<Vec3, 3>& V, const std::array<Rgb, 3>& f,
                                    const std::array<RgbGradient, 3>& g, const std::array<CrossBoundary, 3>& edges) {
  for (int i = 0; i < 3; ++i) {
    RADVIEW_CHECK(finite(V[i]) && finite(f[i]) && finite(edges[i].d) && finite(edges[i].midDerivative));
    for (const Vec3& gc : g[i]) RADVIEW_CHECK(finite(gc));
  }
  CloughTocherPatch P;
  P.frame = barycentricFrame(V);
  P.C = (V[0] + V[1] + V[2]) / 3.0;
  if (P.frame.degenerate) {
    const Rgb fC = (f[0] + f[1] + f[2]) / 3.0;
    for (int k = 0; k < 3; ++k) P.control[k] = linearBezierNet<10>({f[k], f[(k + 1) % 3], fC});
    return P;
  }
  const std::array<Vec3, 3>& gl = P.frame.grad;

  // b on the inner edge V_i - C: in the tangent plane of V_i (step 2). Shared by the two
  // pieces at V_i, which makes them join C1 near V_i.
  std::array<Rgb, 3> bInner;
  for (int i = 0; i < 3; ++i) bInner[i] = f[i] + along(g[i], P.C - V[i]) / 3.0;

  std::array<Rgb, 3> c;
  for (int k = 0; k < 3; ++k) {
    const int k1 = (k + 1) % 3, o = (k + 2) % 3;
    std::array<Rgb, 10>& b = P.control[k];
    b[bezierIndex(3, 3, 0)] = f[k];  // a (step 1)
    b[bezierIndex(3, 0, 3)] = f[k1];
    b[bezierIndex(3, 2, 1)] = f[k] + along(g[k], V[k1] - V[k]) / 3.0;  // b: tangent planes (step 2)
    b[bezierIndex(3, 1, 2)] = f[k1] + along(g[k1], V[k] - V[k1]) / 3.0;
    b[bezierIndex(3, 2, 0)] = bInner[k];
    b[bezierIndex(3, 0, 2)] = bInner[k1];
    // Piece k's barycentric coordinates are sigma = (lambda_k - lambda_o, lambda_k1 - lambda_o,
    // 3 lambda_o); gl[o] is the edge's inward normal.
    const std::array<Vec3, 3> gradSigma{gl[k] - gl[o], gl[k1] - gl[o], 3.0 * gl[o]};
    c[k] = innerControl(gradSigma, gl[o], edges[k], g[k], g[k1], b[bezierIndex(3, 2, 1)], b[bezierIndex(3, 1, 2)]);
    b[bezierIndex(3, 1, 1)] = c[k];
  }

  // Step 4. d on the inner edge V_i - C next to C, from the plane through that edge's b and
  // the c on either side: C1 across the inner edge between pieces i-1 and i, whose far corners
  // satisfy V_i+1 = 3 C - V_i - V_i-1, asks c_i + c_i-1 + b_inner = 3 d_i. The same relation
  // one row nearer V_i holds by itself, as the b are in V_i's tangent plane, and one row
  // nearer C it gives e, the centroid value, as the mean of the three d.
  std::array<Rgb, 3> dInner;
  for (int i = 0; i < 3; ++i) dInner[i] = (bInner[i] + c[i] + c[(i + 2) % 3]) / 3.0;
  const Rgb e = (dInner[0] + dInner[1] + dInner[2]) / 3.0;
  for (int k = 0; k < 3; ++k) {
    P.control[k][bezierIndex(3, 1, 0)] = dInner[k];
    P.control[k][bezierIndex(3, 0, 1)] = dInner[(k + 1) % 3];
    P.control[k][bezierIndex(3, 0, 0)] = e;
  }
  return P;
}

Sample evaluatePiece(const CloughTocherPatch& patch, int k, const Vec3& lambda) {
  // With V_o = 3 C - V_k - V_k1 (o = k + 2), piece k's barycentric coordinates are
  // sigma = (lambda_k - lambda_o, lambda_k1 - lambda_o, 3 lambda_o).
  const int k1 = (k + 1) % 3, o = (k + 2) % 3;
  const Vec3 sigma(lambda[k] - lambda[o], lambda[k1] - lambda[o], 3.0 * lambda[o]);
  const std::array<Vec3, 3>& gl = patch.frame.grad;
  return toWorld(evaluateBezier(patch.control[k], sigma), {gl[k] - gl[o], gl[k1] - gl[o], 3.0 * gl[o]});
}

Sample evaluate(const CloughTocherPatch& patch, const Vec3& lambda) {
  // Piece k's sigma are all >= 0 exactly where lambda_o is the smallest.
  const int o = lambda.x <= lambda.y ? (lambda.x <= lambda.z ? 0 : 2) : (lambda.y <= lambda.z ? 1 : 2);
  return evaluatePiece(patch, (o + 1) % 3, lambda);
}

Vec3 bookCrossDirection(const Vec3& V_k, const Vec3& V_k1, const Vec3& C) {
  const Vec3 e = V_k1 - V_k, w = C - V_k;
  const double e2 = glm::dot(e, e);
  const Vec3 n = e2 > 0.0 ? w - (glm::dot(w, e) / e2) * e : w;
  const double length = glm::length(n);
  return length > 0.0 ? n / length : n;
}

Vec3 affineCrossDirection(const Vec3& V_k, const Vec3& V_k1, const Vec3& C, const std::optional<Vec3>& neighbourC) {
  return neighbourC ? *neighbourC - C : C - 0.5 * (V_k + V_k1);
}

}  // namespace radview
