#include "trace/form_factor.h"

#include <glm/gtc/constants.hpp>

#include "core/error.h"
#include "geom/polygon.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace radview {

namespace {

// Lambert's edge term for R_i -> R_next (relative to x, scaled), times 2 pi.
double edgeTerm(const Vec3& Ri, const Vec3& Rnext, const Vec3& n) {
  const Vec3 c = glm::cross(Rnext, Ri);
  const double cLength = glm::length(c);  // |R_i| |R_i+1| sin(beta)
  // x on the edge's line: beyond the edge beta = 0 and the term vanishes; on the edge
  // itself x would be on the emitter's plane, excluded by the callers. Repeated vertices (from
  // clipping) land here too.
  if (cLength == 0.0) return 0.0;
  const double beta = std::atan2(cLength, glm::dot(Ri, Rnext));  // accurate at every angle
  return beta * glm::dot(n, c) / cLength;
}

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
  for (size_t i = 0; i < R.size(); ++i) sum += edgeTerm(R[i], R[(i + 1) % R.size()], n);
  // Above the horizon and in front of the emitter the integrand is >= 0 and the whole
  // hemisphere gives 1: clamp the rounding.
  return std::clamp(sum / glm::two_pi<double>(), 0.0, 1.0);
}

double formFactorAboveHorizon(const Vec3& x, const Vec3& n, const Vec3* polygon, size_t count) {
  double scale = 0.0;
  for (size_t i = 0; i < count; ++i) scale = std::max(scale, glm::length(polygon[i] - x));
  if (!(scale > 0.0)) return 0.0;
  double sum = 0.0;
  for (size_t i = 0; i < count; ++i)
    sum += edgeTerm((polygon[i] - x) / scale, (polygon[(i + 1) % count] - x) / scale, n);
  return sum / glm::two_pi<double>();
}

PatchFormFactor::PatchFormFactor(const std::vector<std::vector<Vec3>>& polygons) {
  double largest = 0.0;
  Bounds bounds;
  std::map<std::pair<std::array<double, 3>, std::array<double, 3>>, int> edges;
  auto key = [](const Vec3& v) { return std::array<double, 3>{v.x, v.y, v.z}; };
  for (const std::vector<Vec3>& polygon : polygons) {
    const double a = area(polygon);
    if (!(a > 0.0)) continue;
    polygons_.push_back(polygon);
    if (a > largest) {
      largest = a;
      normal_ = unitNormal(polygon);
      pointOnPlane_ = centroid(polygon);
    }
    for (size_t i = 0; i < polygon.size(); ++i) {
      const Vec3& a0 = polygon[i];
      const Vec3& a1 = polygon[(i + 1) % polygon.size()];
      bounds.extend(a0);
      auto reverse = edges.find({key(a1), key(a0)});
      if (reverse != edges.end() && reverse->second > 0)
        --reverse->second;
      else
        ++edges[{key(a0), key(a1)}];
    }
  }
  for (const auto& [edge, count] : edges)
    for (int k = 0; k < count; ++k)
      outline_.push_back(
          {Vec3(edge.first[0], edge.first[1], edge.first[2]), Vec3(edge.second[0], edge.second[1], edge.second[2])});
  size_ = bounds.diagonal();
}

double PatchFormFactor::from(const Vec3& x, const Vec3& n) const {
  RADVIEW_CHECK(isFinite(x) && isFinite(n) && std::abs(glm::dot(n, n) - 1.0) < 1e-6);
  if (polygons_.empty() || !(glm::dot(x - pointOnPlane_, normal_) > 1e-12 * size_)) return 0.0;
  double scale = 0.0;
  bool cut = false;
  for (const auto& edge : outline_) {
    scale = std::max(scale, glm::length(edge[0] - x));
    cut |= glm::dot(edge[0] - x, n) < 0.0;
  }
  if (cut) {
    double F = 0.0;
    for (const std::vector<Vec3>& polygon : polygons_) F += pointToPolygonFormFactor(x, n, polygon);
    return std::min(F, 1.0);
  }
  double sum = 0.0;
  for (const auto& edge : outline_) sum += edgeTerm((edge[0] - x) / scale, (edge[1] - x) / scale, n);
  return std::clamp(sum / glm::two_pi<double>(), 0.0, 1.0);
}

}  // namespace radview
