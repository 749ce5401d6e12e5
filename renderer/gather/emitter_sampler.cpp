#include "gather/emitter_sampler.h"

#include "core/error.h"
#include "geom/polygon.h"

#include <algorithm>
#include <cmath>

namespace radview {

namespace {

double meanOf(const Rgb& E) { return (E.r + E.g + E.b) / 3.0; }

}  // namespace

EmitterSampler::EmitterSampler(const RadiosityMesh& mesh) {
  build(mesh.elements.size(), [&](size_t e) {
    return std::pair{mesh.cornerPositions(e), &mesh.materials[size_t(mesh.elements[e].material)]};
  });
}

EmitterSampler::EmitterSampler(const Scene& scene) {
  build(scene.polygons.size(), [&](size_t p) {
    return std::pair{scene.polygons[p].vertices, &scene.materials[size_t(scene.polygons[p].material)]};
  });
}

template <class PolygonAt>
void EmitterSampler::build(size_t count, const PolygonAt& polygonAt) {
  // Choosing an emitter by power, then a point uniformly on it, is the same as choosing one of
  // its triangles by power, then a point uniformly on the triangle: one table does both.
  std::vector<double> power;
  for (size_t e = 0; e < count; ++e) {
    const auto [corners, materialOf] = polygonAt(e);
    const Material& material = *materialOf;
    if (!material.isEmitter() || meanOf(material.E) <= 0.0) continue;
    const Vec3 normal = unitNormal(corners);
    if (normal == Vec3(0.0)) continue;
    for (const auto& t : triangulatePolygon(corners)) {
      const Triangle triangle{
          corners[size_t(t[0])], corners[size_t(t[1])], corners[size_t(t[2])], normal, material.E, 0.0, uint32_t(e)};
      const double a = 0.5 * glm::length(glm::cross(triangle.b - triangle.a, triangle.c - triangle.a));
      if (!(a > 0.0)) continue;
      triangles_.push_back(triangle);
      power.push_back(a * meanOf(material.E));
    }
  }
  double total = 0.0;
  for (double p : power) total += p;
  for (size_t i = 0; i < triangles_.size(); ++i) {
    triangles_[i].pdfArea = meanOf(triangles_[i].E) / total;
    cumulative_.push_back((cumulative_.empty() ? 0.0 : cumulative_.back()) + power[i] / total);
  }
  if (!cumulative_.empty()) cumulative_.back() = 1.0;
  totalPower_ = total;
}

double EmitterSampler::pdfArea(const Rgb& E) const {
  const double meanE = meanOf(E);
  return triangles_.empty() || meanE <= 0.0 ? 0.0 : meanE / totalPower_;
}

EmitterSample EmitterSampler::sample(double uPick, double u1, double u2) const {
  RADVIEW_CHECK(!triangles_.empty());
  const size_t i =
      std::min(size_t(std::upper_bound(cumulative_.begin(), cumulative_.end(), uPick) - cumulative_.begin()),
               triangles_.size() - 1);
  const Triangle& t = triangles_[i];
  // Uniform on the triangle (pbrt's UniformSampleTriangle).
  const double s = std::sqrt(u1);
  const double b0 = 1.0 - s, b1 = u2 * s;
  return {b0 * t.a + b1 * t.b + (1.0 - b0 - b1) * t.c, t.normal, t.E, t.pdfArea, t.element};
}

}  // namespace radview
