#include "discontinuity/critical_lines.h"

#include "geom/polygon.h"

#include <cmath>

namespace radview {

CriticalLinesByRays::CriticalLinesByRays(const Scene& scene) : caster_(scene), diagonal_(scene.bounds().diagonal()) {
  for (const Polygon& polygon : scene.polygons) normals_.push_back(unitNormal(polygon.vertices));
}

bool CriticalLinesByRays::clear(const Vec3& x, const Vec3& xNormal, const Vec3& q, const Vec3& s,
                                const Vec3& sNormal) const {
  return partClear(x, xNormal, q) && partClear(s, sNormal, q);
}

bool CriticalLinesByRays::partClear(const Vec3& from, const Vec3& fromNormal, const Vec3& q) const {
  const Vec3 d = q - from;
  const double length = glm::length(d);
  // Short of q by a ten-thousandth of the part, and by the lift of the ray's origin (hits are
  // measured from the lifted origin) twice over.
  const double margin = 1e-4 * length + 2.0 * RayCaster::kLift * diagonal_;
  if (!(length > margin)) return true;
  const Vec3 direction = d / length;
  const auto hit = caster_.closestHit({from, direction, fromNormal});
  if (!hit || hit->distance >= length - margin) return true;
  return std::abs(glm::dot(normals_[hit->polygon], direction)) < 1e-6;
}

}  // namespace radview
