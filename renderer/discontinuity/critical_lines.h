#pragma once
// The critical-line test of discontinuity meshing (discontinuity_events.h) answered by rays
// through Embree against the scene's polygons.
#include "discontinuity/discontinuity_events.h"
#include "scene/scene.h"
#include "trace/ray_caster.h"

#include <vector>

namespace radview {

class CriticalLinesByRays : public CriticalLineTest {
 public:
  // Throws Error as RayCaster does.
  explicit CriticalLinesByRays(const Scene& scene);

  // Clear where neither part of the line, x to q and s to q, meets a surface. Each part stops
  // short of q, where the line grazes the occluder by construction, and a surface whose plane
  // holds the line (a face of the occluder beside the edge it grazes) does not block it.
  bool clear(const Vec3& x, const Vec3& xNormal, const Vec3& q, const Vec3& s, const Vec3& sNormal) const override;

  // Each ray's origin is lifted off its surface by RayCaster::kLift of the scene's size, which
  // moves where an edge starts to block it by about the lift over the tangent of the line's
  // angle with the receiver: four lifts cover lines 14 degrees off the receiver and steeper.
  double precision() const override { return 4.0 * RayCaster::kLift * diagonal_; }

 private:
  bool partClear(const Vec3& from, const Vec3& fromNormal, const Vec3& q) const;

  RayCaster caster_;
  std::vector<Vec3> normals_;  // unit, per scene polygon
  double diagonal_ = 0.0;
};

}  // namespace radview
