#include "interp/surface_locator.h"

#include "core/error.h"
#include "geom/embree_device.h"
#include "mesh/display_mesh.h"

#include <cmath>
#include <limits>

namespace radview {

struct SurfaceLocator::Embree {
  EmbreeDevice device{"locating points on the mesh"};
  RTCScene scene = nullptr;
  ~Embree() {
    if (scene) rtcReleaseScene(scene);
  }
};

struct SurfaceLocator::Query {
  const SurfaceLocator* locator;
  Vec3 p;
  SurfacePoint best;
  uint32_t bestTriangle = std::numeric_limits<uint32_t>::max();
};

namespace {

// Each triangle's box, in double, then rounded outwards to float: the box Embree holds
// contains the triangle exactly, whatever the rounding.
struct Boxes {
  const RadiosityMesh* mesh;
  const std::vector<std::array<uint32_t, 3>>* triangles;
  Vec3 center;
  double scale;
};

void triangleBounds(const RTCBoundsFunctionArguments* args) {
  const auto* boxes = static_cast<const Boxes*>(args->geometryUserPtr);
  const auto& t = (*boxes->triangles)[args->primID];
  Vec3 lower(std::numeric_limits<double>::infinity()), upper(-std::numeric_limits<double>::infinity());
  for (uint32_t n : t) {
    const Vec3 q = (boxes->mesh->nodes[n].position - boxes->center) * boxes->scale;
    lower = glm::min(lower, q);
    upper = glm::max(upper, q);
  }
  const float inf = std::numeric_limits<float>::infinity();
  auto down = [&](double v) { return std::nextafter(float(v), -inf); };
  auto up = [&](double v) { return std::nextafter(float(v), inf); };
  *args->bounds_o = {down(lower.x), down(lower.y), down(lower.z), 0.0f, up(upper.x), up(upper.y), up(upper.z), 0.0f};
}

}  // namespace

SurfaceLocator::SurfaceLocator(const RadiosityMesh& mesh) : mesh_(mesh) {
  if (mesh.elements.empty()) throw Error("the mesh has no elements to sample");
  for (uint32_t e = 0; e < mesh.elements.size(); ++e)
    for (const auto& t : elementTriangles(mesh, e)) {
      triangles_.push_back(t);
      triangleElement_.push_back(e);
    }
  triangles_.shrink_to_fit();
  triangleElement_.shrink_to_fit();
  const Bounds bounds = mesh.bounds();
  center_ = bounds.center();
  scale_ = bounds.diagonal() > 0.0 ? 1.0 / bounds.diagonal() : 1.0;

  embree_ = std::make_unique<Embree>();
  const RTCDevice device = embree_->device.get();
  embree_->scene = rtcNewScene(device);
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
  embree_->device.check("creating the triangle geometry");
  // Only read while the scene is built (rtcCommitScene, below).
  Boxes boxes{&mesh, &triangles_, center_, scale_};
  rtcSetGeometryUserPrimitiveCount(geometry, unsigned(triangles_.size()));
  rtcSetGeometryUserData(geometry, &boxes);
  rtcSetGeometryBoundsFunction(geometry, triangleBounds, &boxes);
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(embree_->scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(embree_->scene);
  embree_->device.check("building the hierarchy of the elements' triangles");
}

SurfaceLocator::~SurfaceLocator() = default;

float SurfaceLocator::queryRadius(double distance) const {
  if (!std::isfinite(distance)) return std::numeric_limits<float>::infinity();
  // In Embree's frame coordinates are within +-1, so float rounds the query point by at most
  // 6e-8 per axis; 1e-6 covers that with a wide margin.
  return std::nextafter(float(distance * scale_), std::numeric_limits<float>::infinity()) + 1e-6f;
}

bool SurfaceLocator::visit(RTCPointQueryFunctionArguments* args) {
  auto* query = static_cast<Query*>(args->userPtr);
  const SurfaceLocator& self = *query->locator;
  const uint32_t triangle = args->primID;
  const auto& t = self.triangles_[triangle];
  const auto& nodes = self.mesh_.nodes;
  const Vec3 q = closestOnTriangle(nodes[t[0]].position, nodes[t[1]].position, nodes[t[2]].position, query->p);
  const double d = glm::length(q - query->p);
  // nearestSurfacePoint keeps the first of equals in its order, which triangles_ follows.
  if (d < query->best.distance || (d == query->best.distance && triangle < query->bestTriangle)) {
    query->best = {self.triangleElement_[triangle], q, d};
    query->bestTriangle = triangle;
    args->query->radius = self.queryRadius(d);
    return true;
  }
  return false;
}

SurfacePoint SurfaceLocator::nearest(const Vec3& p, double expectedWithin) const {
  Query query{this, p, {}, std::numeric_limits<uint32_t>::max()};
  query.best.distance = std::numeric_limits<double>::infinity();
  const Vec3 e = (p - center_) * scale_;
  RTCPointQuery point;
  point.x = float(e.x), point.y = float(e.y), point.z = float(e.z);
  point.time = 0.0f;
  RTCPointQueryContext context;
  // First within expectedWithin: every triangle that near is visited, so one found that near
  // is the nearest. Else (none found, or only a farther one whose box came within reach)
  // again, within the best distance found so far.
  point.radius = queryRadius(expectedWithin);
  rtcInitPointQueryContext(&context);
  rtcPointQuery(embree_->scene, &point, &context, &SurfaceLocator::visit, &query);
  if (!(query.best.distance <= expectedWithin)) {
    point.radius = queryRadius(query.best.distance);
    rtcInitPointQueryContext(&context);
    rtcPointQuery(embree_->scene, &point, &context, &SurfaceLocator::visit, &query);
  }
  // A point beyond float's range has no place in Embree's frame: the brute force answers it.
  if (query.bestTriangle == std::numeric_limits<uint32_t>::max()) return nearestSurfacePoint(mesh_, p);
  return query.best;
}

}  // namespace radview
