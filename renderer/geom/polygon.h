#pragma once
// Geometry of planar polygons in 3D: normal, area, planarity, convexity, triangulation.
#include "core/types.h"

#include <array>
#include <vector>

namespace radview {

// Newell's method: robust for concave and slightly non-planar polygons. Length = 2 * area.
Vec3 newellNormal(const std::vector<Vec3>& vertices);
// Unit normal, or zero for a degenerate (zero-area) polygon.
Vec3 unitNormal(const std::vector<Vec3>& vertices);
double area(const std::vector<Vec3>& vertices);
Vec3 centroid(const std::vector<Vec3>& vertices);  // area centroid (vertex mean if degenerate)
// Largest distance of a vertex from the polygon's mean plane.
double planarityError(const std::vector<Vec3>& vertices);
// True if every corner turns the same way as the polygon's normal (collinear corners allowed)
// and the boundary winds once. False for a degenerate polygon.
bool isConvex(const std::vector<Vec3>& vertices);
// Convex with every corner a real corner: the sine of each turn, relative to the normal, is
// above minSine. A fan of such a polygon has no zero-area triangle.
bool isStrictlyConvex(const std::vector<Vec3>& vertices, double minSine = 1e-6);

// Triangulates a simple planar polygon (convex or concave) without adding vertices; the
// triangles index `vertices` and keep its orientation. Strictly convex polygons get a fan
// from vertex 0; any other (concave, or with collinear corners, where a fan would have
// zero-area triangles) a constrained Delaunay triangulation (CGAL). Throws Error for fewer
// than 3 vertices, a non-finite vertex, a zero-area or a self-intersecting polygon.
std::vector<std::array<int, 3>> triangulatePolygon(const std::vector<Vec3>& vertices);

// An orthonormal frame (u, v, n) of the polygon's plane, for 2D work in it: n is the unit
// normal, u runs along the longest edge, and polygons CCW about n project CCW. Throws Error
// for a degenerate (zero-area) polygon, which has no plane.
struct PlaneFrame {
  Vec3 origin, u, v, n;
  Vec2 project(const Vec3& p) const { return {glm::dot(p - origin, u), glm::dot(p - origin, v)}; }
};
PlaneFrame planeFrame(const std::vector<Vec3>& vertices);

// Sutherland-Hodgman: the part of a convex polygon where dot(m, p - point) >= 0, written to
// `kept` (cleared first, its storage reused; not `polygon` itself). Fewer than 3 vertices when
// nothing of it is there.
void clipToHalfSpace(const std::vector<Vec3>& polygon, const Vec3& point, const Vec3& m, std::vector<Vec3>& kept);

}  // namespace radview
