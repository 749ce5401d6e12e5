#pragma once
// Visibility V(x, y) between two surface points (C&W eq. 4.3's V_ij), and the surface a ray
// sees first (the final gather, C&W §9.3.1), by rays cast through Embree 3 against the scene's
// polygons.
#include "core/types.h"
#include "scene/scene.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

namespace radview {

// A segment between two surface points, each with the unit normal of the side it faces: the
// ray leaves `from` and ends at `to`, both lifted off their surfaces (see RayCaster).
struct Segment {
  Vec3 from, fromNormal;
  Vec3 to, toNormal;
};

// A ray leaving `origin` along the unit vector `direction`. A surface point's ray names the
// unit normal of the side it leaves from as `liftNormal`, and is lifted off it as a Segment's
// ends are; a ray from the eye has none (zero).
struct Ray {
  Vec3 origin;
  Vec3 direction;
  Vec3 liftNormal{0.0};
};

// The first surface a ray meets.
struct RayHit {
  size_t polygon = 0;     // index into the scene's polygons
  Vec3 position{0.0};     // world space, on the polygon up to Embree's float rounding
  double distance = 0.0;  // world space, from the (lifted) origin
  bool front = false;     // the ray arrived on the side the polygon faces (its normal's side)
};

class RayCaster {
 public:
  // Builds Embree's BVH over the scene's polygons, triangulated (zero-area polygons are left
  // out and counted). Geometry goes to Embree in a frame centred on the scene and scaled by its
  // bounding diagonal, so huge or tiny coordinates keep float precision and the self-
  // intersection offset means the same everywhere. Throws Error for a vertex or a scene size
  // that is not a finite number, and for any error Embree reports (its message included).
  explicit RayCaster(const Scene& scene);
  ~RayCaster();
  RayCaster(const RayCaster&) = delete;
  RayCaster& operator=(const RayCaster&) = delete;

  // True if any polygon blocks the segment. Both ends are lifted by kLift (of the scene's
  // diagonal) along their normals, so that neither end's own surface, nor a surface it
  // touches at a corner, counts as a blocker. Thread-safe: any number of threads may query.
  bool occluded(const Segment& segment) const;
  // The same for `count` segments at once, blocked[i] (1 or 0) for segments[i]: one call into
  // Embree for all of them, traced as a coherent stream (the rays from one point to one patch
  // are nearly parallel, so they share most of their traversal). Thread-safe.
  void occluded(const Segment* segments, size_t count, uint8_t* blocked) const;
  // The same for the segments from one point to each of `to[0 .. count)`, all ends facing
  // `toNormal` (a receiving node to the samples of a planar patch): the rays and the answers
  // are those of the Segment stream, without a Segment per ray.
  void occludedFrom(const Vec3& from, const Vec3& fromNormal, const Vec3* to, size_t count, const Vec3& toNormal,
                    uint8_t* blocked) const;

  // The nearest polygon along the ray, if any. Thread-safe.
  std::optional<RayHit> closestHit(const Ray& ray) const;

  // The self-intersection offset, a fraction of the scene's bounding diagonal: above float's
  // rounding of the normalised coordinates (~6e-8), far below any element size.
  static constexpr double kLift = 1e-5;

  // The unit normal of a polygon, the side it faces (zero for a zero-area polygon).
  const Vec3& normal(size_t polygon) const { return polygonNormals_[polygon]; }

  size_t triangleCount() const { return triangleCount_; }
  size_t skippedPolygons() const { return skippedPolygons_; }  // zero-area polygons left out

  // Embree's scene handle (RTCScene), for measuring Embree alone on the same rays.
  void* embreeScene() const;
  // A segment in Embree's frame: ray origin, direction (its length the segment's) and tfar,
  // exactly as occluded() casts it.
  void embreeRay(const Segment& segment, float origin[3], float direction[3], float& tfar) const;

 private:
  struct Embree;
  // A point in Embree's frame, lifted by kLift along `liftNormal`.
  Vec3 toEmbree(const Vec3& point, const Vec3& liftNormal) const;

  std::unique_ptr<Embree> embree_;
  Vec3 center_{0.0};
  double scale_ = 1.0;                     // world -> Embree: (p - center_) * scale_
  std::vector<uint32_t> trianglePolygon_;  // Embree's primitive ID -> scene polygon
  std::vector<Vec3> polygonNormals_;       // unit, by scene polygon (zero for skipped ones)
  size_t triangleCount_ = 0;
  size_t skippedPolygons_ = 0;
};

}  // namespace radview
