#pragma once
// Where points are on a mesh of any size: nearestSurfacePoint's answer from a bounding volume
// hierarchy over the elements' triangles (Embree's point queries), so that a point is tested
// against the few triangles near it, not against every element.
#include "interp/surface_point.h"
#include "mesh/radiosity_mesh.h"

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

struct RTCPointQueryFunctionArguments;  // Embree's

namespace radview {

class SurfaceLocator {
 public:
  // Builds the hierarchy over elementTriangles of every element. The mesh must outlive the
  // locator. Throws Error for a mesh without elements, or one Embree cannot build.
  explicit SurfaceLocator(const RadiosityMesh& mesh);
  ~SurfaceLocator();
  SurfaceLocator(const SurfaceLocator&) = delete;
  SurfaceLocator& operator=(const SurfaceLocator&) = delete;

  // Exactly nearestSurfacePoint(mesh, p): the same element (lowest index among equally near
  // ones), point and distance. `expectedWithin`, where the caller knows how near the answer
  // should be, bounds a first search (the hierarchy then culls all but the triangles that near:
  // a million points on a plane are placed three times as fast); past it, the whole mesh is
  // searched, so the answer is the same. Thread-safe.
  SurfacePoint nearest(const Vec3& p, double expectedWithin = std::numeric_limits<double>::infinity()) const;

 private:
  struct Embree;
  struct Query;
  static bool visit(RTCPointQueryFunctionArguments* args);
  // Embree's query radius for a distance found (world units): in its frame, rounded up, and
  // widened by the float rounding of the query point and of the boxes, so that no triangle
  // as near as the best one is ever culled.
  float queryRadius(double distance) const;

  const RadiosityMesh& mesh_;
  std::vector<std::array<uint32_t, 3>> triangles_;  // node indices, in nearestSurfacePoint's order
  std::vector<uint32_t> triangleElement_;
  Vec3 center_{0.0};
  double scale_ = 1.0;  // world -> Embree: (p - center_) * scale_, coordinates within +-1
  std::unique_ptr<Embree> embree_;
};

}  // namespace radview
