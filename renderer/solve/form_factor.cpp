#include "solve/form_factor.h"

#include <glm/gtc/constants.hpp>

#include "core/error.h"
#include "geom/polygon.h"

#include <algorithm>
#include <cmath>

namespace radview {

namespace {


// Sutherland-Hodgman against one plane: keeps the part of the polygon with dot(p, n) >= 0.
// Vertices are relative to x, so the plane passes through the origin.
std::vector<Vec3> clipToFrontHalfSpace(const std::vector<Vec3>& R, const Vec3& n) {
  std::vector<Vec3> clipped;
  clipped.reserve(R.size() + 2);
  for (size_t i = 0; i < R.size(); ++i) {
    const Vec3& P = R[i];
    const Vec3& Q = R[(i + 1) % R.size()];
    const double dP = glm::dot(P, n), dQ = glm::dot(Q, n);
    if (dP >= 0.0) clipped.push_back(P);
    // dP - dQ is nonzero when exactly one of them is negative: t stays in [0, 1].
    if ((dP >= 0.0) != (dQ >= 0.0)) clipped.push_back(P + (dP / (dP - dQ)) * (Q - P));
  }
  return clipped;
}

}  // namespace

// Lambert's formula (C&W ch. 4; Baum, Rushmeier & Winget 1989): by Stokes' theorem the
// area integral of cos(theta) cos(theta') / (pi r^2) over the polygon becomes a sum over its
// edges,
//   F = 1/(2 pi) * sum_i  beta_i * n . (R_{i+1} x R_i) / |R_{i+1} x R_i|,
// with R_i = v_i - x and beta_i the angle between R_i and R_{i+1}. (R_{i+1} x R_i, not
// R_i x R_{i+1}: the emitter's vertices are CCW about its own normal, which faces x.)
double pointToPolygonFormFactor(const Vec3& x, const Vec3& n, const std::vector<Vec3>& polygon) {
  RADVIEW_CHECK(isFinite(x) && isFinite(n) && std::abs(glm::dot(n, n) - 1.0) < 1e-6);
  RADVIEW_CHECK(std::all_of(polygon.begin(), polygon.end(), [](const Vec3& v) { return isFinite(v); }));
  const Vec3 N = unitNormal(polygon);
  if (N == Vec3(0.0)) return 0.0;

  // Work relative to x and in units of the polygon's distance, so that nothing underflows and
  // the tolerances below are relative.
  Bounds bounds;
  double scale = 0.0;
  for (const Vec3& v : polygon) {
    bounds.extend(v);
    scale = std::max(scale, glm::length(v - x));
  }
  // x behind or on the emitter's plane: the emitter faces away or is seen edge-on.
  if (!(glm::dot(x - centroid(polygon), N) > 1e-12 * bounds.diagonal())) return 0.0;

  std::vector<Vec3> R;
  R.reserve(polygon.size());
  for (const Vec3& v : polygon) R.push_back((v - x) / scale);
  R = clipToFrontHalfSpace(R, n);
  if (R.size() < 3) return 0.0;

  double sum = 0.0;
  for (size_t i = 0; i < R.size(); ++i) {
    const Vec3& Ri = R[i];
    const Vec3& Rnext = R[(i + 1) % R.size()];
    const Vec3 c = glm::cross(Rnext, Ri);
    const double cLength = glm::length(c);  // |R_i| |R_i+1| sin(beta)
    // x on the edge's line: beyond the edge beta = 0 and the term vanishes; on the edge
    // itself x would be on the emitter's plane, excluded above. Repeated vertices (from
    // clipping) land here too.
    if (cLength == 0.0) continue;
    const double beta = std::atan2(cLength, glm::dot(Ri, Rnext));  // accurate at every angle
    sum += beta * glm::dot(n, c) / cLength;
  }
  // Above the horizon and in front of the emitter the integrand is >= 0 and the whole
  // hemisphere gives 1: clamp the rounding.
  return std::clamp(sum / glm::two_pi<double>(), 0.0, 1.0);
}

}  // namespace radview
