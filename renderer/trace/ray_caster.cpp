#include "trace/ray_caster.h"

#include "core/error.h"
#include "geom/embree_device.h"
#include "geom/polygon.h"

#include <embree3/rtcore.h>

#include <limits>
#include <string>
#include <vector>

namespace radview {

struct RayCaster::Embree {
  EmbreeDevice device{"ray casting"};
  RTCScene scene = nullptr;

  ~Embree() {
    if (scene) rtcReleaseScene(scene);
  }
};

RayCaster::RayCaster(const Scene& scene) : embree_(std::make_unique<Embree>()) {
  for (size_t p = 0; p < scene.polygons.size(); ++p)
    for (const Vec3& v : scene.polygons[p].vertices)
      if (!isFinite(v))
        throw Error("ray casting: polygon " + std::to_string(p) + " has a vertex that is not a finite number");
  const Bounds bounds = scene.bounds();
  const double diagonal = bounds.diagonal();
  if (!std::isfinite(diagonal))
    throw Error("ray casting: the scene's size is not a finite number (coordinates too large for double)");
  center_ = bounds.center();
  scale_ = diagonal > 0.0 ? 1.0 / diagonal : 1.0;

  std::vector<float> vertices;
  std::vector<unsigned> indices;
  for (const Polygon& polygon : scene.polygons) {
    polygonNormals_.push_back(unitNormal(polygon.vertices));
    if (polygonNormals_.back() == Vec3(0.0)) {
      ++skippedPolygons_;
      continue;
    }
    const unsigned base = unsigned(vertices.size() / 3);
    for (const Vec3& p : polygon.vertices) {
      const Vec3 q = (p - center_) * scale_;
      vertices.insert(vertices.end(), {float(q.x), float(q.y), float(q.z)});
    }
    for (const auto& t : triangulatePolygon(polygon.vertices)) {
      indices.insert(indices.end(), {base + unsigned(t[0]), base + unsigned(t[1]), base + unsigned(t[2])});
      trianglePolygon_.push_back(uint32_t(polygonNormals_.size() - 1));
    }
  }
  triangleCount_ = indices.size() / 3;

  embree_->scene = rtcNewScene(embree_->device.get());
  // Robust: rays through a shared edge of two triangles hit one of them (no leaks through
  // the edges of the Cornell box's blocks into their shadows).
  rtcSetSceneFlags(embree_->scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(embree_->scene, RTC_BUILD_QUALITY_HIGH);
  if (triangleCount_ > 0) {
    RTCGeometry geometry = rtcNewGeometry(embree_->device.get(), RTC_GEOMETRY_TYPE_TRIANGLE);
    embree_->device.check("creating the triangle geometry");
    auto* vertexBuffer = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), vertices.size() / 3));
    auto* indexBuffer = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), triangleCount_));
    if (!vertexBuffer || !indexBuffer) {
      rtcReleaseGeometry(geometry);
      embree_->device.check("allocating the geometry buffers");
      throw Error("ray casting: Embree could not allocate the geometry buffers");
    }
    std::copy(vertices.begin(), vertices.end(), vertexBuffer);
    std::copy(indices.begin(), indices.end(), indexBuffer);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(embree_->scene, geometry);
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(embree_->scene);
  embree_->device.check("building the scene");
}

RayCaster::~RayCaster() = default;

void* RayCaster::embreeScene() const { return embree_->scene; }

Vec3 RayCaster::toEmbree(const Vec3& point, const Vec3& liftNormal) const {
  return (point - center_) * scale_ + kLift * liftNormal;
}

void RayCaster::embreeRay(const Segment& segment, float origin[3], float direction[3], float& tfar) const {
  const Vec3 from = toEmbree(segment.from, segment.fromNormal);
  const Vec3 to = toEmbree(segment.to, segment.toNormal);
  const Vec3 d = to - from;
  for (int k = 0; k < 3; ++k) {
    origin[k] = float(from[k]);
    direction[k] = float(d[k]);
  }
  tfar = 1.0f;
}

