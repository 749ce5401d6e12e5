#include "interp/surface_point.h"

#include "core/error.h"
#include "interp/bezier_triangle.h"
#include "mesh/display_mesh.h"

#include <limits>

namespace radview {

Vec3 closestOnTriangle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& p) {
  const Vec3 w = barycentricFrame({a, b, c})(p);
  if (w.x >= 0 && w.y >= 0 && w.z >= 0) return w.x * a + w.y * b + w.z * c;
  auto onSegment = [&](const Vec3& s, const Vec3& e) {
    const Vec3 d = e - s;
    const double length2 = glm::dot(d, d);
    const double t = length2 > 0.0 ? glm::clamp(glm::dot(p - s, d) / length2, 0.0, 1.0) : 0.0;
    return s + t * d;
  };
  Vec3 best = onSegment(a, b);
  for (const Vec3& q : {onSegment(b, c), onSegment(c, a)})
    if (glm::length(q - p) < glm::length(best - p)) best = q;
  return best;
}

SurfacePoint nearestSurfacePoint(const RadiosityMesh& mesh, const Vec3& p) {
  if (mesh.elements.empty()) throw Error("the mesh has no elements to sample");
  SurfacePoint best;
  best.distance = std::numeric_limits<double>::infinity();
  for (uint32_t e = 0; e < mesh.elements.size(); ++e)
    for (const auto& t : elementTriangles(mesh, e)) {
      const Vec3 q =
          closestOnTriangle(mesh.nodes[t[0]].position, mesh.nodes[t[1]].position, mesh.nodes[t[2]].position, p);
      const double d = glm::length(q - p);
      if (d < best.distance) best = {e, q, d};
    }
  return best;
}

Vec3 pointFromBarycentric(const RadiosityMesh& mesh, uint32_t element, const Vec3& b) {
  const auto& c = mesh.elements[element].corners;
  return b.x * mesh.nodes[c[0]].position + b.y * mesh.nodes[c[1]].position + b.z * mesh.nodes[c[2]].position;
}

}  // namespace radview
