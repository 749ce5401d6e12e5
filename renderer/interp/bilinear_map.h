#pragma once
// The bilinear map of a planar quad from its parameter square [0,1]^2:
//   x(s, t) = (1-s)(1-t) p0 + s(1-t) p1 + s t p2 + (1-s) t p3,
// and its inverse. Interpolating in (s, t) is what makes bilinear elements orientation
// invariant (C&W §9.2: the cure for fig. 9.7-9.8).
#include "core/types.h"

#include <array>

namespace radview {

class BilinearMap {
 public:
  explicit BilinearMap(const std::array<Vec3, 4>& corners);
  Vec3 operator()(const Vec2& st) const;
  // (s, t) of x projected onto the quad's plane, by Newton's method from the centre; exact
  // to round-off for convex quads, extrapolating outside. Never NaN for finite input.
  Vec2 inverse(const Vec3& x) const;
  // World-space gradient of a function of (s, t), given its partial derivatives there.
  Vec3 gradient(const Vec2& st, double dfds, double dfdt) const;

 private:
  std::array<Vec3, 4> p_;
  Vec3 dxds(const Vec2& st) const;
  Vec3 dxdt(const Vec2& st) const;
};

}  // namespace radview
