#include "geom/plane_segments.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace radview {

namespace {

double cross2(const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; }

}  // namespace

double distanceToPolygonBoundary(const Vec2& p, const std::vector<Vec2>& polygon) {
  double d = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < polygon.size(); ++i)
    d = std::min(d, distanceToSegment(p, polygon[i], polygon[(i + 1) % polygon.size()]));
  return d;
}

bool strictlyInsidePolygon(const Vec2& p, const std::vector<Vec2>& polygon) {
  bool inside = false;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Vec2 &a = polygon[i], &b = polygon[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) inside = !inside;
  }
  return inside;
}

double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double lengthSquared = glm::dot(ab, ab);
  const double t = lengthSquared > 0 ? std::clamp(glm::dot(p - a, ab) / lengthSquared, 0.0, 1.0) : 0.0;
  return glm::distance(p, a + t * ab);
}

Vec2 endOntoLine(const Vec2& from, const Vec2& end, const Vec2& a, const Vec2& b, double reach) {
  const Vec2 r = end - from, s = b - a;
  if (!(glm::dot(s, s) > 0.0)) return end;
  const Vec2 projection = a + (glm::dot(end - a, s) / glm::dot(s, s)) * s;
  const double denominator = cross2(r, s);
  if (!(std::abs(denominator) > 1e-3 * glm::length(r) * glm::length(s))) return projection;
  const Vec2 meet = from + (cross2(a - from, s) / denominator) * r;
  return glm::distance(meet, end) <= reach ? meet : projection;
}

std::vector<ParameterInterval> clipSegmentToPolygon(const Vec2& a, const Vec2& b, const std::vector<Vec2>& polygon,
                                                    double tolerance) {
  const Vec2 ab = b - a;
  const double length = glm::length(ab);
  if (!(length > tolerance) || polygon.size() < 3) return {};
  // Cut the segment wherever the boundary crosses it or a polygon vertex lies near it; each
  // piece between cuts is then inside, outside or along the boundary throughout.
  std::vector<double> cuts = {0.0, 1.0};
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Vec2 &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
    const double denominator = cross2(ab, q - p);
    if (std::abs(denominator) > 1e-300) {
      const double t = cross2(p - a, q - p) / denominator, s = cross2(p - a, ab) / denominator;
      if (s >= 0 && s <= 1 && t > 0 && t < 1) cuts.push_back(t);
    }
    if (distanceToSegment(p, a, b) <= tolerance) {
      const double t = glm::dot(p - a, ab) / (length * length);
      if (t > 0 && t < 1) cuts.push_back(t);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  std::vector<ParameterInterval> inside;
  for (size_t k = 0; k + 1 < cuts.size(); ++k) {
    if ((cuts[k + 1] - cuts[k]) * length <= tolerance) continue;
    const Vec2 middle = a + (0.5 * (cuts[k] + cuts[k + 1])) * ab;
    if (distanceToPolygonBoundary(middle, polygon) <= tolerance || !strictlyInsidePolygon(middle, polygon)) continue;
    if (!inside.empty() && (cuts[k] - inside.back().t1) * length <= tolerance)
      inside.back().t1 = cuts[k + 1];
    else
      inside.push_back({cuts[k], cuts[k + 1]});
  }
  return inside;
}

}  // namespace radview
