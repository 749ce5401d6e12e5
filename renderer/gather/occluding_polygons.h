#pragma once
// A few convex planar polygons that hide one another, seen from a point: the final gather's
// stand-in for the scene in its control variates (control_variates.h). Two questions, answered
// so that they agree exactly:
//  - which polygons a ray from x meets with none of the others in front (seenAlong, seenAt);
//  - the form factor from x to the part of each polygon that x sees (visibleFormFactors), in
//    closed form: the polygon, clipped to x's horizon, less the cone from x through every
//    polygon in front of it (clipping, as Weiler and Atherton's hidden-surface removal does in
//    the image plane), and Lambert's formula (trace/form_factor.h) over the pieces left.
// So a function that is constant on what x sees of each polygon integrates over the cosine-
// weighted hemisphere to the sum of those constants times those form factors.
//
// Two polygons that cross one another (or lie in one plane) do not hide each other: neither
// answer lets one hide the other, so the two still agree. Only polygons in front of x (facing
// it) hide or are seen.
#include "core/types.h"

#include <cstdint>
#include <vector>

namespace radview {

class OccludingPolygons {
 public:
  // At most kMaxPolygons convex polygons of at most kMaxCorners corners, each counter-clockwise
  // about the side it faces.
  static constexpr size_t kMaxPolygons = 64, kMaxCorners = 64;
  explicit OccludingPolygons(const std::vector<std::vector<Vec3>>& polygons);

  size_t size() const { return polygons_.size(); }
  // Bit i set: x is in front of polygon i (further than 1e-12 of its size from its plane).
  uint64_t facing(const Vec3& x) const;
  // What x, unit normal n, sees of each polygon of `facing` (facing(x)) above its horizon:
  // visit(i, piece) for convex pieces of polygon i, counter-clockwise about its normal, that
  // together are that part of it.
  template <typename Visit>
  void visibleParts(const Vec3& x, const Vec3& n, uint64_t facing, const Visit& visit) const {
    thread_local std::vector<std::vector<Vec3>> pieces, scratch;
    for (uint64_t m = facing; m != 0; m &= m - 1) {
      const size_t i = size_t(__builtin_ctzll(m));
      const size_t count = visiblePieces(i, x, n, facing, pieces, scratch);
      for (size_t k = 0; k < count; ++k) visit(i, pieces[k]);
    }
  }
  // Polygon i crossed at distance `t` along the ray (seenAlong's answer): the point met.
  Vec3 pointAlong(size_t i, const Vec3& x, const Vec3& direction) const {
    return x + crossing(polygons_[i], x, direction) * direction;
  }
  // The polygons of `facing` that the ray from x along the unit vector `direction` meets with
  // no polygon that can hide them nearer: usually the nearest one alone.
  uint64_t seenAlong(const Vec3& x, const Vec3& direction, uint64_t facing) const;
  // Whether polygon i (in `facing`) is seen along the ray from x to `target`, a point of it.
  bool seenAt(const Vec3& x, const Vec3& target, uint64_t facing, size_t i) const;

 private:
  struct Polygon {
    std::vector<Vec3> corners;
    std::vector<Vec3> edgeInwards;  // per edge corners[k] -> corners[k + 1]: in the plane, inwards
    Vec3 normal, centre;
    double size;  // bounding diagonal
    // The polygons that can hide this one: not crossing it, not coplanar, and with some of
    // this one behind their plane.
    uint64_t hiddenBy;
  };
  // visibleParts' pieces of polygon i: how many, in pieces[0 ..); `scratch` is storage.
  size_t visiblePieces(size_t i, const Vec3& x, const Vec3& n, uint64_t facing, std::vector<std::vector<Vec3>>& pieces,
                       std::vector<std::vector<Vec3>>& scratch) const;
  // Distance along the unit ray to polygon i's plane if the ray crosses the polygon, else -1.
  double crossing(const Polygon& p, const Vec3& x, const Vec3& direction) const;
  std::vector<Polygon> polygons_;
};

}  // namespace radview
