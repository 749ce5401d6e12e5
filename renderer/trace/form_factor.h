#pragma once
// Form factors between a differential receiver area and a polygon (C&W ch. 4).
#include "core/types.h"

#include <array>
#include <vector>

namespace radview {

// The exact form factor F from a differential area at x with unit normal n to a Lambertian
// planar polygon (vertices CCW about the side it emits from): the fraction of the energy
// leaving dA that arrives at the polygon, so that a polygon of exitance E gives dA the
// radiosity rho * E * F (no visibility: nothing occludes).
//
// Parts of the polygon below the receiver's horizon contribute nothing: they are clipped away
// first. The result is in [0, 1] and never NaN. A polygon seen from behind, edge-on (x on its
// plane, within 1e-12 of its size), entirely below the horizon, or degenerate gives 0. The
// edge-on 0 is also the limit from the front everywhere except on the closed polygon itself
// (a receiver touching the emitter), where F jumps. Preconditions (always checked): x, n and
// the vertices are finite and n has unit length.
double pointToPolygonFormFactor(const Vec3& x, const Vec3& n, const std::vector<Vec3>& polygon);

// Lambert's sum alone, for a polygon already clipped to x's horizon (every vertex v has
// dot(v - x, n) >= 0) and facing x (counter-clockwise about the side x is on): no clipping,
// no allocation. Not clamped.
double formFactorAboveHorizon(const Vec3& x, const Vec3& n, const Vec3* polygon, size_t count);

// The same form factor to a shooting patch (one or more non-overlapping polygons in one plane,
// facing one way), prepared once for the many receivers of a shot: what depends on the patch
// alone (normals, centroids, its outline) is computed here, not per receiver. Lambert's edge
// sum is additive over polygons, and the polygons' shared edges cancel (traversed both ways),
// so a receiver that sees the whole patch above its horizon sums over the outline only; one
// whose horizon cuts the patch sums pointToPolygonFormFactor over the polygons, which clips
// each. Same result and preconditions as summing pointToPolygonFormFactor, to rounding.
class PatchFormFactor {
 public:
  explicit PatchFormFactor(const std::vector<std::vector<Vec3>>& polygons);
  double from(const Vec3& x, const Vec3& n) const;

 private:
  std::vector<std::vector<Vec3>> polygons_;   // the non-degenerate ones
  std::vector<std::array<Vec3, 2>> outline_;  // directed edges not cancelled by their reverse
  Vec3 normal_{0.0}, pointOnPlane_{0.0};
  double size_ = 0.0;  // bounding diagonal
};

}  // namespace radview
