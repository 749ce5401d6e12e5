#include "edit/edge_picker.h"

#include "trace/camera_rays.h"
#include "trace/visible_elements.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace radview {

namespace {

double distanceToSegment(const Vec3& x, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double length2 = glm::dot(ab, ab);
  const double t = length2 > 0.0 ? std::clamp(glm::dot(x - a, ab) / length2, 0.0, 1.0) : 0.0;
  return glm::length(x - (a + t * ab));
}

}  // namespace

EdgePicker::EdgePicker(const RadiosityMesh& mesh) : caster_(std::make_unique<RayCaster>(elementScene(mesh))) {
  corners_.reserve(mesh.elements.size());
  for (size_t e = 0; e < mesh.elements.size(); ++e) corners_.push_back(mesh.cornerPositions(e));
}

std::optional<EdgeRef> EdgePicker::pick(const Camera& camera, int width, int height, double px, double py,
                                        double tolerancePixels) const {
  const CameraRays rays(camera, width, height);
  const std::optional<RayHit> hit = caster_->closestHit(rays.through(px, py));
  if (!hit) return std::nullopt;
  const std::vector<Vec3>& corners = corners_[hit->polygon];
  EdgeRef best{uint32_t(hit->polygon), 0};
  double nearest = std::numeric_limits<double>::infinity();
  for (uint32_t i = 0; i < corners.size(); ++i) {
    const double d = distanceToSegment(hit->position, corners[i], corners[(i + 1) % corners.size()]);
    if (d < nearest) nearest = d, best.edge = i;
  }
  // A pixel's size at the hit: the view's height spans 2 d tan(fov / 2) there.
  const double pixel = 2.0 * hit->distance * std::tan(0.5 * camera.yfov) / height;
  if (!(nearest <= tolerancePixels * pixel)) return std::nullopt;
  return best;
}

std::vector<EdgeRef> EdgePicker::pickAlong(const Camera& camera, int width, int height,
                                           const std::vector<std::pair<double, double>>& points,
                                           double tolerancePixels) const {
  std::vector<EdgeRef> edges;
  auto add = [&](double x, double y) {
    if (const std::optional<EdgeRef> e = pick(camera, width, height, x, y, tolerancePixels))
      if (std::find(edges.begin(), edges.end(), *e) == edges.end()) edges.push_back(*e);
  };
  for (size_t i = 0; i < points.size(); ++i) {
    if (i == 0) {
      add(points[0].first, points[0].second);
      continue;
    }
    // Every pixel or so between the stroke's samples, so a fast drag misses no edge.
    const auto [x0, y0] = points[i - 1];
    const auto [x1, y1] = points[i];
    const int steps = std::max(1, int(std::ceil(std::hypot(x1 - x0, y1 - y0))));
    for (int s = 1; s <= steps; ++s) add(x0 + (x1 - x0) * s / steps, y0 + (y1 - y0) * s / steps);
  }
  return edges;
}

}  // namespace radview
