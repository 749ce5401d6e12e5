#pragma once
// Directions about a surface normal for Monte Carlo estimates of the integral of eq. 9.9.
#include "core/types.h"

#include <cmath>

namespace radview {

// An orthonormal basis (t, b, n) for a unit n, continuous except across n.z = -1's sign flip
// (Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 2017).
inline void orthonormalBasis(const Vec3& n, Vec3& t, Vec3& b) {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double c = n.x * n.y * a;
  t = Vec3(1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x);
  b = Vec3(c, sign + n.y * n.y * a, -n.y);
}

// A direction with density cos(theta) / pi over the hemisphere about the unit normal n, from
// two uniforms in [0, 1): Shirley and Chiu's concentric map of the square to the disc, lifted
// to the hemisphere (Malley's method; pbrt's CosineSampleHemisphere). The concentric map keeps
// strata of the square compact on the disc.
inline Vec3 cosineWeightedDirection(const Vec3& n, double u1, double u2) {
  constexpr double kPi = 3.14159265358979323846;
  const double a = 2.0 * u1 - 1.0, b = 2.0 * u2 - 1.0;
  double r = 0.0, phi = 0.0;
  if (a != 0.0 || b != 0.0) {
    if (std::abs(a) > std::abs(b)) {
      r = a;
      phi = kPi / 4.0 * (b / a);
    } else {
      r = b;
      phi = kPi / 2.0 - kPi / 4.0 * (a / b);
    }
  }
  const double x = r * std::cos(phi), y = r * std::sin(phi);
  const double z = std::sqrt(std::max(0.0, 1.0 - x * x - y * y));
  Vec3 t, s;
  orthonormalBasis(n, t, s);
  return glm::normalize(x * t + y * s + z * n);
}

}  // namespace radview