namespace {

void setOccludedRay(RTCRay& ray, const Vec3& from, const Vec3& to, unsigned id) {
  const Vec3 d = to - from;
  ray.org_x = float(from.x), ray.org_y = float(from.y), ray.org_z = float(from.z);
  ray.dir_x = float(d.x), ray.dir_y = float(d.y), ray.dir_z = float(d.z);
  ray.tnear = 0.0f;
  ray.tfar = 1.0f;
  ray.time = 0.0f;
  ray.mask = ~0u;
  ray.id = id;
  ray.flags = 0;
}

// One coherent stream through rtcOccluded1M; Embree marks an occluded ray by setting tfar to
// -infinity.
void castOccludedStream(RTCScene scene, std::vector<RTCRay>& rays, uint8_t* blocked) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  rtcOccluded1M(scene, &context, rays.data(), unsigned(rays.size()), sizeof(RTCRay));
  for (size_t i = 0; i < rays.size(); ++i) blocked[i] = rays[i].tfar < 0.0f ? 1 : 0;
}

}  // namespace

void RayCaster::occluded(const Segment* segments, size_t count, uint8_t* blocked) const {
  if (count == 0) return;
  thread_local std::vector<RTCRay> rays;
  rays.resize(count);
  for (size_t i = 0; i < count; ++i)
    setOccludedRay(rays[i], toEmbree(segments[i].from, segments[i].fromNormal),
                   toEmbree(segments[i].to, segments[i].toNormal), unsigned(i));
  castOccludedStream(embree_->scene, rays, blocked);
}

void RayCaster::occludedFrom(const Vec3& from, const Vec3& fromNormal, const Vec3* to, size_t count,
                             const Vec3& toNormal, uint8_t* blocked) const {
  if (count == 0) return;
  thread_local std::vector<RTCRay> rays;
  rays.resize(count);
  const Vec3 origin = toEmbree(from, fromNormal);
  for (size_t i = 0; i < count; ++i) setOccludedRay(rays[i], origin, toEmbree(to[i], toNormal), unsigned(i));
  castOccludedStream(embree_->scene, rays, blocked);
}

bool RayCaster::occluded(const Segment& segment) const {
  RTCRay ray;
  setOccludedRay(ray, toEmbree(segment.from, segment.fromNormal), toEmbree(segment.to, segment.toNormal), 0);
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcOccluded1(embree_->scene, &context, &ray);
  // Embree marks an occluded ray by setting tfar to -infinity.
  return ray.tfar < 0.0f;
}

}  // namespace radview

namespace radview {

std::optional<RayHit> RayCaster::closestHit(const Ray& ray) const {
  // The direction is a unit vector in both frames (the map to Embree's is a uniform scale), so
  // Embree's t is a distance in its frame: t / scale_ in the world.
  const Vec3 from = (ray.origin - center_) * scale_ + kLift * ray.liftNormal;
  RTCRayHit query;
  query.ray.org_x = float(from.x), query.ray.org_y = float(from.y), query.ray.org_z = float(from.z);
  query.ray.dir_x = float(ray.direction.x), query.ray.dir_y = float(ray.direction.y),
  query.ray.dir_z = float(ray.direction.z);
  query.ray.tnear = 0.0f;
  query.ray.tfar = std::numeric_limits<float>::infinity();
  query.ray.time = 0.0f;
  query.ray.mask = ~0u;
  query.ray.id = 0;
  query.ray.flags = 0;
  query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  query.hit.primID = RTC_INVALID_GEOMETRY_ID;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcIntersect1(embree_->scene, &context, &query);
  if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;

  RayHit hit;
  hit.polygon = trianglePolygon_[query.hit.primID];
  // The float ray, as Embree traced it, in double from here on.
  const Vec3 origin(query.ray.org_x, query.ray.org_y, query.ray.org_z);
  const Vec3 direction(query.ray.dir_x, query.ray.dir_y, query.ray.dir_z);
  const double t = query.ray.tfar;
  hit.position = (origin + t * direction) / scale_ + center_;
  hit.distance = t / scale_;
  // The side from our own double normal, not Embree's Ng, whose sign follows its own winding
  // convention.
  hit.front = glm::dot(polygonNormals_[hit.polygon], ray.direction) < 0.0;
  return hit;
}

}  // namespace radview
