#include "interp/powell_sabin.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>

namespace radview {

namespace {

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool lexicographicallyLess(const Vec3& a, const Vec3& b) {
  if (a.x != b.x) return a.x < b.x;
  if (a.y != b.y) return a.y < b.y;
  return a.z < b.z;
}

// Side lengths opposite each vertex: the incenter's barycentric weights.
Vec3 oppositeSides(const Vec3& V0, const Vec3& V1, const Vec3& V2) {
  return {glm::length(V2 - V1), glm::length(V0 - V2), glm::length(V1 - V0)};
}

constexpr double kMinSplit = 1e-9;  // keeps both pieces of an edge's pair non-degenerate

}  // namespace

Vec3 incenter(const Vec3& V0, const Vec3& V1, const Vec3& V2) {
  const Vec3 w = oppositeSides(V0, V1, V2);
  const double perimeter = w.x + w.y + w.z;
  return perimeter > 0.0 ? (w.x * V0 + w.y * V1 + w.z * V2) / perimeter : V0;
}

Vec3 edgeSplitPoint(const Vec3& Vi, const Vec3& Vj, const Vec3& Z, const Vec3& Zneighbour) {
  const bool swap = lexicographicallyLess(Vj, Vi);
  const Vec3& A = swap ? Vj : Vi;
  const Vec3& B = swap ? Vi : Vj;
  const Vec3 E = B - A;
  const double E2 = glm::dot(E, E);
  if (!(E2 > 0.0)) return A;
  // r and r' scaled by |E|, which cancels in the ratio.
  const double r = glm::length(glm::cross(E, Z - A)), rN = glm::length(glm::cross(E, Zneighbour - A));
  const double tZ = glm::dot(Z - A, E) / E2, tZN = glm::dot(Zneighbour - A, E) / E2;
  const double t = r + rN > 0.0 ? (rN * tZ + r * tZN) / (r + rN) : 0.5;
  return A + std::clamp(t, 0.0, 1.0) * E;
}

// Control values of the six quadratic pieces (Powell & Sabin 1977; Reichert's scheme, C&W
// §9.2.2). With T_i(q) = f_i + g_i . (q - V_i) the tangent plane at V_i:
//   at V_i: f_i; at the midpoints of V_i - R and V_i - Z: T_i there. The three control points
//     at V_i are then in its tangent plane: B interpolates f_i and g_i, and the pieces around
//     V_i join C1 there.
//   at R_k: (1 - t) b(V_k R) + t b(V_k+1 R), R dividing the segment between the two edge
//     midpoints (V_k + R)/2 and (V_k+1 + R)/2 in the ratio t : 1 - t. The edge's three control
//     values are then collinear: C1 across the inner edge R_k - Z.
//   at (R_k + Z)/2: likewise from b(V_k Z) and b(V_k+1 Z), the same ratio.
//   at Z: sum_i zeta_i b(V_i Z), as Z = sum_i zeta_i (V_i + Z)/2.
// The seven control values around Z are then in one plane (the affine function through the
// three b(V_i Z)), which makes the pieces join C1 at Z and across the inner edges V_i - Z
// (there the other control values are in V_i's tangent plane) and R_k - Z.
// Across the outer edge k, to a neighbour with incenter Z' and the same R, g_k and g_k+1:
// quadratic pieces (V_k, R, Z) and (V_k, R, Z') join C1 iff each control value next to the
// edge on the far side is the near piece's degree-1 blend at Z' = alpha V_k + beta R + gamma Z:
//   b(V_k Z') = alpha f_k + beta b(V_k R) + gamma b(V_k Z)   (holds: all three in T_k),
//   b(R Z')   = alpha b(V_k R) + beta b(R) + gamma b(R Z).
// If R lies on the segment Z - Z', R = s Z + (1 - s) Z', then alpha = 0 and the second reads
// s b(R Z) + (1 - s) b(R Z') = b(R), which holds by itself: b(R Z) = (1 - t) T_k((V_k + Z)/2)
// + t T_k+1((V_k+1 + Z)/2) with T affine, so the left side is (1 - t) T_k((V_k + R)/2) +
// t T_k+1((V_k+1 + R)/2) = b(R). Any R off that segment (the edge midpoint, or where the
// centroids' segment crosses) gives alpha != 0 and, in general, a jump in the derivative
// across the edge. Likewise for the pieces at V_k+1.
// A quadratic q with its gradients gives every control value as its blossom (polar form), so
// q is reproduced: b(V R) = q[V, R], b(R) = q[R, R] by affinity in each argument, etc.
PowellSabinPatch buildPowellSabin(const std::array<Vec3, 3>& V, const std::array<Rgb, 3>& f,
                                  const std::array<RgbGradient, 3>& g, const std::array<Vec3, 3>& R) {
  for (int i = 0; i < 3; ++i) {
    RADVIEW_CHECK(finite(V[i]) && finite(f[i]) && finite(R[i]));
    for (const Vec3& gc : g[i]) RADVIEW_CHECK(finite(gc));
  }
  PowellSabinPatch P;
  P.frame = barycentricFrame(V);
  if (P.frame.degenerate) {
    P.zeta = Vec3(1.0 / 3.0);
    P.Z = (V[0] + V[1] + V[2]) / 3.0;
    const Rgb fZ = (f[0] + f[1] + f[2]) / 3.0;
    for (int k = 0; k < 3; ++k) {
      const int k1 = (k + 1) % 3;
      P.t[k] = 0.5;
      const Rgb fR = 0.5 * (f[k] + f[k1]);
      P.control[2 * k] = linearBezierNet<6>({f[k], fR, fZ});
      P.control[2 * k + 1] = linearBezierNet<6>({f[k1], fR, fZ});
    }
    return P;
  }
  const Vec3 w = oppositeSides(V[0], V[1], V[2]);
  P.zeta = w / (w.x + w.y + w.z);
  P.Z = P.zeta.x * V[0] + P.zeta.y * V[1] + P.zeta.z * V[2];

  std::array<Rgb, 3> bVZ;  // at (V_i + Z)/2
  for (int i = 0; i < 3; ++i) bVZ[i] = f[i] + along(g[i], P.Z - V[i]) / 2.0;
  const Rgb bZ = P.zeta.x * bVZ[0] + P.zeta.y * bVZ[1] + P.zeta.z * bVZ[2];
  for (int k = 0; k < 3; ++k) {
    const int k1 = (k + 1) % 3;
    const Vec3 E = V[k1] - V[k];
    const double t = std::clamp(glm::dot(R[k] - V[k], E) / glm::dot(E, E), kMinSplit, 1.0 - kMinSplit);
    P.t[k] = t;
    const Rgb bVR = f[k] + t * along(g[k], E) / 2.0;             // at (V_k + R)/2
    const Rgb bV1R = f[k1] - (1.0 - t) * along(g[k1], E) / 2.0;  // at (V_k+1 + R)/2
    const Rgb bR = (1.0 - t) * bVR + t * bV1R;
    const Rgb bRZ = (1.0 - t) * bVZ[k] + t * bVZ[k1];
    // b200 b110 b101 b020 b011 b002
    P.control[2 * k] = {f[k], bVR, bVZ[k], bR, bRZ, bZ};
    P.control[2 * k + 1] = {f[k1], bV1R, bVZ[k1], bR, bRZ, bZ};
  }
  return P;
}

namespace {

// The point's coordinates (a, b, mu) in the fan triangle (V_k, V_k1, Z), from V_o = (Z -
// zeta_k V_k - zeta_k1 V_k1) / zeta_o (o = k + 2): mu = lambda_o / zeta_o, a = lambda_k -
// mu zeta_k, b = lambda_k1 - mu zeta_k1; and their gradients.
struct FanCoordinates {
  double a, b, mu;
  Vec3 gradA, gradB, gradMu;
};
FanCoordinates fanCoordinates(const PowellSabinPatch& patch, int k, const Vec3& lambda) {
  const int k1 = (k + 1) % 3, o = (k + 2) % 3;
  const Vec3& zeta = patch.zeta;
  const std::array<Vec3, 3>& gl = patch.frame.grad;
  FanCoordinates fan;
  fan.mu = lambda[o] / zeta[o];
  fan.a = lambda[k] - fan.mu * zeta[k];
  fan.b = lambda[k1] - fan.mu * zeta[k1];
  fan.gradMu = gl[o] / zeta[o];
  fan.gradA = gl[k] - zeta[k] * fan.gradMu;
  fan.gradB = gl[k1] - zeta[k1] * fan.gradMu;
  return fan;
}

}  // namespace

Sample evaluatePiece(const PowellSabinPatch& patch, int piece, const Vec3& lambda) {
  const int k = piece / 2;
  const double t = patch.t[k];
  const FanCoordinates fan = fanCoordinates(patch, k, lambda);
  if (piece % 2 == 0) {  // (V_k, R_k, Z), with V_k1 = (R_k - (1 - t) V_k) / t
    const Vec3 sigma(fan.a - fan.b * (1.0 - t) / t, fan.b / t, fan.mu);
    return toWorld(evaluateBezier(patch.control[piece], sigma),
                   {fan.gradA - fan.gradB * ((1.0 - t) / t), fan.gradB / t, fan.gradMu});
  }
  // (V_k1, R_k, Z), with V_k = (R_k - t V_k1) / (1 - t)
  const Vec3 sigma(fan.b - fan.a * t / (1.0 - t), fan.a / (1.0 - t), fan.mu);
  return toWorld(evaluateBezier(patch.control[piece], sigma),
                 {fan.gradB - fan.gradA * (t / (1.0 - t)), fan.gradA / (1.0 - t), fan.gradMu});
}

Sample evaluate(const PowellSabinPatch& patch, const Vec3& lambda) {
  // The fan triangle (V_k, V_k1, Z) holding the point is the one whose mu = lambda_o / zeta_o
  // is the smallest: its (a, b, mu) are all >= 0 exactly then.
  const Vec3 mu = lambda / patch.zeta;
  const int o = mu.x <= mu.y ? (mu.x <= mu.z ? 0 : 2) : (mu.y <= mu.z ? 1 : 2);
  const int k = (o + 1) % 3;
  // The line Z - R_k splits it where a : b = (1 - t) : t. On the V_k side b / t <= a / (1 - t),
  // on the other a / (1 - t) <= b / t: a small t or 1 - t only divides where it cannot amplify.
  const FanCoordinates fan = fanCoordinates(patch, k, lambda);
  const double t = patch.t[k];
  return evaluatePiece(patch, fan.b * (1.0 - t) <= fan.a * t ? 2 * k : 2 * k + 1, lambda);
}

}  // namespace radview
